// The Material panel drawn by the real panel code in a headless ImGui context and dragged
// through ImGui's input: each field of a material's look keeps the value it was dragged to, as
// one undoable edit.
#include "app/viewer/actions.hpp"
#include "app/viewer/panels/panels.hpp"
#include "headless_imgui.hpp"
#include "io/swp/read.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <filesystem>
#include <string>

namespace {

using sweep::MaterialLook;
using sweep::test::HeadlessImGui;
using sweep::viewer::ViewerState;

const char* const kTiled =
    "material tiles checker 4 shininess 32\n"
    "circ ring 12 0.5\n"
    "circ path 24 3\n"
    "gcyl tiled ring path material tiles\n";

void draw_material_panel(ViewerState& s) {
  ImGui::SetNextItemOpen(true);
  sweep::viewer::panels::material_panel(s);
}

/// The look of the material, with the material selected.
class MaterialPanel : public ::testing::Test {
 protected:
  void SetUp() override {
    s.session.load(sweep::io::parse_swp(kTiled, "tiles.swp"), "tiles.swp");
    s.selection.select(s.session.id_of(0));
  }
  const MaterialLook& look() const { return s.doc().objects[0].as<MaterialLook>(); }
  /// Drags the field marked `name` 150 units to the right of where it starts.
  void drag_field(const std::string& name) {
    const glm::vec2 at = imgui.position(s, draw_material_panel, name);
    ASSERT_GE(at.x, 0.0f) << "no field " << name;
    imgui.drag(s, draw_material_panel, at, at + glm::vec2(150.0f, 0.0f));
  }

  HeadlessImGui imgui;
  ViewerState s;
};

TEST_F(MaterialPanel, DraggingCheckerCellsKeepsTheNewCountAsOneUndoableEdit) {
  drag_field("checker");
  EXPECT_NE(look().checker, 4) << "the field snapped back to the old count";
  EXPECT_GT(look().checker, 0);
  EXPECT_TRUE(s.session.dirty());
  ASSERT_TRUE(s.session.can_undo());
  EXPECT_EQ(s.session.undo_label(), "set checker");
  s.session.undo();
  EXPECT_EQ(look().checker, 4);
}

TEST_F(MaterialPanel, DraggingShininessKeepsTheNewValue) {
  drag_field("shininess");
  EXPECT_NE(look().shininess, 32.0) << "the field snapped back";
  ASSERT_TRUE(s.session.can_undo());
  EXPECT_EQ(s.session.undo_label(), "set shininess");
}

TEST_F(MaterialPanel, DraggingBumpHeightKeepsTheNewValue) {
  drag_field("bump height");
  EXPECT_GT(look().bump_height, 0.0) << "the field snapped back";
  ASSERT_TRUE(s.session.can_undo());
  EXPECT_EQ(s.session.undo_label(), "set bump height");
}

TEST_F(MaterialPanel, DraggingTheRedOfTheColourKeepsTheNewColour) {
  drag_field("red");
  EXPECT_GT(look().color.r, 0.7) << "the red snapped back to 0.62";
  EXPECT_EQ(look().color.g, 0.68) << "green was not dragged: no float noise in it";
  EXPECT_EQ(look().color.b, 0.80);
  ASSERT_TRUE(s.session.can_undo());
  EXPECT_EQ(s.session.undo_label(), "set colour");
}

/// The material selected, its fields typed into.
class MaterialTyping : public sweep::test::FieldTyping {
 protected:
  void SetUp() override {
    s.session.load(sweep::io::parse_swp(kTiled, "tiles.swp"), "tiles.swp");
    s.selection.select(s.session.id_of(0));
    draw = draw_material_panel;
  }
  const MaterialLook& look() const { return s.doc().objects[0].as<MaterialLook>(); }
};

TEST_F(MaterialTyping, TypedShininessAppliesOnEnterAsOneUndoableEdit) {
  type_into("shininess", "250");
  EXPECT_EQ(look().shininess, 250.0);
  EXPECT_EQ(s.error, "");
  EXPECT_EQ(s.session.undo_label(), "set shininess");
  EXPECT_EQ(undo_steps(), 1);
  s.session.undo();
  EXPECT_EQ(look().shininess, 32.0);
}

TEST_F(MaterialTyping, ARefusedShininessChangesNothingAndSaysWhy) {
  type_into("shininess", "5000");
  EXPECT_EQ(look().shininess, 32.0);
  EXPECT_FALSE(s.session.can_undo());
  EXPECT_NE(s.error.find("the shininess must be from 1 to 1000"), std::string::npos) << s.error;
  type_into("shininess", "shiny");
  EXPECT_EQ(s.error, "expected a number (shininess), found 'shiny'");
  EXPECT_FALSE(s.session.dirty());
}

TEST_F(MaterialTyping, ATypedColourComponentAppliesOnEnterExactlyAndTheOthersKeepTheirs) {
  type_into("green", "0.25");
  EXPECT_EQ(look().color, glm::dvec3(0.62, 0.25, 0.80)) << "exactly as typed, and no rounding in red and blue";
  EXPECT_EQ(s.session.undo_label(), "set colour");
  EXPECT_EQ(undo_steps(), 1);
  type_into("blue", "1.5");
  EXPECT_EQ(look().color.b, 0.80);
  EXPECT_NE(s.error.find("colour components must be from 0 to 1"), std::string::npos) << s.error;
  type_into("red", "dark");
  EXPECT_EQ(s.error, "expected a number (red of the colour), found 'dark'");
  EXPECT_EQ(undo_steps(), 1);
}

TEST_F(MaterialTyping, TypedCheckerCellsApplyOnEnterEvenBeyondTheSlider) {
  type_into("checker", "12");
  EXPECT_EQ(look().checker, 12);
  EXPECT_EQ(s.session.undo_label(), "set checker");
  type_into("checker", "100");
  EXPECT_EQ(look().checker, 100) << "the file takes up to 256 cells";
  EXPECT_EQ(undo_steps(), 2);
}

TEST_F(MaterialTyping, CheckerCellsRefuseLettersAndFractions) {
  type_into("checker", "abc");
  EXPECT_EQ(s.error, "expected a whole number (checker cells), found 'abc'");
  type_into("checker", "2.5");
  EXPECT_EQ(s.error, "expected a whole number (checker cells), found '2.5'");
  EXPECT_EQ(look().checker, 4);
  EXPECT_FALSE(s.session.can_undo());
}

TEST_F(MaterialTyping, TypedBumpHeightAppliesOnEnterAndEscapeKeepsIt) {
  type_into("bump height", "0.125");
  EXPECT_EQ(look().bump_height, 0.125);
  EXPECT_EQ(s.session.undo_label(), "set bump height");
  type_into("bump height", "0.5", ImGuiKey_Escape);
  EXPECT_EQ(look().bump_height, 0.125);
  EXPECT_EQ(undo_steps(), 1);
}

/// A file copied without its texture, opened as the viewer opens one, its material selected.
class MissingTexture : public sweep::test::FieldTyping {
 protected:
  void SetUp() override {
    sweep::test::write_text(file, text);
    ASSERT_TRUE(sweep::viewer::open_file(s, file.string()));
    s.selection.select(s.session.id_of(0));
    draw = draw_material_panel;
  }
  const MaterialLook& look() const { return s.doc().objects[0].as<MaterialLook>(); }

