// The editor through the real window: under Xvfb, tests/app/editor_gui_driver.sh drags one
// control point with xdotool, saves with Ctrl+S and quits; the saved file must differ from the
// original in exactly that point (and its seam partners), still load, and keep everything else.
// tests/app/adaptive_gui_driver.sh clicks the Adaptive checkbox on and off; the counts the
// stats panel shows must change and come back. tests/app/caps_gui_driver.sh clicks a surface's
// caps checkbox and saves: the file must differ in exactly that clause.
// tests/app/fields_gui_driver.sh types into Material and Edit panel fields as a user does
// (Ctrl+click, key by key, Return) and saves: the file holds exactly the typed values.
#include "io/swp/read.hpp"
#include "model/document.hpp"
#include "model/edit/edit.hpp"
#include "support/file_support.hpp"
#include "support/gui_driver_support.hpp"
#include "support/text_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace sweep {
namespace {

namespace fs = std::filesystem;

using test::read_file;
using test::write_text;

struct Drag {
  int handle = -1;
  int dx = 0;
  int dy = 0;
};

class EditorGui : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!test::can_drive_window()) GTEST_SKIP() << "xvfb-run or xdotool is not installed";
    dir_ =
        test::fresh_test_folder(SWEEP_TEST_OUTPUT_DIR, ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }

  /// Runs `driver` on a copy of `swp_name` from swp/ with `object` selected. Returns its stdout.
  std::string run_driver(const char* driver, const std::string& swp_name, const std::string& object) {
    file_ = dir_ / swp_name;
    if (text_.empty()) {
      fs::copy_file(fs::path(SWEEP_SWP_DIR) / swp_name, file_);
    } else {
      write_text(file_, text_);
    }
    return test::run_gui_driver(env_, driver, file_, object, dir_);
  }

  /// Copies `swp_name` from swp/ and drags a handle of `object` in the window. Returns the drag.
  Drag drag_and_save(const std::string& swp_name, const std::string& object) {
    const std::string out = run_driver(SWEEP_GUI_DRIVER, swp_name, object);
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
  std::string text_;  // when set, the file run_driver opens instead of a copy from swp/
  std::string env_;   // more environment for the driver ("NAME=value ")
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
    ASSERT_EQ(got.as<PointsPart>().points.size(), expected.as<PointsPart>().points.size());
    for (int p : moved) {
      EXPECT_NE(got.as<PointsPart>().points[std::size_t(p)], expected.as<PointsPart>().points[std::size_t(p)])
          << "point " << p << " did not move";
      expected.as<PointsPart>().points[std::size_t(p)] = got.as<PointsPart>().points[std::size_t(p)];
    }
    EXPECT_EQ(got, expected) << "more than the dragged point changed";
  }
}

/// Lines that differ between two texts of the same line count; -1 if the counts differ.
int changed_line_count(const std::string& a, const std::string& b) {
  std::istringstream x(a), y(b);
  std::string p, q;
  int changed = 0;
  while (true) {
    const bool more_x = static_cast<bool>(std::getline(x, p)), more_y = static_cast<bool>(std::getline(y, q));
    if (more_x != more_y) return -1;
    if (!more_x) return changed;
    changed += p != q ? 1 : 0;
  }
}

TEST_F(EditorGui, DraggingA2DHandleChangesExactlyThatPointInTheSavedFile) {
  const Document original = io::load_swp_file(fs::path(SWEEP_SWP_DIR) / "core.swp");
  const Drag drag = drag_and_save("core.swp", "bez2#0");
  ASSERT_GE(drag.handle, 0);
  const Document saved = io::load_swp_file(file_);  // still loads
  const int index = 0;
  const std::vector<int> moved = seam_partners(original.objects[index], drag.handle);
  expect_only_points_changed(original, saved, index, moved);
  const glm::dvec3 before = original.objects[index].as<PointsPart>().points[std::size_t(drag.handle)];
  const glm::dvec3 after = saved.objects[index].as<PointsPart>().points[std::size_t(drag.handle)];
  EXPECT_EQ(after.z, 0.0) << "a 2D point stays in the xy-plane";
  // The default view looks at the xy-plane from the front right and above: a drag right and up
  // moves the point towards +x and +y.
  EXPECT_GT(after.x, before.x);
  EXPECT_GT(after.y, before.y);
}

