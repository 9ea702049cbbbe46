#include "snapshot/merge.hpp"

#include "snapshot/report.hpp"
#include "snapshot/results_file.hpp"

#include <algorithm>
#include <cstdio>
#include <set>
#include <stdexcept>
#include <string>

namespace sweep::snapshot {
namespace {

namespace fs = std::filesystem;

struct Shard {
  fs::path folder;
  RunResults results;
};

Shard read_shard(const fs::path& path) {
  std::error_code ec;
  const bool folder = fs::is_directory(path, ec);
  const fs::path file = folder ? path / "results.json" : path;
  return {folder ? path : path.parent_path(), read_results_file(file)};
}

/// Throws std::runtime_error when the shards are not the parts of one run.
void check_parts(const std::vector<Shard>& shards) {
  const RunSummary& first = shards.front().results.summary;
  std::set<int> present;
  std::set<std::string> names;
  std::size_t cases = 0;
  for (const Shard& s : shards) {
    const RunSummary& summary = s.results.summary;
    if (summary.shard_n != first.shard_n || summary.suite_cases != first.suite_cases) {
      throw std::runtime_error(
          s.folder.string() + " is shard " + std::to_string(summary.shard_k) + "/" + std::to_string(summary.shard_n) +
          " of a suite of " + std::to_string(summary.suite_cases) + " cases, " + shards.front().folder.string() +
          " of one of " + std::to_string(first.suite_cases) + " in " + std::to_string(first.shard_n) + " shards");
    }
    if (!present.insert(summary.shard_k).second) {
      throw std::runtime_error("shard " + std::to_string(summary.shard_k) + "/" + std::to_string(summary.shard_n) +
                               " is given twice (" + s.folder.string() + ")");
    }
    for (const CaseResult& r : s.results.cases) {
      if (!names.insert(r.spec.name).second) {
        throw std::runtime_error("case " + r.spec.name + " is in two shards (again in " + s.folder.string() + ")");
      }
    }
    cases += s.results.cases.size();
  }
  std::string missing;
  for (int k = 1; k <= first.shard_n; ++k) {
    if (!present.count(k))
      missing += (missing.empty() ? "" : ", ") + std::to_string(k) + "/" + std::to_string(first.shard_n);
  }
  if (!missing.empty() || cases != first.suite_cases) {
    throw std::runtime_error("the reports hold " + std::to_string(cases) + " of the suite's " +
                             std::to_string(first.suite_cases) + " cases" +
                             (missing.empty() ? std::string() : "; missing shard " + missing));
  }
}

/// The images a case names, copied from its shard's report into `report`.
void carry_images(const CaseResult& r, const fs::path& from, const fs::path& report) {
  for (const std::string* image : {&r.reference_image, &r.actual_image, &r.diff_image}) {
    if (image->empty()) continue;
    const fs::path source = from / *image;
    const fs::path target = report / *image;
    std::error_code ec;
    if (fs::exists(target, ec) && fs::equivalent(source, target, ec)) continue;
    fs::create_directories(target.parent_path(), ec);
    if (!fs::copy_file(source, target, fs::copy_options::overwrite_existing, ec)) {
      throw std::runtime_error("cannot copy " + source.string() + " to " + target.string() + ": " + ec.message());
    }
  }
}

RunSummary merged_summary(const std::vector<Shard>& shards) {
  RunSummary out = shards.front().results.summary;
  out.shard_k = out.shard_n = 1;
  out.workers = 0;
  out.seconds = 0.0;
  std::vector<std::string> renderers;
  for (const Shard& s : shards) {
    const RunSummary& summary = s.results.summary;
    out.workers += summary.workers;
    out.seconds = std::max(out.seconds, summary.seconds);  // the shards ran side by side
    out.new_fails = out.new_fails || summary.new_fails;
    if (std::find(renderers.begin(), renderers.end(), summary.renderer) == renderers.end()) {
      renderers.push_back(summary.renderer);
    }
  }
  out.renderer.clear();
  for (const std::string& r : renderers) out.renderer += (out.renderer.empty() ? "" : " | ") + r;
  return out;
}

}  // namespace

int merge_reports(const MergeOptions& options) {
  try {
    std::vector<Shard> shards;
    for (const fs::path& path : options.shards) shards.push_back(read_shard(path));
    if (shards.empty()) throw std::runtime_error("no shard reports to merge");
    check_parts(shards);
    std::vector<CaseResult> cases;
    for (const Shard& s : shards) {
      for (const CaseResult& r : s.results.cases) {
        carry_images(r, s.folder, options.report);
        cases.push_back(r);
      }
    }
    std::sort(cases.begin(), cases.end(),
              [](const CaseResult& a, const CaseResult& b) { return a.spec.order < b.spec.order; });
    const RunSummary summary = merged_summary(shards);
    write_html_report(options.report, cases, summary);
    write_results_file(options.report, cases, summary);
    if (!options.junit.empty()) write_junit(options.junit, cases, summary);
    const Totals totals = count_results(cases, summary);
    std::printf("merged %zu shards: %s\nreport: %s\n", shards.size(), totals_line(totals).c_str(),
                (options.report / "index.html").c_str());
    return exit_status(totals);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 2;
  }
}

}  // namespace sweep::snapshot
