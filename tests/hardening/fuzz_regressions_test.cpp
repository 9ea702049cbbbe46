// Replays every input in tests/data/fuzz-regressions/ (crashes, hangs and property violations the
// fuzzer found, each named after what it found) and the starter files through the fuzzer's checks.
#include "swp_fuzz_check.hpp"

#include "support/file_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace {

std::vector<std::filesystem::path> files_in(const std::filesystem::path& folder) {
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (entry.is_regular_file() && entry.path().filename() != "README.md") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  return files;
}

using sweep::test::read_file;

TEST(FuzzRegressions, EveryRecordedInputPassesTheFuzzChecks) {
  const auto files = files_in(SWEEP_TEST_DATA_DIR "/fuzz-regressions");
  ASSERT_FALSE(files.empty()) << "tests/data/fuzz-regressions/ holds the fuzzer's findings";
  for (const auto& file : files) {
    EXPECT_EQ(sweep::fuzz::check_swp_input(read_file(file)), "") << file;
  }
}

TEST(FuzzRegressions, EveryStarterFilePassesTheFuzzChecks) {
  const auto files = files_in(SWEEP_SWP_DIR);
  ASSERT_GE(files.size(), 10u);
  for (const auto& file : files) {
    EXPECT_EQ(sweep::fuzz::check_swp_input(read_file(file)), "") << file;
  }
}

// A ParseError is a fine outcome for the fuzzer; a valid document is evaluated and exported.
TEST(FuzzRegressions, ChecksAcceptParseErrorsAndValidDocuments) {
  EXPECT_EQ(sweep::fuzz::check_swp_input("bez2 . 0 4"), "");
  EXPECT_EQ(sweep::fuzz::check_swp_input("circ c 8 1\nsrev s 4 c"), "");
}

}  // namespace