TEST_F(EditorGui, DraggingA3DHandleChangesExactlyThatPointInTheSavedFile) {
  const Document original = io::load_swp_file(fs::path(SWEEP_SWP_DIR) / "core.swp");
  const Drag drag = drag_and_save("core.swp", "bsp3#3");
  ASSERT_GE(drag.handle, 0);
  const Document saved = io::load_swp_file(file_);
  const int index = 3;
  expect_only_points_changed(original, saved, index, seam_partners(original.objects[index], drag.handle));
}

// A press and release on a handle without moving is a click, not a drag: no edit, nothing
// unsaved (the title has no '*'), and the saved file holds exactly the points it had.
TEST_F(EditorGui, ClickingAHandleWithoutMovingChangesNothing) {
  const Document original = io::load_swp_file(fs::path(SWEEP_SWP_DIR) / "core.swp");
  env_ = "SWEEP_DRIVER_CLICK=1 ";
  const Drag drag = drag_and_save("core.swp", "bsp3#3");
  ASSERT_GE(drag.handle, 0);
  EXPECT_EQ(drag.dx, 0);
  EXPECT_EQ(drag.dy, 0);
  const std::string out = read_file(dir_ / "driver.out");
  EXPECT_NE(out.find("title core.swp \xE2\x80\x94 Sweep"), std::string::npos) << "the click left unsaved changes:\n"
                                                                              << out;
  // Saving is format-preserving: the file comes back byte for byte.
  EXPECT_TRUE(read_file(file_) == read_file(fs::path(SWEEP_SWP_DIR) / "core.swp")) << read_file(file_);
}

// A cage and a patch alone in the view, so their handles are far apart (in the starter files
// many coincide on screen, and the driver only grabs a handle with no other near it).
TEST_F(EditorGui, DraggingACagePointChangesExactlyThatPointInTheSavedFile) {
  text_ =
      "mesh box 8 6\n[-1 -1 -1]\n[1 -1 -1]\n[1 1 -1]\n[-1 1 -1]\n[-1 -1 1]\n[1 -1 1]\n[1 1 1]\n[-1 1 1]\n"
      "[0 3 2 1]\n[4 5 6 7]\n[0 1 5 4]\n[1 2 6 5]\n[2 3 7 6]\n[3 0 4 7]\n\nsubd round 2 box\n\n";
  const Document original = io::parse_swp(text_, "box.swp");
  const Drag drag = drag_and_save("box.swp", "box");
  ASSERT_GE(drag.handle, 0);
  const Document saved = io::load_swp_file(file_);
  expect_only_points_changed(original, saved, 0, {drag.handle});
}

TEST_F(EditorGui, DraggingAPatchPointChangesExactlyThatPointInTheSavedFile) {
  text_ = "bezpatch hill 6 1\n";
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const bool inner = (i == 1 || i == 2) && (j == 1 || j == 2);
      // Appended piece by piece: "[" + std::to_string(...) trips GCC 12's false -Wrestrict.
      text_ += '[';
      text_ += std::to_string(j);
      text_ += inner ? " 1 " : " 0 ";
      text_ += std::to_string(i);
      text_ += "]\n";
    }
  }
  const Document original = io::parse_swp(text_, "hill.swp");
  const Drag drag = drag_and_save("hill.swp", "hill");
  ASSERT_GE(drag.handle, 0);
  const Document saved = io::load_swp_file(file_);
  expect_only_points_changed(original, saved, 0, seam_partners(original.objects[0], drag.handle));
}

TEST_F(EditorGui, KillingTheViewerMidEditLosesNothingButTheLastSecond) {
  // Drag, wait for the recovery copy (at most a second after the drag), kill -9, start again
  // on the same file: the copy is offered, Return recovers it, Ctrl+S saves it.
  env_ = "SWEEP_DRIVER_KILL=1 ";
  const Document original = io::load_swp_file(fs::path(SWEEP_SWP_DIR) / "core.swp");
  const Drag drag = drag_and_save("core.swp", "bez2#0");
  ASSERT_GE(drag.handle, 0);
  const Document saved = io::load_swp_file(file_);
  expect_only_points_changed(original, saved, 0, seam_partners(original.objects[0], drag.handle));
  // A clean save and quit leave no copy behind.
  const fs::path copies = dir_ / "state" / "sweep";
  ASSERT_TRUE(fs::is_directory(copies));
  EXPECT_TRUE(fs::is_empty(copies));
}

