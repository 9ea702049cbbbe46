#include "snapshot/run_snapshots.hpp"

#include "snapshot/references.hpp"
#include "snapshot/report.hpp"
#include "snapshot/results_file.hpp"
#include "snapshot/run_case.hpp"
#include "snapshot/stale_references.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <memory>
#include <mutex>
#include <set>
#include <stdexcept>
#include <thread>

namespace sweep::snapshot {
namespace {

namespace fs = std::filesystem;

/// Cases that share one evaluation, by index into the run's cases.
std::vector<std::vector<std::size_t>> scene_groups(const std::vector<CaseSpec>& cases) {
  std::vector<std::vector<std::size_t>> groups;
  for (std::size_t i = 0; i < cases.size(); ++i) {
    auto same = std::find_if(groups.begin(), groups.end(),
                             [&](const std::vector<std::size_t>& g) { return same_scene(cases[g.front()], cases[i]); });
    if (same == groups.end()) {
      groups.push_back({i});
    } else {
      same->push_back(i);
    }
  }
  return groups;
}

/// The cases of the run, before sharding, each knowing its place; throws SuiteError.
std::vector<CaseSpec> all_cases(const RunOptions& options) {
  fs::path suite = options.suite;
  std::error_code ec;
  if (suite.empty() && fs::is_regular_file(options.dir / "snapshots.txt", ec)) suite = options.dir / "snapshots.txt";
  std::vector<CaseSpec> cases =
      suite.empty() ? cases_in_folder(options.dir, options.defaults) : read_suite(suite, options.dir, options.defaults);
  for (std::size_t i = 0; i < cases.size(); ++i) cases[i].order = i;
  return cases;
}

/// "sweep snapshot models [--suite S] [--references R]": what the messages' commands start with.
std::string command_of(const RunOptions& options) {
  std::string command = "sweep snapshot " + options.dir.string();
  if (!options.suite.empty()) command += " --suite " + options.suite.string();
  if (!options.references.empty()) command += " --references " + options.references.string();
  return command;
}

/// "[ 3/66] FAIL     wineglass-smooth: ..." and the attribution lines under it.
void print_result(const CaseResult& r, std::size_t done, std::size_t total, bool quiet) {
  const int width = int(std::to_string(total).size());
  std::string line;
  if (!quiet) {
    char count[48];
    std::snprintf(count, sizeof count, "[%*zu/%zu] ", width, done, total);
    line = count;
  }
  char status[16];
  std::snprintf(status, sizeof status, "%-8s ", name_of(r.status));
  line += status + r.spec.name;
  // A pass says only what a reviewer may want to know: which of several references, whose renderer.
  if (r.status != Status::Pass || r.accepted.size() > 1 || r.other_renderer) line += ": " + r.message;
  std::printf("%s\n", line.c_str());
  if (r.status == Status::Fail || r.status == Status::Warning) {
    for (const ObjectChange& change : r.changes) std::printf("           %s\n", change.text.c_str());
  }
  std::fflush(stdout);
}

/// Prints results in case order as they finish (two logs of one run are the same at any -j).
class OrderedPrinter {
 public:
  OrderedPrinter(const std::vector<CaseResult>& results, bool quiet)
      : results_(results), done_(results.size(), false), quiet_(quiet) {}
  void finished(std::size_t i) {
    const std::lock_guard<std::mutex> hold(lock_);
    done_[i] = true;
    for (; next_ < done_.size() && done_[next_]; ++next_)
      print_result(results_[next_], next_ + 1, done_.size(), quiet_);
  }

