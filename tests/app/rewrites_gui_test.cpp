// Another program writing the open file while the real window watches it (issue 29): 1 000
// rewrites in about 10 seconds (rewrites_gui_driver.sh). The viewer stays up, never shows a
// version that was not written whole (a two-part write's first part is itself a valid file), and
// shows the last version soon after the last write (goal 0.5 s: the figure is printed and
// recorded in docs/reliability.md; the bound here is loose so that a loaded machine passes).
#include "support/gui_driver_support.hpp"

#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

namespace sweep {
namespace {

namespace fs = std::filesystem;

TEST(RewritesGui, TheViewerShowsOnlyWholeVersionsAndSettlesOnTheLast) {
  if (!test::can_drive_window()) GTEST_SKIP() << "xvfb-run or xdotool is not installed";
  const fs::path dir = test::fresh_test_folder(SWEEP_TEST_OUTPUT_DIR, "rewrites");
  const fs::path file = dir / "watched.swp";
  test::write_text(file, "circ a 10 1\ncirc b 10 1\n");
  const std::string out = test::run_gui_driver("", SWEEP_REWRITES_DRIVER, file, "a", dir, 120);
  std::printf("%s", out.c_str());  // the figures: versions written and shown, the settle time
  EXPECT_NE(out.find("written 1000 valid 501 invalid 499"), std::string::npos) << out;
  const std::size_t at = out.find("settled in ");
  ASSERT_NE(at, std::string::npos) << out;
  EXPECT_LT(std::atof(out.c_str() + at + 11), 3.0) << out;
  // The versions left for 150 ms were read and shown (the storm's pauses), besides the first and last.
  const std::size_t shown = out.find("shown ");
  ASSERT_NE(shown, std::string::npos) << out;
  EXPECT_GE(std::atoi(out.c_str() + shown + 6), 5) << out;
  EXPECT_NE(out.find("\ndone"), std::string::npos) << out;
}

}  // namespace
}  // namespace sweep
