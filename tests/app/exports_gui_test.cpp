// Exports and PNGs through the real window: under Xvfb, tests/app/exports_gui_driver.sh starts
// the viewer from another working folder on ../taper.swp and clicks the File panel's Export STL,
// Export glb, Save PNG of the view and (after typing a name) Save PNG of the window. Every file
// must appear beside the SWP file, none in the working folder, the messages must name each with
// its full path, and the view PNG must be the part of the window the panels leave free, without
// a panel's pixel; asked for at 1920 x 1080 without control points, it is that size without them.
#include "editor/viewport_layout.hpp"
#include "render/png_file.hpp"
#include "support/file_support.hpp"
#include "support/gui_driver_support.hpp"
#include "support/text_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace sweep {
namespace {

namespace fs = std::filesystem;

using test::read_file;

/// The driver's output lines that begin with `word` (without it).
std::vector<std::string> lines_after(const std::string& out, const std::string& word) {
  std::vector<std::string> found;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(word + " ", 0) == 0) found.push_back(line.substr(word.size() + 1));
  }
  return found;
}

bool same_pixel(const render::Image& a, int ax, int ay, const render::Image& b, int bx, int by) {
  return std::memcmp(a.pixel(ax, ay), b.pixel(bx, by), 3) == 0;
}

/// Pixels of the control points' yellow (render::DisplaySettings::control_color, also dimmed).
int yellow_pixels(const render::Image& image) {
  int count = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const unsigned char* p = image.pixel(x, y);
      count += p[0] > 150 && p[1] > 0.8 * p[0] && p[2] < 0.3 * p[0] ? 1 : 0;
    }
  }
  return count;
}

class ExportsGui : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!test::can_drive_window()) GTEST_SKIP() << "xvfb-run or xdotool is not installed";
    dir_ = test::fresh_test_folder(SWEEP_TEST_OUTPUT_DIR, "ExportsGui");
  }

  /// Copies taper.swp into the test's folder and runs the driver on it. Returns its stdout.
  std::string run_driver() {
    fs::copy_file(fs::path(SWEEP_SWP_DIR) / "taper.swp", dir_ / "taper.swp");
    return test::run_gui_driver("", SWEEP_EXPORTS_DRIVER, dir_ / "taper.swp", "horn", dir_, 120);
  }

  fs::path dir_;
};

