#include "snapshot/report.hpp"

// The one rule of what fails a run, and the counts of its closing line: the terminal, both
// reports, merged shards and the exit status agree because they all count here.

namespace sweep::snapshot {

bool fails_run(const CaseResult& result, const RunSummary& summary) {
  return result.status == Status::Fail || result.status == Status::Error ||
         (result.status == Status::New && summary.new_fails);
}

Totals count_results(const std::vector<CaseResult>& results, const RunSummary& summary) {
  Totals t;
  for (const CaseResult& r : results) {
    ++t.by_status[static_cast<std::size_t>(r.status)];
    if (fails_run(r, summary)) {
      ++t.failed;
    } else if (r.status == Status::Pass || r.status == Status::Warning) {
      ++t.passed;
    }
  }
  return t;
}

int exit_status(const Totals& totals) {
  if (totals.of(Status::Error) > 0) return 2;
  return totals.failed > 0 ? 1 : 0;
}

std::string totals_line(const Totals& t) {
  return std::to_string(t.passed) + " passed, " + std::to_string(t.failed) + " failed (" +
         std::to_string(t.of(Status::New)) + " new, " + std::to_string(t.of(Status::Updated)) + " updated, " +
         std::to_string(t.of(Status::Warning)) + " warnings, " + std::to_string(t.of(Status::Error)) + " errors)";
}

}  // namespace sweep::snapshot
