// Typing a number into a field of the Edit panel's point table, drawn by the real panel code in
// a headless ImGui context: Ctrl+click types, and the number applies once, on Enter or when the
// field loses focus; nothing applies while it is typed, and a refused number changes nothing and
// says why.
#include "app/viewer/panels/number_field.hpp"
#include "app/viewer/command_bindings.hpp"
#include "app/viewer/panels/panels.hpp"
#include "headless_imgui.hpp"
#include "io/swp/read.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <string>

namespace {

using sweep::test::HeadlessImGui;
using sweep::viewer::ViewerState;

class PointTableTyping : public ::testing::Test {
 protected:
  void SetUp() override {
    sweep::viewer::bind_commands(commands, s);
    s.session.load(sweep::io::parse_swp("bsp2 profile 20 4\n[1 0]\n[1 1]\n[3 1]\n[3 0]\n", "p.swp"), "p.swp");
    s.selection.select(s.session.id_of(0));
    draw = [this](ViewerState& state) { sweep::viewer::panels::point_table(state, commands, 0); };
  }
  double x1() const { return s.doc().objects[0].as<sweep::PointsPart>().points[1].x; }
  /// Ctrl+clicks the x of point 1, so it is typed in.
  void start_typing() {
    const glm::vec2 at = imgui.position(s, draw, "point 1 x");
    ASSERT_GE(at.x, 0.0f) << "no field for the x of point 1";
    imgui.drag(s, draw, at + glm::vec2(20.0f, 0.0f), at + glm::vec2(20.0f, 0.0f), true);
  }
  /// Types `text` into the field, checking after each character that nothing was applied.
  void type_checking_nothing_applies(const std::string& text) {
    for (char c : text) {
      imgui.type(s, draw, std::string(1, c));
      EXPECT_EQ(x1(), 1.0) << "applied while typing, after '" << c << "'";
      EXPECT_FALSE(s.session.dirty());
    }
  }

  HeadlessImGui imgui;
  ViewerState s;
  sweep::editor::CommandTable commands;
  HeadlessImGui::Draw draw;
};

TEST_F(PointTableTyping, ANumberAppliesOnEnterAsOneUndoableEdit) {
  start_typing();
  type_checking_nothing_applies("2.5");
  imgui.type(s, draw, "", ImGuiKey_Enter);
  EXPECT_EQ(x1(), 2.5);
  EXPECT_EQ(s.error, "");
  ASSERT_TRUE(s.session.can_undo());
  EXPECT_EQ(s.session.undo_label(), "move point");
  s.session.undo();
  EXPECT_EQ(x1(), 1.0);
  EXPECT_FALSE(s.session.can_undo()) << "one step";
}

TEST_F(PointTableTyping, ARefusedNumberChangesNothingAndSaysWhy) {
  start_typing();
  type_checking_nothing_applies("1e13");
  imgui.type(s, draw, "", ImGuiKey_Enter);
  EXPECT_EQ(x1(), 1.0) << "1e1 was applied on the way to 1e13";
  EXPECT_FALSE(s.session.dirty());
  EXPECT_FALSE(s.session.can_undo());
  EXPECT_EQ(s.error, "coordinate x = 1e+13 is out of range: coordinates must be from -1e12 to 1e12");
}

TEST_F(PointTableTyping, LettersAreRefusedWithAMessage) {
  start_typing();
  type_checking_nothing_applies("abc");
  imgui.type(s, draw, "", ImGuiKey_Enter);
  EXPECT_EQ(x1(), 1.0);
  EXPECT_FALSE(s.session.can_undo());
  EXPECT_EQ(s.error, "expected a number (x of point 1), found 'abc'");
}

TEST_F(PointTableTyping, ANumberAppliesWhenTheFieldLosesFocus) {
  start_typing();
  type_checking_nothing_applies("-4");
  imgui.drag(s, draw, glm::vec2(590.0f, 570.0f), glm::vec2(590.0f, 570.0f));  // a click elsewhere
  EXPECT_EQ(x1(), -4.0);
  EXPECT_TRUE(s.session.can_undo());
}

TEST_F(PointTableTyping, EscapeKeepsTheValue) {
  start_typing();
  type_checking_nothing_applies("7");
  imgui.type(s, draw, "", ImGuiKey_Escape);
  EXPECT_EQ(x1(), 1.0);
  EXPECT_FALSE(s.session.can_undo());
  EXPECT_EQ(s.error, "");
}

TEST_F(PointTableTyping, DraggingTheFieldStillMovesThePointAsOneStep) {
  const glm::vec2 at = imgui.position(s, draw, "point 1 x") + glm::vec2(20.0f, 0.0f);
  imgui.drag(s, draw, at, at + glm::vec2(40.0f, 0.0f));
  EXPECT_GT(x1(), 1.0);
  ASSERT_TRUE(s.session.can_undo());
  s.session.undo();
  EXPECT_EQ(x1(), 1.0);
  EXPECT_FALSE(s.session.can_undo());
}

/// The Edit panel (and the Display and Create panels) with a B-spline profile selected.
class EditPanelTyping : public sweep::test::FieldTyping {
 protected:
  void SetUp() override {
    sweep::viewer::bind_commands(commands, s);
    load("bsp2 profile 20 4\n[1 0]\n[1 1]\n[3 1]\n[3 0]\n");
    draw = [this](ViewerState& state) { sweep::viewer::panels::edit_panel(state, commands); };
  }
  void load(const std::string& text) {
    s.session.load(sweep::io::parse_swp(text, "p.swp"), "p.swp");
    s.selection.select(s.session.id_of(0));
  }
  int steps() const { return s.doc().objects[0].as<sweep::StepsPart>().steps; }

