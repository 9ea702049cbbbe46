// Finding one's way in the viewer: F frames the selection and Home everything (centred in the
// part the panels leave free, keeping the orientation), the status bar's line, and the Help
// window built from the command table.
#include "app/viewer/actions.hpp"
#include "app/viewer/command_bindings.hpp"
#include "app/viewer/panels/panels.hpp"
#include "app/viewer/viewer_state.hpp"
#include "headless_imgui.hpp"
#include "io/swp_parser.hpp"

#include <gtest/gtest.h>
#include <imgui_internal.h>  // FindWindowByName

#include <glm/geometric.hpp>

#include <algorithm>

namespace {

using sweep::viewer::ViewerState;

/// Two circles of radius 1, one at the origin, one ten units along x (a bsp2 far away: control points).
void load_two_circles(ViewerState& s) {
  s.layout = sweep::editor::compute_layout({1280, 800}, {1280, 800}, 1.0f, true);
  s.session.load(sweep::parse_swp("circ near 24 1\n\nbsp2 far 8 4\n[9 -1]\n[11 -1]\n[11 1]\n[9 1]\n", "two.swp"),
                 "two.swp");
  sweep::viewer::reset_camera(s);
}

TEST(Framing, FFramesTheSelectedObjectWithItsControlPointsAndKeepsTheOrientation) {
  ViewerState s;
  load_two_circles(s);
  s.camera.arcball_rotate({0.0, 0.0}, {0.3, 0.1});
  const glm::dquat turned = s.camera.orientation;
  const double whole = s.camera.distance;
  ASSERT_TRUE(sweep::viewer::select_by_name(s, "far"));
  sweep::viewer::frame_selection(s);
  EXPECT_NEAR(glm::length(s.camera.target - glm::dvec3(10.0, 0.0, 0.0)), 0.0, 1e-9) << "the control points' centre";
  EXPECT_LT(s.camera.distance, 0.5 * whole) << "closer than the whole scene's framing";
  EXPECT_EQ(s.camera.orientation, turned);
  ASSERT_TRUE(sweep::viewer::select_by_name(s, "near"));
  sweep::viewer::frame_selection(s);
  EXPECT_NEAR(glm::length(s.camera.target), 0.0, 1e-9);
}

TEST(Framing, FWithNothingSelectedAndHomeFrameEveryVisibleObject) {
  ViewerState s;
  load_two_circles(s);
  const glm::dvec3 all = s.camera.target;
  s.selection = {};
  sweep::viewer::frame_selection(s);
  EXPECT_NEAR(glm::length(s.camera.target - all), 0.0, 1e-9);
  s.views.set_visible(s.doc().objects[1].id, false);
  sweep::viewer::frame_all(s);
  EXPECT_NEAR(glm::length(s.camera.target), 0.0, 1e-9) << "the hidden curve is left out";
}

TEST(Framing, TheKeysRunThem) {
  ViewerState s;
  load_two_circles(s);
  sweep::editor::CommandTable commands;
  sweep::viewer::bind_commands(commands, s);
  ASSERT_TRUE(sweep::viewer::select_by_name(s, "far"));
  EXPECT_TRUE(commands.press({sweep::editor::Key::F}));
  EXPECT_NEAR(s.camera.target.x, 10.0, 1e-9);
  EXPECT_TRUE(commands.press({sweep::editor::Key::Home}));
  EXPECT_NEAR(s.camera.target.x, sweep::render::scene_bounds(s.session.scene()).center().x, 1e-9) << "everything";
  EXPECT_GT(s.camera.target.x, 4.0);
  EXPECT_TRUE(commands.press({sweep::editor::Key::F1}));
  EXPECT_TRUE(s.show_help);
}

TEST(StatusBar, ShowsTheLastMessageOrTheErrorsFirstLine) {
  ViewerState s;
  s.status = "saved /tmp/a.swp";
  EXPECT_EQ(sweep::viewer::panels::status_line(s), "saved /tmp/a.swp");
  s.status = "wrote /tmp/a_vase.obj\nwrote /tmp/a_vase.mtl\nwrote /tmp/a_vase_wood.png";
  EXPECT_EQ(sweep::viewer::panels::status_line(s), "wrote /tmp/a_vase.obj  (and 2 more: point here to see them)");
  s.error = "a.swp:3:7: expected a number, found 'x'";
  EXPECT_EQ(sweep::viewer::panels::status_line(s), "a.swp:3:7: expected a number, found 'x'");
  s.error += "\nwarning: another";
  EXPECT_EQ(sweep::viewer::panels::status_line(s),
            "a.swp:3:7: expected a number, found 'x'  (more in the Error panel)");
}

TEST(HelpWindow, ListsEveryCommandWithAllItsKeysAndTheMouse) {
  sweep::editor::CommandTable commands;
  const auto rows = sweep::viewer::panels::help_rows(commands);
  ASSERT_EQ(rows.size(), commands.commands().size());
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const sweep::editor::Command& command = commands.commands()[i];
    EXPECT_EQ(rows[i].does, command.label);
    EXPECT_EQ(rows[i].keys, command.shortcuts.empty() ? "-" : commands.all_shortcuts_label(command.id));
  }
  const auto redo = std::find_if(rows.begin(), rows.end(), [](const auto& r) { return r.does == "Redo"; });
  ASSERT_NE(redo, rows.end());
  EXPECT_EQ(redo->keys, "Ctrl+Shift+Z / Ctrl+Y");
  const auto mouse = sweep::viewer::panels::mouse_help_rows();
  EXPECT_TRUE(std::any_of(mouse.begin(), mouse.end(), [](const auto& r) { return r.keys == "middle drag"; }));
}

TEST(HelpWindow, OpensWhenAskedAndItsCloseButtonClosesIt) {
  sweep::test::HeadlessImGui imgui;
  ViewerState s;
  sweep::editor::CommandTable commands;
  const auto draw = [&](ViewerState& state) { sweep::viewer::panels::help_window(state, commands); };
  imgui.frame(s, draw);
  EXPECT_EQ(ImGui::FindWindowByName("Help"), nullptr) << "not drawn until asked";
  s.show_help = true;
  imgui.frame(s, draw);
  imgui.frame(s, draw);
  const ImGuiWindow* help = ImGui::FindWindowByName("Help");
  ASSERT_NE(help, nullptr);
  EXPECT_TRUE(help->Active);
  EXPECT_GT(help->ContentSize.y, 20.0f * float(commands.commands().size())) << "a row per command";
  const ImRect close = help->TitleBarRect();
  const ImVec2 button(close.Max.x - help->TitleBarHeight() * 0.5f, close.GetCenter().y);
  imgui.frame(s, draw, sweep::test::pointer(button, false));
  imgui.frame(s, draw, sweep::test::pointer(button, true));
  imgui.frame(s, draw, sweep::test::pointer(button, false));
  EXPECT_FALSE(s.show_help) << "the title bar's close button";
}

}  // namespace
