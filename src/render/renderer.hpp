#pragma once
// The one renderer, written against OpenGL 3.3 core. It draws what a DrawList holds into whatever
// context is current (a GLFW window or an OSMesa buffer) and never knows which. Each object's GPU copy
// mirrors its CPU copy and is re-uploaded only when the object's revision changes.
#include "render/camera.hpp"
#include "render/display_settings.hpp"
#include "render/draw_list.hpp"
#include "render/image.hpp"

#include <glm/vec2.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace sweep::render {

struct RenderStats {
  std::size_t vertices = 0;       // of the visible surfaces
  std::size_t triangles = 0;      // of the visible surfaces
  std::size_t curve_samples = 0;  // of the visible curves
  /// Curvature colour modes: the map runs from -range (blue) to +range (red); 0 otherwise.
  float color_range = 0.0f;
  /// Images that could not be loaded (the surface is drawn in its colour instead), once each.
  std::vector<std::string> warnings;
};

class Renderer {
 public:
  /// Compiles the embedded shaders. Precondition: a current OpenGL >= 3.3 core context with
  /// its functions loaded (load_gl_functions). Throws std::runtime_error with the GLSL log if
  /// a shader does not compile.
  Renderer();
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  /// Draws `list` into the currently bound draw framebuffer of `target`: its surfaces, curves,
  /// decorations and control polygons as `settings` asks, then its overlay over them. Uploads the
  /// objects whose revision changed since the last call and the decorations (frames, normals,
  /// control polygons) the modes need; overlay batches are uploaded every call (they are meant
  /// to be small). Preconditions: the context of construction is current; list.scene is set
  /// (throws std::invalid_argument if not).
  void draw(const DrawList& list, const Camera& camera, const RenderTarget& target, const DisplaySettings& settings);

  /// What the last draw() showed.
  const RenderStats& stats() const;
  /// Buffer uploads so far (tests check that unchanged objects are not re-uploaded).
  std::uint64_t upload_count() const;
  /// Frees every GPU copy; the next draw() uploads everything again.
  void clear();

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

/// Loads the GL 3.3 core functions through `get_proc` for the current context (glad).
/// Returns false if the context is older than 3.3 or loading fails.
bool load_gl_functions(void (*(*get_proc)(const char*))());

/// Reads the colour buffer of the bound read framebuffer (rows flipped to top-down).
/// Precondition: a current context; size within the framebuffer.
Image read_framebuffer(glm::ivec2 size);

/// The first pending GL error of the current context (GL_NO_ERROR, 0, if none), clearing all
/// pending ones. Tests call it after drawing.
unsigned int take_gl_error();

/// Renderer name, version and GLSL version of the current context, for diagnostics.
std::string gl_description();

}  // namespace sweep::render
