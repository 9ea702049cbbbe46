// Replays the SVG fuzzer's seeds (fuzz/svg-corpus/, tests/data/svg/) and every input it found
// (tests/data/svg-fuzz-regressions/) through its checks (fuzz/svg_fuzz_check.cpp), and shows the
// checks tell a good import from a bad one.
#include "svg_fuzz_check.hpp"

#include "support/file_support.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace {

using sweep::fuzz::check_svg_input;
using sweep::test::read_file;

int replay(const std::filesystem::path& folder) {
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    if (!entry.is_regular_file() || entry.path().filename() == "README.md") continue;
    ++files;
    EXPECT_EQ(check_svg_input(read_file(entry.path())), "") << entry.path();
  }
  return files;
}

TEST(SvgFuzzRegressions, EverySeedAndRecordedInputPassesTheChecks) {
  EXPECT_GE(replay(SWEEP_FUZZ_DIR "/svg-corpus"), 3);
  EXPECT_GE(replay(SWEEP_TEST_DATA_DIR "/svg"), 3);
  replay(SWEEP_TEST_DATA_DIR "/svg-fuzz-regressions");
}

TEST(SvgFuzzRegressions, ChecksAcceptImportErrorsAndImportedCurves) {
  EXPECT_EQ(check_svg_input("<svg xmlns=\"http://www.w3.org/2000/svg\"><path d=\"M0 0 C 1 2 x\"/></svg>"), "");
  EXPECT_EQ(check_svg_input("not xml <"), "");
  EXPECT_EQ(check_svg_input("<svg xmlns=\"http://www.w3.org/2000/svg\"><path d=\"M0 0 L1 1 2 0z\"/></svg>"), "");
}

}  // namespace