TEST_F(EditorGui, AnotherProgramsSaveUnderUnsavedEditsAsksAndKeepsThem) {
  // The file changes on disk after a drag: the viewer asks (Return keeps the drag), and Save
  // asks again before replacing the changed file; the saved file is the drag, not the change.
  env_ = "SWEEP_DRIVER_CONFLICT=1 ";
  const Document original = io::load_swp_file(fs::path(SWEEP_SWP_DIR) / "core.swp");
  const Drag drag = drag_and_save("core.swp", "bez2#0");
  ASSERT_GE(drag.handle, 0);
  expect_only_points_changed(original, io::load_swp_file(file_), 0, seam_partners(original.objects[0], drag.handle));
}

TEST_F(EditorGui, TheViewerReloadsWhatAnotherProgramSaves) {
  const std::string out = run_driver(SWEEP_RELOAD_DRIVER, "core.swp", "bez2#0");
  // In place, rename-over, an error (file:line:column, the last good scene kept), fixed.
  std::istringstream lines(out);
  std::vector<std::string> got;
  for (std::string line; std::getline(lines, line);) got.push_back(line);
  const std::string path = file_.string();
  ASSERT_EQ(got.size(), 5u) << out;
  EXPECT_EQ(got[0], "reloaded " + path + " selected bez2#0");
  EXPECT_EQ(got[1], "reloaded " + path + " selected bez2#0");
  EXPECT_EQ(got[2], "reload failed " + path + ":2:1: expected a number (radius), found end of file");
  EXPECT_EQ(got[3], "reloaded " + path + " selected bez2#0");
  EXPECT_EQ(got[4], "done");
}

TEST_F(EditorGui, DraggingTheWineglassProfileChangesOnlyThatPoint) {
  // wineglass.swp: a surface of revolution of an open B-spline profile; the drag re-meshes it.
  const Document original = io::load_swp_file(fs::path(SWEEP_SWP_DIR) / "wineglass.swp");
  const Drag drag = drag_and_save("wineglass.swp", "profile");
  ASSERT_GE(drag.handle, 0);
  const Document saved = io::load_swp_file(file_);
  const int index = original.find("profile");
  ASSERT_GE(index, 0);
  expect_only_points_changed(original, saved, index, seam_partners(original.objects[std::size_t(index)], drag.handle));
  // The save is format-preserving: one line of the file changed, the dragged point's.
  EXPECT_EQ(changed_line_count(read_file(fs::path(SWEEP_SWP_DIR) / "wineglass.swp"), read_file(file_)), 1);
}

/// The stats panel's counts as a scripted viewer prints them: "counts vertices V [(by STEPS S)]
/// triangles ...". -1 for a number not there.
struct ShownCounts {
  long long vertices = -1;
  long long vertices_by_steps = -1;
  long long triangles = -1;
};

std::vector<ShownCounts> shown_counts(const std::string& out) {
  std::vector<ShownCounts> all;
  std::istringstream lines(out);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.rfind("counts ", 0) != 0) continue;
    ShownCounts c;
    std::istringstream words(line);
    std::string word;
    long long* last = nullptr;
    while (words >> word) {
      if (word == "vertices") {
        words >> c.vertices;
        last = &c.vertices_by_steps;
      } else if (word == "triangles") {
        words >> c.triangles;
        last = nullptr;
      } else if (word == "STEPS" && last != nullptr) {
        std::string number;
        words >> number;  // "8192)"
        *last = std::stoll(number);
      }
    }
    all.push_back(c);
  }
  return all;
}

TEST_F(EditorGui, TogglingAdaptiveChangesTheVertexCountShown) {
  // weird.swp: a star-shaped profile along a closed 3D sweep, with straight runs and tight turns.
  const std::vector<ShownCounts> counts = shown_counts(run_driver(SWEEP_ADAPTIVE_DRIVER, "weird.swp", "profile"));
  ASSERT_EQ(counts.size(), 3u) << "before, Adaptive on, Adaptive off";
  const ShownCounts& steps = counts[0];
  const ShownCounts& adaptive = counts[1];
  EXPECT_GT(steps.vertices, 0);
  EXPECT_EQ(steps.vertices_by_steps, -1) << "no comparison without a tolerance";
  EXPECT_NE(adaptive.vertices, steps.vertices);
  EXPECT_LT(adaptive.vertices, steps.vertices) << "the default tolerance (1e-3 of the scene) saves vertices here";
  EXPECT_EQ(adaptive.vertices_by_steps, steps.vertices) << "the uniform count beside the adaptive one";
  EXPECT_NE(adaptive.triangles, steps.triangles);
  EXPECT_EQ(counts[2].vertices, steps.vertices) << "off again: by STEPS as before";
  EXPECT_EQ(counts[2].triangles, steps.triangles);
}

