#pragma once
// The window: every GLFW call of the viewer lives behind this (platform_glfw.cpp): the "glfw"
// context provider, input callbacks and the key queue, ImGui's GLFW and OpenGL backends with
// the ImGui 1.86 key-tap workaround, the title, waiting for events.
#include "render/gl_context.hpp"

#include <glm/vec2.hpp>

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace sweep::viewer {

/// Thrown when GLFW finds no display to open a window on.
class NoDisplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// True if DISPLAY or WAYLAND_DISPLAY is set and not empty.
bool display_variable_set();

/// A key press as the window reported it: the key code (GLFW's, which editor::Key uses) and
/// whether Ctrl (or Cmd) and Shift were down.
struct KeyPress {
  int key = 0;
  bool ctrl = false;
  bool shift = false;
};

class Platform {
 public:
  /// Opens a window of `size` screen units titled "Sweep" with an OpenGL 3.3 core context
  /// (single-sampled: the viewer multisamples offscreen) and ImGui. Throws NoDisplayError or
  /// std::runtime_error saying why.
  explicit Platform(glm::ivec2 size, bool vsync);
  ~Platform();
  Platform(const Platform&) = delete;
  Platform& operator=(const Platform&) = delete;

  render::GlContext& context() { return *context_; }
  /// The monitor's content scale (1 on ordinary screens); the UI is drawn this much larger.
  float content_scale() const { return content_scale_; }

  /// Waits until an event arrives or `timeout` seconds pass (< 0: no limit; 0: just polls).
  /// Returns true if any input or window event arrived since the last call (the first call
  /// always says so).
  bool wait(double timeout);
  /// Seconds since the window opened.
  double now() const;
  /// Makes a wait() in progress return (from any thread: a file dialog that finished).
  static void wake();

  /// Starts an ImGui frame; keys tapped since the last frame are held down for it.
  void begin_ui_frame();
  /// Ends the ImGui frame (ImGui::Render) and lets the tapped keys go.
  void end_ui_frame();
  /// Draws the ImGui frame into the bound framebuffer.
  void draw_ui();

  /// Key presses since the last call, in order.
  std::vector<KeyPress> take_key_presses();
  /// Files dropped onto the window since the last call.
  std::vector<std::string> take_dropped_files();
  /// True once after the user asked the window to close (the close button); the window stays
  /// open until close().
  bool take_close_request();
  void close();
  bool closing() const;
  /// The axis (0 x, 1 y, 2 z) whose key is held down to constrain a drag, or -1.
  int held_axis() const;
  void set_title(const std::string& title);

  struct Queue;  // what the window's callbacks collect between frames (platform_glfw.cpp)

 private:
  std::unique_ptr<Queue> queue_;
  std::unique_ptr<render::GlContext> context_;
  void* window_ = nullptr;  // GLFWwindow*, kept opaque so no GLFW header leaks out of here
  float content_scale_ = 1.0f;
  bool imgui_ready_ = false;
  std::vector<int> held_taps_;
  std::string title_;
};

}  // namespace sweep::viewer
