// The riders' timeline through the real window: under Xvfb, tests/app/timeline_gui_driver.sh
// takes screenshots of the viewer paused at time 0, a second later still paused, and a second
// after Shift+Space started the riders. Paused, the 3D view does not change at all; playing, the
// riders have moved: some of the view changed, but only a little of it (the camera stayed), and
// the time shown when paused again is about the second that passed.
#include "render/png_file.hpp"
#include "support/gui_driver_support.hpp"
#include "support/rider_test_support.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>

namespace sweep {
namespace {

namespace fs = std::filesystem;

constexpr const char* kRiders = sweep::test::kTwoRidersOnAKnot;

/// The number after `key` on the driver's line starting with `key` (e.g. "panel 368.00"), or -1.
double number_after(const std::string& out, const std::string& key, int which = 0) {
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(key + " ", 0) != 0) continue;
    std::istringstream words(line.substr(key.size()));
    double value = -1.0;
    for (int i = 0; i <= which; ++i) words >> value;
    return value;
  }
  return -1.0;
}

/// Pixels that differ (any channel by more than 8) between `a` and `b` inside [x0, x1) x [y0, y1).
int differing(const render::Image& a, const render::Image& b, int x0, int y0, int x1, int y1) {
  int count = 0;
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) {
      const std::uint8_t* p = a.pixel(x, y);
      const std::uint8_t* q = b.pixel(x, y);
      for (int c = 0; c < 3; ++c) {
        if (std::abs(int(p[c]) - int(q[c])) > 8) {
          ++count;
          break;
        }
      }
    }
  }
  return count;
}

TEST(TimelineGui, PausedTheViewStaysStillAndPlayingMovesTheRiders) {
  if (!test::can_drive_window()) GTEST_SKIP() << "xvfb-run or xdotool is not installed";
  if (std::system("command -v import >/dev/null 2>&1") != 0) GTEST_SKIP() << "ImageMagick's import is not installed";
  const fs::path dir = test::fresh_test_folder(SWEEP_TEST_OUTPUT_DIR, "timeline");
  const fs::path file = dir / "riders.swp";
  test::write_text(file, kRiders);
  const std::string out = test::run_gui_driver("", SWEEP_TIMELINE_DRIVER, file, "track", dir);

  const render::Image paused = render::load_png_file(dir / "paused.png");
  const render::Image later = render::load_png_file(dir / "paused-later.png");
  const render::Image playing = render::load_png_file(dir / "playing.png");
  ASSERT_EQ(paused.width, 1000);
  ASSERT_EQ(paused.height, 700);
  ASSERT_EQ(playing.width, paused.width);
  ASSERT_EQ(later.height, paused.height);
  // The 3D view: between the main panel and the edit panel, above the timeline strip (the status
  // bar, 22, a margin, 8, and the strip, 62), a few pixels inside.
  const int x0 = int(number_after(out, "panel")) + 4;
  const int x1 = int(number_after(out, "edit")) - 4;
  const int y0 = 4;
  const int y1 = 700 - 22 - 8 - 62 - 4;
  ASSERT_GT(x1 - x0, 100) << out;
  const int area = (x1 - x0) * (y1 - y0);

  EXPECT_EQ(differing(paused, later, x0, y0, x1, y1), 0) << "paused, nothing in the view moves";
  const int moved = differing(paused, playing, x0, y0, x1, y1);
  EXPECT_GT(moved, 100) << "playing, the riders moved";
  EXPECT_LT(moved, area / 20) << "only the riders: the camera and the rest stayed";

  // "status riders paused at T s": about the second (and a bit) that passed while playing.
  const std::size_t at = out.find("status riders paused at ");
  ASSERT_NE(at, std::string::npos) << out;
  const double time = std::atof(out.c_str() + at + std::string("status riders paused at ").size());
  EXPECT_GT(time, 0.8);
  EXPECT_LT(time, 5.0);
}

}  // namespace
}  // namespace sweep
