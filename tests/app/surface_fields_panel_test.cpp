// The Edit panel's surface clauses, drawn by the real panel code in a headless ImGui context (no
// window, no GL) and clicked through ImGui's input: each checkbox shows its own clause and a
// click switches exactly that clause, as one undoable edit.
#include "app/viewer/panels/panels.hpp"
#include "headless_imgui.hpp"
#include "io/swp/read.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using sweep::test::HeadlessImGui;
using sweep::viewer::ViewerState;

/// Draws the surface fields of object `index`, then clicks the checkbox marked `name`.
void click(HeadlessImGui& imgui, ViewerState& s, int index, const std::string& name) {
  const auto draw = [index](ViewerState& state) { sweep::viewer::panels::surface_fields(state, index); };
  const glm::vec2 at = imgui.position(s, draw, name);
  ASSERT_GE(at.x, 0.0f) << "no checkbox " << name;
  imgui.drag(s, draw, at, at);
}

const char* const kLoopCage =
    "mesh tet 4 4\n[0 0 0]\n[1 0 0]\n[0 1 0]\n[0 0 1]\n[0 2 1]\n[0 1 3]\n[0 3 2]\n[1 2 3]\n"
    "subd smooth 1 tet loop smooth-boundary\n";

}  // namespace

TEST(SurfaceFieldsPanel, TheLoopCheckboxShowsTheSubdsLoopAndClearsIt) {
  HeadlessImGui imgui;
  ViewerState s;
  s.session.load(sweep::io::parse_swp(kLoopCage, "loop.swp"), "loop.swp");
  click(imgui, s, 1, "loop");
  const sweep::Object& subd = s.doc().objects[1];
  EXPECT_FALSE(subd.as<sweep::SubdivisionSurface>().loop)
      << "the checkbox showed loop unchecked, so a click could not clear it";
  EXPECT_TRUE(subd.as<sweep::SubdivisionSurface>().smooth_boundary);
  EXPECT_TRUE(s.session.can_undo());
  EXPECT_EQ(s.session.undo_label(), "clear loop");
}

TEST(SurfaceFieldsPanel, TheSmoothBoundaryCheckboxClearsOnlyItsClause) {
  HeadlessImGui imgui;
  ViewerState s;
  s.session.load(sweep::io::parse_swp(kLoopCage, "loop.swp"), "loop.swp");
  click(imgui, s, 1, "smooth-boundary");
  const sweep::Object& subd = s.doc().objects[1];
  EXPECT_FALSE(subd.as<sweep::SubdivisionSurface>().smooth_boundary);
  EXPECT_TRUE(subd.as<sweep::SubdivisionSurface>().loop);
}

TEST(SurfaceFieldsPanel, TheCapsCheckboxSwitchesCaps) {
  HeadlessImGui imgui;
  ViewerState s;
  s.session.load(sweep::io::parse_swp("circ c 8 1\nsrev r 8 c\n", "caps.swp"), "caps.swp");
  click(imgui, s, 1, "caps");
  EXPECT_TRUE(s.doc().objects[1].as<sweep::CapsPart>().caps);
  click(imgui, s, 1, "caps");
  EXPECT_FALSE(s.doc().objects[1].as<sweep::CapsPart>().caps);
}

namespace {

/// A surface's numbers typed into: a generalized cylinder's twist, a subd's level.
class SurfaceFieldTyping : public sweep::test::FieldTyping {
 protected:
  void show(const std::string& text, int index) {
    s.session.load(sweep::io::parse_swp(text, "s.swp"), "s.swp");
    draw = [index](ViewerState& state) { sweep::viewer::panels::surface_fields(state, index); };
  }
};

TEST_F(SurfaceFieldTyping, TypedTwistAppliesOnEnterAsOneUndoableEdit) {
  show("circ ring 12 0.5\ncirc path 24 3\ngcyl tube ring path\n", 2);
  type_into("twist", "1080");
  EXPECT_EQ(s.doc().objects[2].as<sweep::CylinderSurface>().twist, 1080.0) << "beyond the slider's 720";
  EXPECT_EQ(s.session.undo_label(), "set twist");
  EXPECT_EQ(undo_steps(), 1);
  type_into("twist", "a lot");
  EXPECT_EQ(s.error, "expected a number (twist degrees), found 'a lot'");
  type_into("twist", "90", ImGuiKey_Escape);
  EXPECT_EQ(s.doc().objects[2].as<sweep::CylinderSurface>().twist, 1080.0);
  EXPECT_EQ(undo_steps(), 1);
}

TEST_F(SurfaceFieldTyping, TypedLevelAppliesOnEnterAndRefusesTooDeep) {
  show(kLoopCage, 1);
  type_into("level", "2");
  EXPECT_EQ(s.doc().objects[1].as<sweep::SubdivisionSurface>().levels, 2);
  EXPECT_EQ(s.session.undo_label(), "set subdivision level");
  type_into("level", "99");
  EXPECT_EQ(s.doc().objects[1].as<sweep::SubdivisionSurface>().levels, 2);
  EXPECT_NE(s.error, "");
  type_into("level", "1.5");
  EXPECT_EQ(s.error, "expected a whole number (subdivision level), found '1.5'");
  EXPECT_EQ(undo_steps(), 1);
}

}  // namespace
