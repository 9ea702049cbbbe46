#pragma once
// The run's reports: the HTML page (failures first, each with reference, actual, diff heat map,
// a slider and a flicker toggle between reference and actual, the attribution and the numbers)
// and JUnit XML for CI systems. The runner writes the images into the report folder first and
// names them in each CaseResult.
#include "snapshot/snapshot_case.hpp"

#include <array>
#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace sweep::snapshot {

struct RunSummary {
  std::string title;     // "sweep snapshot models/"
  std::string renderer;  // the GL renderer string (merged shards: each different one, " | " between)
  double seconds = 0.0;  // the whole run
  int workers = 1;
  /// A new reference fails the run (no --update or --update=missing was given).
  bool new_fails = true;
  int shard_k = 1;  // which shard of how many ran (a merge: 1/1)
  int shard_n = 1;
  std::size_t suite_cases = 0;  // cases of the whole suite, every shard's together
};

/// Whether `result` makes the run exit non-zero: a failure, an error, or a new reference that
/// was not accepted. The terminal, the HTML report, the JUnit XML and the exit status all ask this.
bool fails_run(const CaseResult& result, const RunSummary& summary);

/// The one count of a run's cases: how many have each status, and how many pass and fail the
/// run by fails_run's rule (a new reference fails it unless accepted). The closing line, the
/// report's filters and the exit status all read it.
struct Totals {
  std::array<int, kStatusCount> by_status{};  // indexed by Status
  int passed = 0, failed = 0;
  int of(Status status) const { return by_status[static_cast<std::size_t>(status)]; }
};
Totals count_results(const std::vector<CaseResult>& results, const RunSummary& summary);
/// 2 when any case is an error, else 1 when any fails the run, else 0.
int exit_status(const Totals& totals);
/// "6 passed, 3 failed (0 new, 0 updated, 0 warnings, 0 errors)".
std::string totals_line(const Totals& totals);

/// Writes REPORT/index.html: self-contained (inline CSS and script, no network), the images
/// beside it as the results name them. Throws std::runtime_error when it cannot be written.
void write_html_report(const std::filesystem::path& report_dir, const std::vector<CaseResult>& results,
                       const RunSummary& summary);

/// Writes FILE as JUnit XML: one <testsuite name="sweep snapshot"> with a <testcase> per case
/// (classname the SWP file, name the case): <failure> for FAIL and for a new reference that fails
/// the run (fails_run), <error> for error; warnings, renderer differences, accepted new and
/// updated cases pass with their text in <system-out>. Throws std::runtime_error.
void write_junit(const std::filesystem::path& file, const std::vector<CaseResult>& results, const RunSummary& summary);

}  // namespace sweep::snapshot
