#pragma once
// The "glfw" GL context provider: a window with an OpenGL 3.3 core context (4x MSAA when the
// system has it).
#include <stdexcept>

namespace sweep::viewer {

/// Thrown by the provider when GLFW finds no display to open a window on.
class NoDisplayError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Registers the provider under the name "glfw" (see render::create_context). Idempotent.
/// The contexts it makes throw NoDisplayError when glfwInit fails, std::runtime_error when the
/// window or a 3.3 core context cannot be created.
void register_glfw_provider();

/// True if DISPLAY or WAYLAND_DISPLAY is set and not empty.
bool display_variable_set();

}  // namespace sweep::viewer