  sweep::test::ScratchFolder folder{"sweep-missing-texture"};
  std::filesystem::path file = folder.path() / "lost.swp";
  const std::string shapes = "circ ring 12 0.5\ncirc path 24 3\ngcyl tiled ring path material wood\n";
  const std::string text = "material wood texture wood.png shininess 32\n" + shapes;
};

TEST_F(MissingTexture, TheFileOpensWithTheWarningInTheErrorPanelAndItsLookStillEdits) {
  EXPECT_EQ(s.error, file.string() + ":1:23: warning: texture 'wood.png' not found; drawn as a magenta checker");
  ASSERT_EQ(s.doc().objects.size(), 4u);
  EXPECT_EQ(look().texture, "wood.png");
  // The missing image does not stop an edit of the colour or shininess...
  s.error.clear();
  type_into("shininess", "250");
  EXPECT_EQ(look().shininess, 250.0);
  EXPECT_EQ(s.error, "");
  // ...and saving keeps the texture clause as written.
  ASSERT_TRUE(sweep::viewer::save_to(s, file.string())) << s.error;
  EXPECT_EQ(sweep::test::read_file(file), "material wood texture wood.png shininess 250\n" + shapes);
}

TEST_F(MaterialTyping, ShininessAppliesWhenTheFieldLosesFocus) {
  type_into("shininess", "64", -1);
  imgui.drag(s, draw, glm::vec2(590.0f, 570.0f), glm::vec2(590.0f, 570.0f));  // a click elsewhere
  EXPECT_EQ(look().shininess, 64.0);
  EXPECT_EQ(undo_steps(), 1);
}

}  // namespace
