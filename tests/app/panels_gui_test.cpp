// Issue 47 ("The viewer's second hour") in the real window under Xvfb: the Create panel shows at
// 1280x800 and what it adds is said in the status bar, an export's warning is shown as a warning
// (create_gui_driver.sh, items 4 and 5); the Help window fits the window and scrolls, and an
// empty view shows the ground grid from above at an angle, not edge-on as a line
// (view_aids_gui_driver.sh, item 9). Issue 59: new objects stand beside the scene
// (place_gui_driver.sh, item 3).
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"
#include "render/png_file.hpp"
#include "support/gui_driver_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <sstream>
#include <string>

namespace sweep {
namespace {

namespace fs = std::filesystem;

/// The rest of the driver's line that starts with `key` and a space, or "" if none does.
std::string after(const std::string& out, const std::string& key) {
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(key + " ", 0) == 0) return line.substr(key.size() + 1);
  }
  return {};
}

/// The rows of [x0, x1) x [y0, y1) of `image` with at least 20 pixels unlike its background (the
/// region's most common colour; unlike: a channel more than 12 away): a grid seen from above at
/// an angle spans hundreds, one seen edge-on is a line of a row or two.
int rows_with_lines(const render::Image& image, int x0, int y0, int x1, int y1) {
  std::map<std::uint32_t, int> counts;
  const auto colour = [&image](int x, int y) {
    const std::uint8_t* p = image.pixel(x, y);
    return std::uint32_t(p[0]) << 16 | std::uint32_t(p[1]) << 8 | std::uint32_t(p[2]);
  };
  for (int y = y0; y < y1; ++y) {
    for (int x = x0; x < x1; ++x) ++counts[colour(x, y)];
  }
  std::uint32_t background = 0;
  int most = 0;
  for (const auto& [c, n] : counts) {
    if (n > most) {
      background = c;
      most = n;
    }
  }
  int rows = 0;
  for (int y = y0; y < y1; ++y) {
    int unlike = 0;
    for (int x = x0; x < x1; ++x) {
      const std::uint32_t c = colour(x, y);
      for (int shift : {0, 8, 16}) {
        if (std::abs(int((c >> shift) & 0xFFu) - int((background >> shift) & 0xFFu)) > 12) {
          ++unlike;
          break;
        }
      }
    }
    rows += unlike >= 20 ? 1 : 0;
  }
  return rows;
}

// Items 4 and 5: the Create panel was below the fold of a 1280x800 window (under Display and a
// long outliner); adding a curve said nothing; an STL export's warning hid behind "(and 1 more)".
TEST(PanelsGui, CreateShowsAt1280x800AndTheStatusBarSaysWhatItAddedAndWarns) {
  if (!test::can_drive_window()) GTEST_SKIP() << "xvfb-run or xdotool is not installed";
  const fs::path dir = test::fresh_test_folder(SWEEP_TEST_OUTPUT_DIR, "create");
  for (const char* name : {"chess-queen.swp", "wood.png", "grain.png"}) {
    fs::copy_file(fs::path(SWEEP_SWP_DIR) / "artifacts" / name, dir / name);
  }
  const std::string out = test::run_gui_driver("", SWEEP_CREATE_DRIVER, dir / "chess-queen.swp", "body", dir, 120);
  for (const char* part : {"ok create visible ", "ok curve\n", "ok surface\n", "ok warning\n", "done\n"}) {
    EXPECT_NE(out.find(part), std::string::npos) << part << out;
  }
  EXPECT_TRUE(fs::exists(dir / "chess-queen_revolution.stl")) << "the warning's file was written all the same";
}

// Issue 59, item 3: new objects where the user can see them. On the wineglass the trefoil knot
// stands beside the glass on its ground, and the tube of a circle along it never passes through
// itself (no fold: the circle shrinks to fit the knot's tightest bend); the saved file says where
// the knot stands.
TEST(PanelsGui, NewObjectsStandBesideTheSceneAndMakeACleanTube) {
  if (!test::can_drive_window()) GTEST_SKIP() << "xvfb-run or xdotool is not installed";
  const fs::path dir = test::fresh_test_folder(SWEEP_TEST_OUTPUT_DIR, "place");
  fs::copy_file(fs::path(SWEEP_SWP_DIR) / "wineglass.swp", dir / "wineglass.swp");
  const std::string out = test::run_gui_driver("", SWEEP_PLACE_DRIVER, dir / "wineglass.swp", "wineglass", dir, 120);
  for (const char* part : {"ok knot\n", "ok circle\n", "ok tube\n", "done\n"}) {
    EXPECT_NE(out.find(part), std::string::npos) << part << out;
  }
  const Document saved = io::load_swp_file(dir / "wineglass.swp");
  const Scene scene = evaluate_document(saved);
  const int glass = saved.find("wineglass");
  const int knot = saved.find("knot");
  const int tube = saved.find("cylinder");
  ASSERT_GE(glass, 0);
  ASSERT_GE(knot, 0);
  ASSERT_GE(tube, 0);
  double glass_right = -1e300;
  for (const glm::vec3& p : scene.objects[std::size_t(glass)].mesh.positions)
    glass_right = std::max(glass_right, double(p.x));
  for (const Frame& f : scene.objects[std::size_t(knot)].curve.frames) EXPECT_GT(f.V.x, glass_right);
  EXPECT_TRUE(scene.objects[std::size_t(tube)].diagnostics.folds.empty()) << "the tube folds over itself";
}

// Item 9: the Help window ran past the bottom of the window, its last rows out of reach; an empty
// view (started without a file) looked at the ground grid edge-on, a line.
TEST(PanelsGui, HelpFitsAndScrollsAndAnEmptyViewShowsTheGridFromAbove) {
  if (!test::can_drive_window()) GTEST_SKIP() << "xvfb-run or xdotool is not installed";
  const fs::path dir = test::fresh_test_folder(SWEEP_TEST_OUTPUT_DIR, "view-aids");
  fs::copy_file(fs::path(SWEEP_SWP_DIR) / "wineglass.swp", dir / "wineglass.swp");
  const std::string out = test::run_gui_driver("", SWEEP_VIEW_AIDS_DRIVER, dir / "wineglass.swp", "profile", dir, 120);
  for (const char* part : {"ok help fits\n", "ok help scrolls\n", "done\n"}) {
    EXPECT_NE(out.find(part), std::string::npos) << part << out;
  }
  // File > New: the view alone (the part of the window the panels leave free).
  const std::string new_view = after(out, "new view");
  ASSERT_FALSE(new_view.empty()) << out;
  const render::Image view = render::load_png_file(new_view);
  EXPECT_GT(rows_with_lines(view, 0, 0, view.width, view.height), view.height / 4) << new_view;
  // Started without a file: the window, between the main panel (368 wide) and the Edit panel
  // (from x = 922), under the Edit panel's few rows and above the status bar.
  const std::string empty = after(out, "empty start");
  ASSERT_FALSE(empty.empty()) << out;
  const render::Image window = render::load_png_file(empty);
  ASSERT_EQ(window.width, 1280);
  ASSERT_EQ(window.height, 800);
  EXPECT_GT(rows_with_lines(window, 380, 100, 910, 770), 200) << empty << ": the grid edge-on?";
}

}  // namespace
}  // namespace sweep
