// Typing a number into a field of the Edit panel's point table, drawn by the real panel code in
// a headless ImGui context: Ctrl+click types, and the number applies once, on Enter or when the
// field loses focus; nothing applies while it is typed, and a refused number changes nothing and
// says why.
#include "app/viewer/panels/number_field.hpp"
#include "app/viewer/command_bindings.hpp"
#include "app/viewer/panels/panels.hpp"
#include "headless_imgui.hpp"
#include "io/swp_parser.hpp"

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
    s.session.load(sweep::parse_swp("bsp2 profile 20 4\n[1 0]\n[1 1]\n[3 1]\n[3 0]\n", "p.swp"), "p.swp");
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
}

}  // namespace
