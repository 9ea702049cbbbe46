#include "snapshot/run_snapshots.hpp"

#include "snapshot/references.hpp"
#include "snapshot/report.hpp"
#include "snapshot/run_case.hpp"

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

/// The cases of the run, before sharding; throws SuiteError.
std::vector<CaseSpec> all_cases(const RunOptions& options) {
  fs::path suite = options.suite;
  std::error_code ec;
  if (suite.empty() && fs::is_regular_file(options.dir / "snapshots.txt", ec)) suite = options.dir / "snapshots.txt";
  return suite.empty() ? cases_in_folder(options.dir, options.defaults)
                       : read_suite(suite, options.dir, options.defaults);
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
  if (r.status != Status::Pass || r.references > 1 || r.other_renderer) line += ": " + r.message;
  std::printf("%s\n", line.c_str());
  if (r.status == Status::Fail || r.status == Status::Warning) {
    for (const ObjectChange& change : r.changes) std::printf("           %s\n", change.text.c_str());
  }
  std::fflush(stdout);
}

struct Totals {
  int passed = 0, failed = 0, added = 0, updated = 0, warnings = 0, errors = 0;
};

Totals count(const std::vector<CaseResult>& results, UpdateMode update) {
  Totals t;
  for (const CaseResult& r : results) {
    switch (r.status) {
      case Status::Pass:
        ++t.passed;
        break;
      case Status::Warning:
        ++t.warnings;
        ++t.passed;
        break;
      case Status::Fail:
        ++t.failed;
        break;
      case Status::New:
        ++t.added;
        if (update == UpdateMode::None) ++t.failed;
        break;
      case Status::Updated:
        ++t.updated;
        break;
      case Status::Error:
        ++t.errors;
        ++t.failed;
        break;
    }
  }
  return t;
}

/// Runs the cases on `jobs` workers, each with its own OSMesa context; results in case order.
std::vector<CaseResult> run_all(const std::vector<CaseSpec>& cases, const CaseContext& context, int jobs, bool quiet,
                                std::string& renderer) {
  std::vector<CaseResult> results(cases.size());
  const std::vector<std::vector<std::size_t>> groups = scene_groups(cases);
  std::atomic<std::size_t> next{0};
  std::mutex print_lock;
  std::size_t done = 0;
  std::string failure;  // why a worker has no context
  std::atomic<int> working{0};
  const auto work = [&] {
    std::unique_ptr<Worker> worker;
    try {
      worker = std::make_unique<Worker>();
    } catch (const std::exception& e) {
      const std::lock_guard<std::mutex> hold(print_lock);
      failure = e.what();
      return;
    }
    ++working;
    {
      const std::lock_guard<std::mutex> hold(print_lock);
      renderer = worker->renderer_name();
    }
    for (std::size_t g = next++; g < groups.size(); g = next++) {
      const LoadedScene loaded = load_scene(cases[groups[g].front()]);
      for (const std::size_t i : groups[g]) {
        results[i] = run_case(*worker, loaded, cases[i], context);
        const std::lock_guard<std::mutex> hold(print_lock);
        print_result(results[i], ++done, cases.size(), quiet);
      }
    }
  };
  const int count = std::max(1, std::min<int>(jobs, int(groups.size())));
  std::vector<std::thread> threads;
  for (int j = 1; j < count; ++j) threads.emplace_back(work);
  work();
  for (std::thread& t : threads) t.join();
  if (working == 0) throw std::runtime_error(failure);
  return results;
}

/// Reports references that belong to no case; deletes them with --prune.
void handle_orphans(const RunOptions& options, const fs::path& references, const std::vector<CaseSpec>& every_case) {
  std::set<std::string> names;
  for (const CaseSpec& c : every_case) names.insert(c.name);
  const std::vector<fs::path> orphans = orphan_references(references, names);
  if (orphans.empty()) return;
  if (!options.prune) {
    std::printf("%zu reference file%s belong to no case (kept; --prune deletes them)\n", orphans.size(),
                orphans.size() == 1 ? "" : "s");
    return;
  }
  for (const fs::path& file : orphans) {
    std::error_code ec;
    fs::remove(file, ec);
    std::printf("pruned %s%s\n", file.c_str(), ec ? (": " + ec.message()).c_str() : "");
  }
}

void write_reports(const RunOptions& options, const std::vector<CaseResult>& results, const RunSummary& summary) {
  if (!options.report.empty()) {
    write_html_report(options.report, results, summary);
    std::printf("report: %s\n", (options.report / "index.html").c_str());
  }
  if (!options.junit.empty()) write_junit(options.junit, results, summary);
}

}  // namespace

int run_snapshots(const RunOptions& options) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<CaseSpec> every_case;
  try {
    every_case = all_cases(options);
  } catch (const SuiteError& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 2;
  }
  const std::vector<CaseSpec> cases = shard(every_case, options.shard_k, options.shard_n);
  CaseContext context;
  context.references = options.references.empty() ? options.dir / "__snapshots__" : options.references;
  context.report = options.report;
  context.update = options.update;
  context.strict_geometry = options.strict_geometry;
  const int jobs = options.jobs > 0 ? options.jobs : int(std::max(1u, std::thread::hardware_concurrency()));
  RunSummary summary;
  summary.title = "sweep snapshot " + options.dir.string();
  summary.workers = jobs;
  std::vector<CaseResult> results;
  try {
    results = run_all(cases, context, jobs, options.quiet, summary.renderer);
  } catch (const std::exception& e) {  // no OSMesa context
    std::fprintf(stderr, "sweep: cannot render headless: %s\n", e.what());
    return 2;
  }
  handle_orphans(options, context.references, every_case);
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  try {
    write_reports(options, results, summary);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 2;
  }
  const Totals t = count(results, options.update);
  double renders = 0.0;
  for (const CaseResult& r : results) renders += r.render_seconds;
  std::printf(
      "%d passed, %d failed (%d new, %d updated, %d warnings, %d errors) in %.2f s (renders %.2f s on %d "
      "workers)\n",
      t.passed, t.failed, t.added, t.updated, t.warnings, t.errors, summary.seconds, renders, summary.workers);
  if (t.errors > 0) return 2;
  return t.failed > 0 ? 1 : 0;
}

}  // namespace sweep::snapshot
