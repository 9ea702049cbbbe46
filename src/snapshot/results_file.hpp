#pragma once
// REPORT/results.json: every case of a run as data (its options, status, message, the
// comparison's figures, the attribution, the accepted references and their renderers, the
// report's image paths) and the run's summary. Written beside index.html by every run with
// --report; `sweep snapshot merge` reads the shards' files back and writes the report one
// unsharded run would have written. The format is versioned ("format": 1).
#include "snapshot/report.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace sweep::snapshot {

inline constexpr int kResultsFormat = 1;

class ResultsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;  // what(): "shard1/results.json: expected cases[3].status ..."
};

struct RunResults {
  RunSummary summary;
  std::vector<CaseResult> cases;
};

/// The JSON text of a run (numbers written so they read back exactly).
std::string results_json(const std::vector<CaseResult>& results, const RunSummary& summary);
/// Writes REPORT/results.json atomically. Throws std::runtime_error naming the file.
void write_results_file(const std::filesystem::path& report_dir, const std::vector<CaseResult>& results,
                        const RunSummary& summary);
/// Reads a results file; throws ResultsError naming the file and what is wrong.
RunResults read_results_file(const std::filesystem::path& file);
/// The same from text (`name` names it in messages).
RunResults parse_results(const std::string& text, const std::string& name);

}  // namespace sweep::snapshot