  sweep::editor::CommandTable commands;
};

TEST_F(EditPanelTyping, TypedStepsApplyOnEnterAsOneUndoableEdit) {
  type_into("STEPS", "37");
  EXPECT_EQ(steps(), 37);
  EXPECT_EQ(s.error, "");
  EXPECT_EQ(s.session.undo_label(), "set STEPS");
  EXPECT_EQ(undo_steps(), 1);
}

TEST_F(EditPanelTyping, TypedStepsBeyondTheSliderApply) {
  type_into("STEPS", "5000");
  EXPECT_EQ(steps(), 5000);
}

TEST_F(EditPanelTyping, StepsThatAreNotAWholeNumberAreRefusedWithAMessage) {
  type_into("STEPS", "2.5");
  EXPECT_EQ(steps(), 20);
  EXPECT_FALSE(s.session.can_undo());
  EXPECT_EQ(s.error, "expected a whole number (STEPS), found '2.5'");
  type_into("STEPS", "many");
  EXPECT_EQ(s.error, "expected a whole number (STEPS), found 'many'");
  type_into("STEPS", "0");
  EXPECT_EQ(steps(), 20);
  EXPECT_FALSE(s.session.can_undo());
  EXPECT_NE(s.error.find("STEPS must be from 1 to 100000, not 0"), std::string::npos) << s.error;
}

TEST_F(EditPanelTyping, EscapeKeepsTheSteps) {
  type_into("STEPS", "7", ImGuiKey_Escape);
  EXPECT_EQ(steps(), 20);
  EXPECT_FALSE(s.session.can_undo());
  EXPECT_EQ(s.error, "");
}

TEST_F(EditPanelTyping, DraggingTheStepsSliderIsOneStep) {
  const glm::vec2 at = imgui.position(s, draw, "STEPS");
  ASSERT_GE(at.x, 0.0f);
  imgui.drag(s, draw, at + glm::vec2(20.0f, 0.0f), at + glm::vec2(120.0f, 0.0f));
  EXPECT_NE(steps(), 20);
  EXPECT_EQ(undo_steps(), 1);
}

TEST_F(EditPanelTyping, ATypedToleranceAppliesOnEnterAndARefusedOneSaysWhy) {
  const glm::vec2 adaptive = imgui.position(s, draw, "adaptive");
  ASSERT_GE(adaptive.x, 0.0f);
  imgui.drag(s, draw, adaptive, adaptive);
  ASSERT_GT(s.session.evaluation().tolerance, 0.0) << "the Adaptive checkbox did not switch on";
  const double before = s.session.evaluation().tolerance;
  const auto tolerance = [this] { return s.session.evaluation().tolerance; };
  type_into("tolerance", "0.0125", ImGuiKey_Enter, tolerance);
  EXPECT_EQ(tolerance(), 0.0125);
  EXPECT_EQ(s.error, "");
  type_into("tolerance", "1e-30", ImGuiKey_Enter, tolerance);
  EXPECT_EQ(tolerance(), 0.0125);
  EXPECT_EQ(s.error.rfind("the tolerance must be from ", 0), 0u) << s.error;
  type_into("tolerance", "fine", ImGuiKey_Enter, tolerance);
  EXPECT_EQ(s.error, "expected a number (tolerance), found 'fine'");
  type_into("tolerance", "0.5", ImGuiKey_Escape, tolerance);
  EXPECT_EQ(tolerance(), 0.0125);
  EXPECT_NE(before, 0.0125);
}

TEST_F(EditPanelTyping, TheGridSizeAppliesOnEnterAndRefusesZero) {
  const auto grid = [this] { return s.snap_size; };
  type_into("grid", "0.1", ImGuiKey_Enter, grid);
  EXPECT_EQ(s.snap_size, 0.1);
  type_into("grid", "0", ImGuiKey_Enter, grid);
  EXPECT_EQ(s.snap_size, 0.1);
  EXPECT_EQ(s.error, "the grid size must be more than 0");
  type_into("grid", "x", ImGuiKey_Enter, grid);
  EXPECT_EQ(s.error, "expected a number (grid size), found 'x'");
  EXPECT_FALSE(s.session.dirty());
}

TEST_F(EditPanelTyping, SplitTAppliesOnEnterAndSplitsThere) {
  load("bez2 arc 8 4\n[0 0]\n[0 1]\n[1 1]\n[1 0]\n");
  const auto t = [this] { return s.fields.split_t; };
  type_into("split t", "0.25", ImGuiKey_Enter, t);
  EXPECT_EQ(s.fields.split_t, 0.25);
  type_into("split t", "1", ImGuiKey_Enter, t);
  EXPECT_EQ(s.fields.split_t, 0.25);
  EXPECT_EQ(s.error, "t must be between 0 and 1 (a point inside the piece)");
  EXPECT_FALSE(s.session.dirty());
}

TEST_F(EditPanelTyping, TheMitreLimitAppliesOnEnterAndRefusesLessThanOne) {
  draw = [this](ViewerState& state) {
    ImGui::SetNextItemOpen(true);  // closed until opened
    sweep::viewer::panels::display_panel(state, commands);
  };
  const auto mitre = [this] { return s.session.evaluation().mitre_limit; };
  type_into("mitre limit", "2.75", ImGuiKey_Enter, mitre);
  EXPECT_EQ(mitre(), 2.75);
  type_into("mitre limit", "0.5", ImGuiKey_Enter, mitre);
  EXPECT_EQ(mitre(), 2.75);
  EXPECT_EQ(s.error, "expected a mitre limit of at least 1, found 0.5");
  type_into("mitre limit", "12", ImGuiKey_Escape, mitre);
  EXPECT_EQ(mitre(), 2.75);
}

TEST_F(EditPanelTyping, CreatesCopiesApplyOnEnterAndRefuseZero) {
  draw = [](ViewerState& state) {
    ImGui::SetNextItemOpen(true);
    sweep::viewer::panels::create_panel(state);
  };
  const auto copies = [this] { return double(s.fields.surface_steps); };
  type_into("copies", "48", ImGuiKey_Enter, copies);
  EXPECT_EQ(s.fields.surface_steps, 48);
  type_into("copies", "0", ImGuiKey_Enter, copies);
  EXPECT_EQ(s.fields.surface_steps, 48);
  EXPECT_EQ(s.error, "STEPS must be from 1 to 100000, not 0");
  type_into("copies", "4.5", ImGuiKey_Enter, copies);
  EXPECT_EQ(s.error, "expected a whole number (copies), found '4.5'");
}

TEST(ParseTypedNumber, ReadsNumbersAndNamesTheRoleOtherwise) {
  double value = 0.0;
  std::string message;
  EXPECT_TRUE(sweep::viewer::panels::parse_typed_number(" +2.5e-3 ", "radius", value, message));
  EXPECT_EQ(value, 2.5e-3);
  EXPECT_FALSE(sweep::viewer::panels::parse_typed_number("1.5.2", "radius", value, message));
  EXPECT_EQ(message, "expected a number (radius), found '1.5.2'");
  EXPECT_FALSE(sweep::viewer::panels::parse_typed_number("", "radius", value, message));
  EXPECT_FALSE(sweep::viewer::panels::parse_typed_number("1e999", "radius", value, message));
  EXPECT_EQ(message, "expected a number (radius), found '1e999': out of range");
  EXPECT_TRUE(sweep::viewer::panels::parse_typed_number("12", "cells", value, message, true));
  EXPECT_EQ(value, 12.0);
  EXPECT_FALSE(sweep::viewer::panels::parse_typed_number("1.5", "cells", value, message, true));
  EXPECT_EQ(message, "expected a whole number (cells), found '1.5'");
  EXPECT_FALSE(sweep::viewer::panels::parse_typed_number("1e10", "cells", value, message, true));
  EXPECT_EQ(message, "expected a whole number (cells), found '1e10': out of range");
}

}  // namespace