TEST_F(ExportsGui, ExportsAndPngsGoBesideTheSwpFileAndTheViewPngHasNoPanel) {
  const std::string out = run_driver();
  const fs::path folder = fs::canonical(dir_);  // the viewer's working folder is a real path
  const std::vector<std::string> status = lines_after(out, "status");
  for (const char* name : {"taper_column.stl", "taper_horn.stl", "taper_column.glb", "taper_horn.glb", "taper.svg",
                           "taper.png", "window.png", "big.png"}) {
    EXPECT_TRUE(fs::is_regular_file(folder / name)) << name << " is not beside the SWP file";
    const std::string path = (folder / name).string();
    EXPECT_TRUE(
        std::any_of(status.begin(), status.end(),
                    [&path](const std::string& line) { return line.find(" " + path + " (") != std::string::npos; }))
        << "no message names " << path << ":\n"
        << out;
  }
  // glb (quantized) wrote the glb files again, quantized; SVG the four planar curves.
  EXPECT_NE(test::read_file(folder / "taper_horn.glb").find("KHR_mesh_quantization"), std::string::npos);
  EXPECT_NE(std::find(status.begin(), status.end(), "wrote " + (folder / "taper.svg").string() + " (4 curves)"),
            status.end())
      << out;
  ASSERT_TRUE(fs::is_directory(dir_ / "elsewhere"));
  EXPECT_TRUE(fs::is_empty(dir_ / "elsewhere")) << "nothing goes to the folder Sweep was started from";

  // The free part: from the main panel's right edge to the edit panel's left edge.
  const std::vector<std::string> panel = lines_after(out, "panel");
  const std::vector<std::string> edit = lines_after(out, "edit");
  ASSERT_EQ(panel.size(), 1u) << out;
  ASSERT_EQ(edit.size(), 1u) << out;
  const int left = int(std::stod(panel[0]));
  const int right = int(std::stod(edit[0]));
  const render::Image view = render::load_png_file(folder / "taper.png");
  const render::Image window = render::load_png_file(folder / "window.png");
  EXPECT_EQ(window.width, 1200);
  EXPECT_EQ(window.height, 760);
  ASSERT_EQ(view.width, right - left) << "the view PNG is as wide as the part the panels leave free";
  ASSERT_EQ(view.height, window.height - int(editor::kStatusBarHeight)) << "above the status bar";

  // The same picture as the window's free part, but where the button's tooltip reaches into it
  // and on the selected horn, which a picture of the view draws unselected (4.4 % of it here).
  long same = 0;
  for (int y = 0; y < view.height; ++y) {
    for (int x = 0; x < view.width; ++x) same += same_pixel(view, x, y, window, left + x, y) ? 1 : 0;
  }
  EXPECT_GT(double(same), 0.93 * view.width * view.height) << "the view PNG is not the window's free part";
  // No panel's edge in it: its left column is not the main panel's last one (beside the whole
  // height but the margins), nor its right column the edit panel's first (beside the edit panel).
  std::istringstream edit_words(edit[0]);
  double edit_left = 0.0, edit_bottom = 0.0;
  edit_words >> edit_left >> edit_bottom;
  int left_like = 0;
  for (int y = 0; y < view.height; ++y) left_like += same_pixel(view, 0, y, window, left - 1, y) ? 1 : 0;
  EXPECT_LT(left_like, view.height / 20) << "the main panel's pixels in the view PNG";
  int right_like = 0;
  const int rows = int(edit_bottom) - 20;
  ASSERT_GT(rows, 100) << out;
  for (int y = 10; y < 10 + rows; ++y) right_like += same_pixel(view, view.width - 1, y, window, right, y) ? 1 : 0;
  EXPECT_LT(right_like, rows / 20) << "the edit panel's pixels in the view PNG";

  // Asked for at 1920 x 1080 without the control points (drawn yellow), it has that size and
  // none of their pixels, where the view's own PNG has them.
  const render::Image big = render::load_png_file(folder / "big.png");
  EXPECT_EQ(big.width, 1920);
  EXPECT_EQ(big.height, 1080);
  EXPECT_GT(yellow_pixels(view), 50);
  EXPECT_EQ(yellow_pixels(big), 0);
}

// Issue 58: the 3MF export at a typed height, its findings listed, a click selecting the surface
// a finding names (print_gui_driver.sh). The capped bar is selected first; the open tube warns.
TEST_F(ExportsGui, A3mfExportListsItsFindingsAndAClickSelectsTheSurface) {
  const std::string shapes = "circ ring 16 0.3\nbez3 path 4 4\n[0 0 0]\n[0 1 0]\n[0 2 0]\n[0 3 0]\n";
  test::write_text(dir_ / "print.swp", shapes +
                                           "gcyl tube ring path\nbez3 across 4 4\n[-1 4 0]\n[0 4 0]\n[1 4 0]\n"
                                           "[2 4 0]\ngcyl bar ring across caps\n");
  const std::string out = test::run_gui_driver("", SWEEP_PRINT_DRIVER, dir_ / "print.swp", "bar", dir_, 120);
  const fs::path folder = fs::canonical(dir_);
  EXPECT_TRUE(fs::is_regular_file(folder / "print.3mf")) << out;
  const std::vector<std::string> status = lines_after(out, "status");
  const std::string open =
      (folder / "print.swp").string() +
      ":7:1: warning: surface 'tube' is open: 2 holes (32 boundary edges); a printer needs a closed "
      "solid";
  EXPECT_NE(std::find(status.begin(), status.end(), open), status.end()) << out;
  const std::vector<std::string> selection = lines_after(out, "selection");
  ASSERT_GE(selection.size(), 2u) << out;
  EXPECT_EQ(selection.front(), "bar");
  EXPECT_EQ(selection.back(), "tube");
}

}  // namespace
}  // namespace sweep