TEST_F(EditorGui, ClickingCapsAndSavingWritesTheClause) {
  // taper.swp's horn is capped: one click turns its caps off, and the saved file says so.
  const Document original = io::load_swp_file(fs::path(SWEEP_SWP_DIR) / "taper.swp");
  run_driver(SWEEP_CAPS_DRIVER, "taper.swp", "horn");
  const Document saved = io::load_swp_file(file_);
  const int horn = original.find("horn");
  ASSERT_GE(horn, 0);
  EXPECT_TRUE(original.objects[std::size_t(horn)].as<CapsPart>().caps);
  EXPECT_FALSE(saved.objects[std::size_t(horn)].as<CapsPart>().caps) << "the click should have turned the caps off";
  Document expected = original;
  expected.objects[std::size_t(horn)].as<CapsPart>().caps = false;
  EXPECT_EQ(saved, expected) << "only the caps clause changed";
}

/// The lines "typing NAME TEXT title TITLE" the fields driver prints before each Return.
std::vector<std::string> typing_lines(const std::string& out) {
  std::vector<std::string> lines;
  std::istringstream in(out);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("typing ", 0) == 0) lines.push_back(line);
  }
  return lines;
}

TEST_F(EditorGui, TypingIntoMaterialFieldsSavesExactlyTheTypedValues) {
  // A refused shininess, then a shininess and checker cells, each typed key by key with Return.
  text_ =
      "material tiles checker 4 shininess 32\n\ncirc ring 12 0.5\ncirc path 24 3\ngcyl tiled ring path material "
      "tiles\n";
  env_ = "SWEEP_DRIVER_TYPING='scroll=15;material panel;scroll=15;shininess=2000;shininess=250;checker=12' ";
  const Document original = io::parse_swp(text_, "tiles.swp");
  const std::string out = run_driver(SWEEP_FIELDS_DRIVER, "tiles.swp", "tiles");
  const std::vector<std::string> typing = typing_lines(out);
  ASSERT_EQ(typing.size(), 3u) << out;
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(typing[i].find('*'), std::string::npos) << "applied while typing (the title says unsaved): " << typing[i];
  }
  EXPECT_NE(out.find("error material 'tiles': the shininess must be from 1 to 1000"), std::string::npos) << out;
  Document expected = original;
  expected.objects[0].as<MaterialLook>().shininess = 250.0;
  expected.objects[0].as<MaterialLook>().checker = 12;
  EXPECT_EQ(io::load_swp_file(file_), expected) << read_file(file_);
}

TEST_F(EditorGui, TypingIntoAPointCoordinateSavesExactlyTheTypedValue) {
  // 1e13 is refused (1e1 on the way must not apply), 2.5 applies, letters are refused.
  text_ = "bsp2 profile 20 4\n[1.000000 0.000000]\n[1.000000 1.000000]\n[3.000000 1.000000]\n[3.000000 0.000000]\n";
  env_ = "SWEEP_DRIVER_TYPING='point 1 x=1e13;point 1 x=2.5;point 1 y=abc' ";
  const std::string out = run_driver(SWEEP_FIELDS_DRIVER, "profile.swp", "profile");
  const std::vector<std::string> typing = typing_lines(out);
  ASSERT_EQ(typing.size(), 3u) << out;
  for (std::size_t i = 0; i < 2; ++i) {
    EXPECT_EQ(typing[i].find('*'), std::string::npos) << "applied while typing (the title says unsaved): " << typing[i];
  }
  EXPECT_NE(out.find("error coordinate x = 1e+13 is out of range: coordinates must be from -1e12 to 1e12"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("error expected a number (y of point 1), found 'abc'"), std::string::npos) << out;
  Document expected = io::parse_swp(text_, "profile.swp");
  expected.objects[0].as<PointsPart>().points[1] = glm::dvec3(2.5, 1.0, 0.0);
  EXPECT_EQ(io::load_swp_file(file_), expected) << read_file(file_);
  const std::string saved = read_file(file_);
  EXPECT_EQ(changed_line_count(text_, saved), 1) << saved;
  EXPECT_NE(saved.find("\n[2.500000 1.000000]\n"), std::string::npos) << saved;
}

}  // namespace
}  // namespace sweep
