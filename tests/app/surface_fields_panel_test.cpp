// The Edit panel's surface clauses, drawn by the real panel code in a headless ImGui context (no
// window, no GL) and clicked through ImGui's input: each checkbox shows its own clause and a
// click switches exactly that clause, as one undoable edit.
#include "app/viewer/item_positions.hpp"
#include "app/viewer/panels/panels.hpp"
#include "app/viewer/viewer_state.hpp"
#include "io/swp_parser.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <string>

namespace {

using sweep::viewer::ItemPositions;
using sweep::viewer::ViewerState;

/// An ImGui context of its own, with a font atlas built and nothing drawn.
class HeadlessImGui {
 public:
  HeadlessImGui() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(800.0f, 600.0f);
    io.DeltaTime = 1.0f / 60.0f;
    io.IniFilename = nullptr;
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  }
  ~HeadlessImGui() { ImGui::DestroyContext(); }
  HeadlessImGui(const HeadlessImGui&) = delete;
  HeadlessImGui& operator=(const HeadlessImGui&) = delete;

  /// One frame of the panel's surface fields for object `index`, the mouse at `mouse`.
  void frame(ViewerState& s, int index, ImVec2 mouse, bool pressed) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = mouse;
    io.MouseDown[0] = pressed;
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(600.0f, 500.0f));
    ImGui::Begin("edit");
    sweep::viewer::panels::surface_fields(s, index);
    ImGui::End();
    ImGui::Render();
  }

  /// Draws the panel, then clicks the checkbox marked `name` (press, release).
  void click(ViewerState& s, int index, const std::string& name) {
    ItemPositions positions;
    s.item_positions = &positions;
    frame(s, index, ImVec2(-1.0f, -1.0f), false);
    const glm::vec2 at = positions.position(name, glm::vec2(-1.0f));
    s.item_positions = nullptr;
    ASSERT_GE(at.x, 0.0f) << "no checkbox " << name;
    frame(s, index, ImVec2(at.x, at.y), false);
    frame(s, index, ImVec2(at.x, at.y), true);
    frame(s, index, ImVec2(at.x, at.y), false);
  }
};

const char* const kLoopCage =
    "mesh tet 4 4\n[0 0 0]\n[1 0 0]\n[0 1 0]\n[0 0 1]\n[0 2 1]\n[0 1 3]\n[0 3 2]\n[1 2 3]\n"
    "subd smooth 1 tet loop smooth-boundary\n";

}  // namespace

TEST(SurfaceFieldsPanel, TheLoopCheckboxShowsTheSubdsLoopAndClearsIt) {
  HeadlessImGui imgui;
  ViewerState s;
  s.session.load(sweep::parse_swp(kLoopCage, "loop.swp"), "loop.swp");
  imgui.click(s, 1, "loop");
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
  s.session.load(sweep::parse_swp(kLoopCage, "loop.swp"), "loop.swp");
  imgui.click(s, 1, "smooth-boundary");
  const sweep::Object& subd = s.doc().objects[1];
  EXPECT_FALSE(subd.as<sweep::SubdivisionSurface>().smooth_boundary);
  EXPECT_TRUE(subd.as<sweep::SubdivisionSurface>().loop);
}

TEST(SurfaceFieldsPanel, TheCapsCheckboxSwitchesCaps) {
  HeadlessImGui imgui;
  ViewerState s;
  s.session.load(sweep::parse_swp("circ c 8 1\nsrev r 8 c\n", "caps.swp"), "caps.swp");
  imgui.click(s, 1, "caps");
  EXPECT_TRUE(s.doc().objects[1].as<sweep::CapsPart>().caps);
  imgui.click(s, 1, "caps");
  EXPECT_FALSE(s.doc().objects[1].as<sweep::CapsPart>().caps);
}
