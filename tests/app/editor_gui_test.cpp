// The editor through the real window: under Xvfb, tests/render/editor_gui_driver.sh drags one
// control point with xdotool, saves with Ctrl+S and quits; the saved file must differ from the
// original in exactly that point (and its seam partners), still load, and keep everything else.
#include "core/document.hpp"
#include "core/edit.hpp"
#include "core/swp_parser.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace sweep {
namespace {

namespace fs = std::filesystem;

std::string quoted(const fs::path& p) {
  std::string text(1, '\'');
  text.append(p.string());
  text.push_back('\'');
  return text;
}

std::string slurp(const fs::path& p) {
  std::ifstream in(p);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

struct Drag {
  int handle = -1;
  int dx = 0;
  int dy = 0;
};

class EditorGui : public ::testing::Test {
 protected:
  void SetUp() override {
    if (std::system("command -v xvfb-run >/dev/null 2>&1 && command -v xdotool >/dev/null 2>&1") != 0) {
      GTEST_SKIP() << "xvfb-run or xdotool is not installed";
    }
    dir_ = fs::path(SWEEP_TEST_OUTPUT_DIR) / ::testing::UnitTest::GetInstance()->current_test_info()->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }

  /// Copies `swp_name` from swp/ and drags a handle of `object` in the window. Returns the drag.
  Drag drag_and_save(const std::string& swp_name, const std::string& object) {
    file_ = dir_ / swp_name;
    fs::copy_file(fs::path(SWEEP_SWP_DIR) / swp_name, file_);
    // timeout: the whole run can never hang the test suite.
    const std::string command = "timeout 90 xvfb-run -a -s '-screen 0 1280x800x24' bash " + quoted(SWEEP_GUI_DRIVER) +
                                " " + quoted(SWEEP_EXECUTABLE) + " " + quoted(file_) + " '" + object + "' " +
                                quoted(dir_) + " >" + quoted(dir_ / "driver.out") + " 2>" + quoted(dir_ / "driver.err");
    const int status = std::system(command.c_str());
    const std::string out = slurp(dir_ / "driver.out");
    EXPECT_EQ(status, 0) << out << slurp(dir_ / "driver.err");
    Drag drag;
    std::istringstream words(out);
    std::string word;
    while (words >> word) {
      if (word == "dragged") words >> drag.handle >> drag.dx >> drag.dy;
    }
    return drag;
  }

  fs::path dir_;
  fs::path file_;
};

/// Checks that `saved` equals `original` but for the points of object `index` in `moved`.
void expect_only_points_changed(const Document& original, const Document& saved, int index,
                                const std::vector<int>& moved) {
  ASSERT_EQ(saved.objects.size(), original.objects.size());
  for (std::size_t i = 0; i < original.objects.size(); ++i) {
    if (int(i) != index) {
      EXPECT_EQ(saved.objects[i], original.objects[i]) << "object " << i << " changed";
      continue;
    }
    Object expected = original.objects[i];
    const Object& got = saved.objects[i];
    ASSERT_EQ(got.points.size(), expected.points.size());
    for (int p : moved) {
      EXPECT_NE(got.points[std::size_t(p)], expected.points[std::size_t(p)]) << "point " << p << " did not move";
      expected.points[std::size_t(p)] = got.points[std::size_t(p)];
    }
    EXPECT_EQ(got, expected) << "more than the dragged point changed";
  }
}

TEST_F(EditorGui, DraggingA2DHandleChangesExactlyThatPointInTheSavedFile) {
  const Document original = load_swp_file(fs::path(SWEEP_SWP_DIR) / "core.swp");
  const Drag drag = drag_and_save("core.swp", "bez2#0");
  ASSERT_GE(drag.handle, 0);
  const Document saved = load_swp_file(file_);  // still loads
  const int index = 0;
  const std::vector<int> moved = seam_partners(original.objects[index], drag.handle);
  expect_only_points_changed(original, saved, index, moved);
  const glm::dvec3 before = original.objects[index].points[std::size_t(drag.handle)];
  const glm::dvec3 after = saved.objects[index].points[std::size_t(drag.handle)];
  EXPECT_EQ(after.z, 0.0) << "a 2D point stays in the xy-plane";
  // The default view looks at the xy-plane from the front right and above: a drag right and up
  // moves the point towards +x and +y.
  EXPECT_GT(after.x, before.x);
  EXPECT_GT(after.y, before.y);
}

TEST_F(EditorGui, DraggingA3DHandleChangesExactlyThatPointInTheSavedFile) {
  const Document original = load_swp_file(fs::path(SWEEP_SWP_DIR) / "core.swp");
  const Drag drag = drag_and_save("core.swp", "bsp3#3");
  ASSERT_GE(drag.handle, 0);
  const Document saved = load_swp_file(file_);
  const int index = 3;
  expect_only_points_changed(original, saved, index, seam_partners(original.objects[index], drag.handle));
}

TEST_F(EditorGui, DraggingTheWineglassProfileChangesOnlyThatPoint) {
  // wineglass.swp: a surface of revolution of an open B-spline profile; the drag re-meshes it.
  const Document original = load_swp_file(fs::path(SWEEP_SWP_DIR) / "wineglass.swp");
  const Drag drag = drag_and_save("wineglass.swp", "profile");
  ASSERT_GE(drag.handle, 0);
  const Document saved = load_swp_file(file_);
  const int index = original.find("profile");
  ASSERT_GE(index, 0);
  expect_only_points_changed(original, saved, index, seam_partners(original.objects[std::size_t(index)], drag.handle));
}

}  // namespace
}  // namespace sweep
