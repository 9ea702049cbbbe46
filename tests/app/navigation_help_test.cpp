// Finding one's way in the viewer: F frames the selection and Home everything (centred in the
// part the panels leave free, keeping the orientation), the status bar's line, and the Help
// window built from the command table.
#include "app/viewer/actions.hpp"
#include "app/viewer/command_bindings.hpp"
#include "app/viewer/panels/panels.hpp"
#include "app/viewer/viewer_state.hpp"
#include "headless_imgui.hpp"
#include "io/swp/read.hpp"

#include <gtest/gtest.h>
#include <imgui_internal.h>  // FindWindowByName

#include <glm/geometric.hpp>

#include <algorithm>
#include <string_view>

namespace {

using sweep::viewer::ViewerState;

/// Two circles of radius 1, one at the origin, one ten units along x (a bsp2 far away: control points).
void load_two_circles(ViewerState& s) {
  s.layout = sweep::editor::compute_layout({1280, 800}, {1280, 800}, 1.0f, true);
  s.session.load(sweep::io::parse_swp("circ near 24 1\n\nbsp2 far 8 4\n[9 -1]\n[11 -1]\n[11 1]\n[9 1]\n", "two.swp"),
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
  using Tone = sweep::viewer::panels::StatusLine::Tone;
  ViewerState s;
  const auto line = [&s] { return sweep::viewer::panels::status_line(s); };
  EXPECT_EQ(line().text, "") << "nothing yet: the bar says Ready";
  s.status = "saved /tmp/a.swp";
  EXPECT_EQ(line().text, "saved /tmp/a.swp");
  EXPECT_EQ(line().tone, Tone::Plain);
  EXPECT_EQ(line().more, "");
  s.status = "wrote /tmp/a_vase.obj\nwrote /tmp/a_vase.mtl\nwrote /tmp/a_vase_wood.png";
  EXPECT_EQ(line().text, "wrote /tmp/a_vase.obj");
  EXPECT_EQ(line().more, "(and 2 more: point here to see them)");
  EXPECT_EQ(line().tone, Tone::Plain);
  s.error = "a.swp:3:7: expected a number, found 'x'";
  EXPECT_EQ(line().text, "a.swp:3:7: expected a number, found 'x'") << "an error keeps its file:line:column";
  EXPECT_EQ(line().more, "");
  EXPECT_EQ(line().tone, Tone::Error);
  s.error += "\nwarning: another";
  EXPECT_EQ(line().text, "a.swp:3:7: expected a number, found 'x'");
  EXPECT_EQ(line().more, "(more in the Error panel)");
  EXPECT_EQ(line().tone, Tone::Error);
}

// A line wider than the bar loses its middle: the start (file:line:column) and the end (the file
// written) stay.
TEST(StatusBar, ALongLineLosesItsMiddle) {
  const auto measure = [](std::string_view text) { return 7.0f * float(text.size()); };  // a monospaced font
  using sweep::viewer::panels::elide_middle;
  EXPECT_EQ(elide_middle("saved /tmp/a.swp", 700.0f, measure), "saved /tmp/a.swp");
  const std::string error = "/home/me/models/vase.swp:12:5: expected a number after 'C' in path data, found 'x'";
  const std::string cut = elide_middle(error, 7.0f * 40.0f, measure);
  EXPECT_EQ(cut.size(), 40u);
  EXPECT_EQ(cut, "/home/me/models/va...ath data, found 'x'");
  EXPECT_EQ(elide_middle(error, 7.0f * 3.0f, measure), "...");
  // Never inside a UTF-8 character: "é" is two bytes.
  const std::string accented = "wrote /tmp/élan/émail/vase_hull.stl";
  for (float width = 21.0f; width < 7.0f * float(accented.size()); width += 7.0f) {
    const std::string shown = elide_middle(accented, width, measure);
    EXPECT_LE(7.0f * float(shown.size()), width);
    for (std::size_t i = 0; i < shown.size(); ++i) {
      const auto byte = static_cast<unsigned char>(shown[i]);
      if (byte == 0xC3) {
        ASSERT_LT(i + 1, shown.size());
        EXPECT_EQ(static_cast<unsigned char>(shown[i + 1]) & 0xC0u, 0x80u) << shown;
        ++i;  // its second byte
      } else {
        EXPECT_NE(byte & 0xC0u, 0x80u) << "a lone continuation byte at " << i << " in " << shown;
      }
    }
  }
}

// Issue 47, item 5: an STL export of a surface that is not closed wrote its file and warned, but
// the bar showed "wrote ..." and hid the warning behind "(and 1 more: point here ...)".
TEST(StatusBar, AWarningIsTheLineShownAndShownAsAWarning) {
  using Tone = sweep::viewer::panels::StatusLine::Tone;
  ViewerState s;
  const std::string warning =
      "birail.swp:26:1: warning: surface 'hull' is open: 1 hole (100 boundary edges); a printer needs a closed solid";
  s.status = "wrote /tmp/b_deck.stl (8 vertices, 12 triangles)\nwrote /tmp/b_hull.stl (400 vertices, 800 triangles)\n" +
             warning;
  EXPECT_EQ(sweep::viewer::panels::status_line(s).text, warning);
  EXPECT_EQ(sweep::viewer::panels::status_line(s).more, "(and 2 more: point here to see them)");
  EXPECT_EQ(sweep::viewer::panels::status_line(s).tone, Tone::Warning);
  s.status = warning;
  EXPECT_EQ(sweep::viewer::panels::status_line(s).text, warning);
  EXPECT_EQ(sweep::viewer::panels::status_line(s).tone, Tone::Warning);
  // The reader's warnings (an image not found) go to the Error panel; the bar shows them as warnings.
  s.error = "warning: a.swp:2:20: texture 'wood.png' not found; drawn as a magenta checker";
  EXPECT_EQ(sweep::viewer::panels::status_line(s).text, s.error);
  EXPECT_EQ(sweep::viewer::panels::status_line(s).tone, Tone::Warning);
}

// Issue 47, item 9: the Help window listed "Open" beside "Open...", in the table's order.
TEST(HelpWindow, ListsEveryCommandOnceWithAllItsKeysInTheMenusOrderAndTheMouse) {
  sweep::editor::CommandTable commands;
  const auto rows = sweep::viewer::panels::help_rows(commands);
  ASSERT_EQ(rows.size(), commands.commands().size());
  for (const sweep::editor::Command& command : commands.commands()) {
    const auto listed = std::count_if(rows.begin(), rows.end(), [&](const auto& r) { return r.does == command.label; });
    EXPECT_EQ(listed, 1) << command.label;
    const auto row = std::find_if(rows.begin(), rows.end(), [&](const auto& r) { return r.does == command.label; });
    ASSERT_NE(row, rows.end());
    EXPECT_EQ(row->keys, command.shortcuts.empty() ? "-" : commands.all_shortcuts_label(command.id));
  }
  for (const auto& row : rows) {
    EXPECT_EQ(std::count_if(rows.begin(), rows.end(), [&](const auto& r) { return r.does == row.does; }), 1)
        << "two commands are both called " << row.does;
  }
  // As the menus list them: File (New first, Quit last), Edit, View, Help.
  const auto at = [&rows](std::string_view does) {
    return std::find_if(rows.begin(), rows.end(), [&](const auto& r) { return r.does == does; }) - rows.begin();
  };
  EXPECT_EQ(rows.front().does, "New");
  EXPECT_LT(at("Export OBJ"), at("Export STL"));
  EXPECT_EQ(at("Export STL") + 1, at("Export glb"));
  EXPECT_LT(at("Quit"), at("Undo"));
  EXPECT_LT(at("Undo"), at("Front view"));
  EXPECT_EQ(rows.back().does, "Help: every command and key");
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
  EXPECT_GT(help->ContentSize.y, 15.0f * float(commands.commands().size())) << "a row per command";
  // Taller than the room: as tall as the room above the status bar, and it scrolls.
  EXPECT_LE(help->Pos.y + help->Size.y, ImGui::GetIO().DisplaySize.y - s.layout.status_height);
  EXPECT_GT(help->ScrollMax.y, 0.0f) << "the rest scrolls";
  const ImRect close = help->TitleBarRect();
  const ImVec2 button(close.Max.x - help->TitleBarHeight() * 0.5f, close.GetCenter().y);
  imgui.frame(s, draw, sweep::test::pointer(button, false));
  imgui.frame(s, draw, sweep::test::pointer(button, true));
  imgui.frame(s, draw, sweep::test::pointer(button, false));
  EXPECT_FALSE(s.show_help) << "the title bar's close button";
}

}  // namespace
