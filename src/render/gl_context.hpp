#pragma once
// Where GL contexts come from. A provider (a GLFW window, an OSMesa offscreen buffer, ...) is
// registered under a name and chosen by that name at run time; the renderer only ever sees a
// current OpenGL 3.3 core context with its functions loaded.
#include <glm/vec2.hpp>

#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace sweep::render {

struct ContextRequest {
  glm::ivec2 size{800, 600};  // window size in screen units, or offscreen size in pixels
  int samples = 4;            // multisampling wanted (providers may give fewer)
  std::string title = "Sweep";
  bool visible = true;  // windows only
};

/// A current OpenGL 3.3 core context whose functions are loaded (glad).
class GlContext {
 public:
  virtual ~GlContext() = default;
  /// The provider's registered name ("glfw", "osmesa").
  virtual std::string_view provider() const = 0;
  virtual void make_current() = 0;
  /// Size of the default framebuffer in pixels (differs from the window size on HiDPI).
  virtual glm::ivec2 framebuffer_size() const = 0;
  /// Window size in screen units; equals framebuffer_size() offscreen.
  virtual glm::ivec2 window_size() const = 0;
  /// Shows the frame (swap buffers) or waits for it to finish (offscreen).
  virtual void present() = 0;
  /// The native window (GLFWwindow*) for input and UI, or nullptr for offscreen contexts.
  virtual void* native_window() const = 0;
};

/// Makes a context or throws std::runtime_error saying why (no display, no OSMesa, ...).
using ContextFactory = std::function<std::unique_ptr<GlContext>(const ContextRequest&)>;

/// Registers (or replaces) the provider called `name`.
void register_context_provider(const std::string& name, ContextFactory factory);
/// Creates a context from the provider called `name`. Throws std::runtime_error if no such
/// provider is registered or the provider fails.
std::unique_ptr<GlContext> create_context(std::string_view name, const ContextRequest& request);
/// Names of the registered providers, sorted.
std::vector<std::string> context_provider_names();

}  // namespace sweep::render
