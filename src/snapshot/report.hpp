#pragma once
// The run's reports: the HTML page (failures first, each with reference, actual, diff heat map,
// a slider and a flicker toggle between reference and actual, the attribution and the numbers)
// and JUnit XML for CI systems. The runner writes the images into the report folder first and
// names them in each CaseResult.
#include "snapshot/snapshot_case.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sweep::snapshot {

struct RunSummary {
  std::string title;     // "sweep snapshot models/"
  std::string renderer;  // the GL renderer string
  double seconds = 0.0;  // the whole run
  int workers = 1;
};

/// Writes REPORT/index.html: self-contained (inline CSS and script, no network), the images
/// beside it as the results name them. Throws std::runtime_error when it cannot be written.
void write_html_report(const std::filesystem::path& report_dir, const std::vector<CaseResult>& results,
                       const RunSummary& summary);

/// Writes FILE as JUnit XML: one <testsuite name="sweep snapshot"> with a <testcase> per case
/// (classname the SWP file, name the case), <failure> for FAIL, <error> for error, <skipped> for
/// none; new and updated cases pass with a <system-out> line. Throws std::runtime_error.
void write_junit(const std::filesystem::path& file, const std::vector<CaseResult>& results, const RunSummary& summary);

}  // namespace sweep::snapshot
