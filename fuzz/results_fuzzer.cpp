// libFuzzer entry point: every input is a snapshot results file (REPORT/results.json, what
// `sweep snapshot merge` reads). Bad input is one ResultsError; what parses writes back to text
// that parses to the same text again (a violated property aborts, so libFuzzer keeps the input).
#include "snapshot/results_file.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  sweep::snapshot::RunResults results;
  try {
    results = sweep::snapshot::parse_results(text, "results.json");
  } catch (const sweep::snapshot::ResultsError&) {
    return 0;
  }
  const std::string once = sweep::snapshot::results_json(results.cases, results.summary);
  const sweep::snapshot::RunResults again = sweep::snapshot::parse_results(once, "written");
  if (sweep::snapshot::results_json(again.cases, again.summary) != once) {
    std::fprintf(stderr, "a results file does not read back as written:\n%s\n", once.c_str());
    std::abort();
  }
  return 0;
}
