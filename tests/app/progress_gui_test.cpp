// Long work in the real window (Xvfb, xdotool): a subdivision level whose re-mesh takes seconds
// runs in the background; its progress bar offers Cancel, which takes the document back to what
// the view shows (issue 29, "never freezing").
#include "support/gui_driver_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>

namespace sweep {
namespace {

namespace fs = std::filesystem;

/// A torus cage of `rows` x `columns` quads and its Catmull-Clark subdivision at level 1.
std::string torus_cage(int rows, int columns) {
  std::ostringstream text;
  text << "mesh cage " << rows * columns << ' ' << rows * columns << '\n';
  const double pi = std::acos(-1.0);
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      const double u = 2 * pi * i / rows;
      const double v = 2 * pi * j / columns;
      text << '[' << (3 + std::cos(v)) * std::cos(u) << ' ' << std::sin(v) << ' ' << (3 + std::cos(v)) * std::sin(u)
           << "]\n";
    }
  }
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      const int next_i = (i + 1) % rows;
      const int next_j = (j + 1) % columns;
      text << '[' << i * columns + j << ' ' << i * columns + next_j << ' ' << next_i * columns + next_j << ' '
           << next_i * columns + j << "]\n";
    }
  }
  text << "subd smooth 1 cage\n";
  return text.str();
}

TEST(ProgressGui, ALongRemeshShowsProgressAndCancelGoesBack) {
  if (!test::can_drive_window()) GTEST_SKIP() << "xvfb-run or xdotool is not installed";
  const fs::path dir = test::fresh_test_folder(SWEEP_TEST_OUTPUT_DIR, "progress");
  const fs::path file = dir / "cage.swp";
  // 12 000 faces: level 5 has 12 million vertices, a re-mesh of about a second on two cores,
  // on one thread (SWEEP_THREADS=1) about two, which leaves the driver time to click Cancel
  // on a loaded CI machine too (on two cores it once finished first).
  test::write_text(file, torus_cage(100, 120));
  const std::string out = test::run_gui_driver("SWEEP_THREADS=1", SWEEP_PROGRESS_DRIVER, file, "smooth", dir);

  EXPECT_NE(out.find("\nstatus cancelled: back to what the view showed"), std::string::npos) << out;
  // The cage (12 000 vertices, drawn in the wire mode) and level 1 (48 000 quads, two triangles
  // each), before the edit and after Cancel; no other mesh (level 5) was ever shown.
  const std::string level_one = "counts vertices 60000 triangles 120000";
  EXPECT_NE(out.find(level_one), std::string::npos) << out;
  EXPECT_EQ(out.find("counts vertices", out.find(level_one) + 1), std::string::npos) << out;
  EXPECT_NE(out.find("done"), std::string::npos) << out;
}

}  // namespace
}  // namespace sweep
