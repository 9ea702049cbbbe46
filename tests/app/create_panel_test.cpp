// The Create panel drawn by the real panel code in a headless ImGui context (issue 47, item 5):
// what it adds is said in the status bar, and a new 2D curve is the profile it offers next.
#include "app/viewer/panels/panels.hpp"
#include "headless_imgui.hpp"
#include "io/swp/read.hpp"

#include <gtest/gtest.h>

namespace {

using sweep::test::HeadlessImGui;
using sweep::viewer::ViewerState;

class CreatePanel : public ::testing::Test {
 protected:
  void SetUp() override {
    s.session.load(sweep::io::parse_swp("circ ring 12 0.5\n", "ring.swp"), "ring.swp");
    draw = [](ViewerState& state) { sweep::viewer::panels::create_panel(state); };
  }
  /// Clicks the button marked `name`.
  void click(const std::string& name) {
    const glm::vec2 at = imgui.position(s, draw, name);
    ASSERT_GE(at.x, 0.0f) << "no button " << name << " (is the panel open?)";
    imgui.drag(s, draw, at, at);
  }

  HeadlessImGui imgui;
  ViewerState s;
  HeadlessImGui::Draw draw;
};

TEST_F(CreatePanel, IsOpenFromTheStart) {
  EXPECT_GE(imgui.position(s, draw, "add-curve").x, 0.0f);
  EXPECT_GE(imgui.position(s, draw, "add-surface").x, 0.0f);
}

TEST_F(CreatePanel, AddingACurveSaysSoAndOffersItAsTheNextProfile) {
  click("add-curve");
  ASSERT_EQ(s.doc().objects.size(), 2u);
  EXPECT_EQ(s.doc().objects[1].name, "curve");
  EXPECT_EQ(s.status, "added bsp2 'curve': drag its points in the view");
  EXPECT_EQ(s.error, "");
  EXPECT_EQ(s.selected(), 1);
  EXPECT_EQ(s.fields.profile_choice, 1) << "the new 2D curve, not the ring";

  click("add-surface");
  ASSERT_EQ(s.doc().objects.size(), 3u);
  EXPECT_EQ(s.status, "added srev 'revolution' turning 'curve' in 24 steps");
  EXPECT_EQ(s.selected(), 2);
}

TEST_F(CreatePanel, ACurveWithoutPointsPointsToItsNumbers) {
  s.fields.template_choice = 5;  // circle
  click("add-curve");
  // Sized to the ring (radius 0.5): half its size, a nice factor of the template's radius 1.
  EXPECT_EQ(s.status, "added circ 'circle' (scaled by 0.2): its numbers are in the Edit panel");
  EXPECT_EQ(s.doc().objects[1].as<sweep::CircleCurve>().radius, 0.2);
  EXPECT_TRUE(s.fields.frame_added) << "the main window frames the view on it";
}

TEST_F(CreatePanel, ARefusedAdditionSaysWhyAndNothingElse) {
  s.fields.curve_name.set("ring");  // taken
  s.status = "opened ring.swp";
  click("add-curve");
  EXPECT_EQ(s.doc().objects.size(), 1u);
  EXPECT_NE(s.error, "");
  EXPECT_EQ(s.status, "opened ring.swp");
}

}  // namespace
