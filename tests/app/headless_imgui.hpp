#pragma once
// A headless ImGui context for panel tests: real panel code drawn with no window and no GL,
// driven through ImGui's own input (mouse, keys, typed characters), and the widgets found where
// the panels marked them (ItemPositions).
#include "app/viewer/item_positions.hpp"
#include "app/viewer/viewer_state.hpp"
#include "model/document.hpp"

#include <gtest/gtest.h>
#include <imgui.h>

#include <functional>
#include <string>
#include <utility>

namespace sweep::test {

/// What the user does in one frame.
struct FrameInput {
  ImVec2 mouse{-1.0f, -1.0f};
  bool pressed = false;  // the left button is down
  bool ctrl = false;
  std::string chars;  // typed this frame
  int key = -1;       // an ImGuiKey_ held down this frame (Enter, Escape), or -1
};

/// The mouse at `mouse`, the left button down or not.
inline FrameInput pointer(ImVec2 mouse, bool pressed, bool ctrl = false) {
  FrameInput input;
  input.mouse = mouse;
  input.pressed = pressed;
  input.ctrl = ctrl;
  return input;
}

/// The characters `chars` typed, or `key` held down.
inline FrameInput keys(std::string chars, int key = -1) {
  FrameInput input;
  input.chars = std::move(chars);
  input.key = key;
  return input;
}

/// An ImGui context of its own, with a font atlas built and nothing drawn.
class HeadlessImGui {
 public:
  using Draw = std::function<void(viewer::ViewerState&)>;

  HeadlessImGui() {
    ImGui::CreateContext();
    ImGuiIO& io = ImGui::GetIO();
    io.DisplaySize = ImVec2(800.0f, 600.0f);
    io.DeltaTime = 1.0f / 60.0f;
    io.IniFilename = nullptr;
    for (int key = 0; key < ImGuiKey_COUNT; ++key) io.KeyMap[key] = key;  // key i is KeysDown[i]
    unsigned char* pixels = nullptr;
    int width = 0, height = 0;
    io.Fonts->GetTexDataAsRGBA32(&pixels, &width, &height);
  }
  ~HeadlessImGui() { ImGui::DestroyContext(); }
  HeadlessImGui(const HeadlessImGui&) = delete;
  HeadlessImGui& operator=(const HeadlessImGui&) = delete;

  /// One frame of `draw` in a window at the top left, with `input`.
  void frame(viewer::ViewerState& s, const Draw& draw, const FrameInput& input = {}) {
    ImGuiIO& io = ImGui::GetIO();
    io.MousePos = input.mouse;
    io.MouseDown[0] = input.pressed;
    io.KeyCtrl = input.ctrl;
    for (bool& down : io.KeysDown) down = false;
    if (input.key >= 0) io.KeysDown[input.key] = true;
    for (char c : input.chars) io.AddInputCharacter(static_cast<unsigned int>(c));
    ImGui::NewFrame();
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(600.0f, 580.0f));
    ImGui::Begin("panel");
    draw(s);
    ImGui::End();
    ImGui::Render();
  }

  /// Where `draw` marks `name` (drawn once, with no input); x < 0 when it marks nothing so.
  glm::vec2 position(viewer::ViewerState& s, const Draw& draw, const std::string& name) {
    viewer::ItemPositions positions;
    s.item_positions = &positions;
    frame(s, draw);
    s.item_positions = nullptr;
    return positions.position(name, glm::vec2(-1.0f));
  }

  /// Presses the mouse at `from`, moves it to `to` and lets go there (a plain click if equal).
  void drag(viewer::ViewerState& s, const Draw& draw, glm::vec2 from, glm::vec2 to, bool ctrl = false) {
    const ImVec2 start(from.x, from.y);
    const ImVec2 end(to.x, to.y);
    frame(s, draw, pointer(start, false, ctrl));
    frame(s, draw, pointer(start, true, ctrl));
    frame(s, draw, pointer(end, true, ctrl));
    frame(s, draw, pointer(end, false, ctrl));
    frame(s, draw, pointer(end, false));
  }

  /// Ctrl+clicks `dx` right of where `draw` marks `name`, so that field is typed in.
  void start_typing(viewer::ViewerState& s, const Draw& draw, const std::string& name, float dx = 20.0f) {
    const glm::vec2 at = position(s, draw, name);
    ASSERT_GE(at.x, 0.0f) << "no field " << name;
    drag(s, draw, at + glm::vec2(dx, 0.0f), at + glm::vec2(dx, 0.0f), true);
  }

  /// Types `text`, one character a frame, then holds `key` (e.g. ImGuiKey_Enter) for a frame.
  void type(viewer::ViewerState& s, const Draw& draw, const std::string& text, int key = -1) {
    for (char c : text) frame(s, draw, keys(std::string(1, c)));
    if (key < 0) return;
    frame(s, draw, keys("", key));
    frame(s, draw);
  }
};

/// A field typed into through the real panel code: `draw` (set by the test's SetUp) draws the
/// panel with `s`. type_into checks after every character that nothing was applied yet.
class FieldTyping : public ::testing::Test {
 protected:
  /// Ctrl+clicks the field marked `name`, types `text` one character a frame, checking each time
  /// that the document, whether it is saved and `setting` (a viewer setting, or nothing) are
  /// unchanged, then presses `key` (Enter by default; -1: none).
  void type_into(const std::string& name, const std::string& text, int key = ImGuiKey_Enter,
                 const std::function<double()>& setting = {}) {
    imgui.start_typing(s, draw, name);
    const Document before = s.doc();
    const double setting_before = setting ? setting() : 0.0;
    const bool dirty_before = s.session.dirty();
    for (char c : text) {
      imgui.type(s, draw, std::string(1, c));
      EXPECT_EQ(s.doc(), before) << "applied while typing, after '" << c << "'";
      EXPECT_EQ(s.session.dirty(), dirty_before) << "after '" << c << "'";
      if (setting) {
        EXPECT_EQ(setting(), setting_before) << "set while typing, after '" << c << "'";
      }
    }
    if (key >= 0) imgui.type(s, draw, "", key);
  }
  /// The number of undo steps.
  int undo_steps() {
    int steps = 0;
    for (; s.session.can_undo(); ++steps) s.session.undo();
    for (int i = 0; i < steps; ++i) s.session.redo();
    return steps;
  }

  HeadlessImGui imgui;
  viewer::ViewerState s;
  HeadlessImGui::Draw draw;
};

}  // namespace sweep::test
