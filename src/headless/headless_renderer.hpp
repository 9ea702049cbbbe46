#pragma once
// Pictures without a window: the shared renderer drawing into a multisampled framebuffer
// object of an offscreen context.
#include "model/document.hpp"
#include "model/evaluation/scene.hpp"
#include "render/camera.hpp"
#include "render/display_settings.hpp"
#include "render/draw_list.hpp"
#include "render/gl_context.hpp"
#include "render/image.hpp"
#include "render/offscreen_target.hpp"
#include "render/renderer.hpp"

#include <filesystem>
#include <memory>
#include <string>

namespace sweep::headless {

class HeadlessRenderer {
 public:
  /// Creates a context from `provider` (default "osmesa", registered here). Throws
  /// std::runtime_error if the context cannot be created.
  explicit HeadlessRenderer(const std::string& provider = "osmesa");
  ~HeadlessRenderer();

  /// Renders `list` (overlay included) at `size` pixels (both > 0, pixel ratio 1) and reads it
  /// back. Precondition: list.scene is set.
  render::Image render(const render::DrawList& list, const render::Camera& camera, glm::ivec2 size,
                       const render::DisplaySettings& settings);
  /// Renders render::draw_list(doc, scene, image_folder): every object, with the control
  /// polygons of `doc` and the materials' images from `image_folder` (the SWP file's folder).
  /// Precondition: scene evaluated from doc.
  render::Image render(const Document& doc, const Scene& scene, const render::Camera& camera, glm::ivec2 size,
                       const render::DisplaySettings& settings, const std::filesystem::path& image_folder = {});

  render::Renderer& renderer() { return *renderer_; }
  /// The largest side of a picture this context can render: the smaller of GL's largest
  /// renderbuffer and viewport (the samples are clamped to GL_MAX_SAMPLES by OffscreenTarget).
  int max_picture_side() const;
  /// GL renderer and version, for messages.
  std::string description() const;

 private:
  std::unique_ptr<render::GlContext> context_;
  std::unique_ptr<render::Renderer> renderer_;
  std::unique_ptr<render::OffscreenTarget> target_;
};

}  // namespace sweep::headless