 private:
  const std::vector<CaseResult>& results_;
  std::vector<bool> done_;
  std::size_t next_ = 0;
  bool quiet_;
  std::mutex lock_;
};

/// The cases' size against what the renderer can allocate: "" or why not, before any render.
std::string size_problem(const std::vector<CaseSpec>& cases, const Worker& worker) {
  const int largest = worker.max_picture_side();
  for (const CaseSpec& c : cases) {
    if (c.size.x > largest || c.size.y > largest) {
      return "case " + c.name + " is " + std::to_string(c.size.x) + "x" + std::to_string(c.size.y) + ", larger than " +
             worker.renderer_name() + " renders (sides up to " + std::to_string(largest) + ")";
    }
  }
  return "";
}

/// Runs the cases on `jobs` workers, each with its own OSMesa context; results in case order.
/// Throws std::runtime_error when no context can be made or a case is larger than it renders.
std::vector<CaseResult> run_all(const std::vector<CaseSpec>& cases, const CaseContext& context, int jobs, bool quiet,
                                std::string& renderer) {
  std::vector<CaseResult> results(cases.size());
  const std::vector<std::vector<std::size_t>> groups = scene_groups(cases);
  std::atomic<std::size_t> next{0};
  OrderedPrinter printer(results, quiet);
  std::mutex lock;
  std::string failure;  // why a worker has no context
  const auto work = [&](std::unique_ptr<Worker> worker) {
    if (worker == nullptr) return;
    for (std::size_t g = next++; g < groups.size(); g = next++) {
      const LoadedScene loaded = load_scene(cases[groups[g].front()]);
      for (const std::size_t i : groups[g]) {
        results[i] = run_case(*worker, loaded, cases[i], context);
        printer.finished(i);
      }
    }
  };
  const auto make_worker = [&]() -> std::unique_ptr<Worker> {
    try {
      return std::make_unique<Worker>();
    } catch (const std::exception& e) {
      const std::lock_guard<std::mutex> hold(lock);
      failure = e.what();
      return nullptr;
    }
  };
  std::unique_ptr<Worker> first = make_worker();
  if (first == nullptr) throw std::runtime_error("cannot render headless: " + failure);
  renderer = first->renderer_name();
  if (const std::string problem = size_problem(cases, *first); !problem.empty()) throw std::runtime_error(problem);
  const int count = std::max(1, std::min<int>(jobs, int(groups.size())));
  std::vector<std::thread> threads;
  for (int j = 1; j < count; ++j) threads.emplace_back([&] { work(make_worker()); });
  work(std::move(first));
  for (std::thread& t : threads) t.join();
  return results;
}

void write_reports(const RunOptions& options, const std::vector<CaseResult>& results, const RunSummary& summary) {
  if (!options.report.empty()) {
    write_html_report(options.report, results, summary);
    write_results_file(options.report, results, summary);
    std::printf("report: %s\n", (options.report / "index.html").c_str());
  }
  if (!options.junit.empty()) write_junit(options.junit, results, summary);
}

/// `--rename OLD NEW`: moves the references and renders nothing.
int rename_case(const RunOptions& options, const fs::path& references) {
  try {
    for (const fs::path& file : rename_references(references, options.rename_from, options.rename_to)) {
      std::printf("moved to %s\n", file.c_str());
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 2;
  }
  return 0;
}

CaseContext context_of(const RunOptions& options, const StaleReferences& stale) {
  CaseContext context;
  context.references = options.references.empty() ? options.dir / "__snapshots__" : options.references;
  context.report = options.report;
  context.update = options.update;
  context.strict_geometry = options.strict_geometry;
  context.strict_renderer = options.strict_renderer;
  context.accept_renderer_command = command_of(options) + " --update=renderer";
  context.stale = &stale;
  return context;
}

}  // namespace

int run_snapshots(const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  const fs::path references = options.references.empty() ? options.dir / "__snapshots__" : options.references;
  if (!options.rename_from.empty()) return rename_case(options, references);
  std::vector<CaseSpec> every_case;
  try {
    every_case = all_cases(options);
  } catch (const SuiteError& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 2;
  }
  std::set<std::string> names;
  for (const CaseSpec& c : every_case) names.insert(c.name);
  const StaleReferences stale(references, names, command_of(options));
  if (options.prune && options.dry_run) {
    prune(stale.files(), true);
    return 0;
  }
  const std::vector<CaseSpec> cases = shard(every_case, options.shard_k, options.shard_n);
  const CaseContext context = context_of(options, stale);
  const int jobs = options.jobs > 0 ? options.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
  RunSummary summary;
  summary.title = "sweep snapshot " + options.dir.string();
  summary.workers = jobs;
  summary.new_fails = options.update != UpdateMode::All && options.update != UpdateMode::Missing;
  summary.shard_k = options.shard_k;
  summary.shard_n = options.shard_n;
  summary.suite_cases = every_case.size();
  std::vector<CaseResult> results;
  try {
    results = run_all(cases, context, jobs, options.quiet, summary.renderer);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 2;
  }
  if (options.prune) {
    prune(stale.files(), false);
  } else if (!stale.summary().empty()) {
    std::printf("%s\n", stale.summary().c_str());
  }
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  try {
    write_reports(options, results, summary);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 2;
  }
  const Totals t = count_results(results, summary);
  double renders = 0.0;
  for (const CaseResult& r : results) renders += r.render_seconds;
  std::printf("%s in %.2f s (renders %.2f s on %d workers)\n", totals_line(t).c_str(), summary.seconds, renders,
              summary.workers);
  return exit_status(t);
}

}  // namespace sweep::snapshot
