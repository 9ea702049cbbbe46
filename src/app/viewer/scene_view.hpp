#pragma once
// Draws the viewer's scene into the window: what the state shows (visible objects, control
// polygons, the editor's overlay) through the shared renderer. Still frames are multisampled
// offscreen and resolved into the (single-sampled) window; fast frames, while the view moves,
// go straight to the window, which on a software rasterizer is several times cheaper.
#include "app/viewer/viewer_state.hpp"
#include "render/draw_list.hpp"
#include "render/image.hpp"
#include "render/offscreen_target.hpp"
#include "render/renderer.hpp"

#include <glm/vec2.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace sweep::viewer {

class SceneView {
 public:
  /// Precondition: the window's context is current. `samples`: multisampling of still frames
  /// (0: none).
  explicit SceneView(int samples) : samples_(samples) {}

  /// Draws the scene and overlay into the window's back buffer of `framebuffer` pixels, and
  /// leaves the window's framebuffer bound for the UI.
  void draw(ViewerState& s, glm::ivec2 framebuffer, bool fast);

  /// The scene as `camera` sees it at `size` (> 0 both ways) pixels with `display`'s settings
  /// (control points, curves, grid), without the selection, the hover or the UI: Save PNG of the
  /// view. Multisampled as still frames are; leaves the window's framebuffer bound.
  render::Image picture(ViewerState& s, const render::Camera& camera, glm::ivec2 size,
                        const render::DisplaySettings& display);

  render::Renderer& renderer() { return renderer_; }

 private:
  /// What a draw list shows besides the objects: the curves' fold marks, the ground grid, and
  /// the selection with the hovered point.
  struct SceneChoice {
    bool curves = true;
    bool grid = true;
    bool selection = true;
  };
  render::DrawList scene_list(ViewerState& s, const SceneChoice& choice);

  /// The box of the visible objects for the ground grid, measured again only when an object's
  /// revision or the visibility changed (a big surface is not walked every frame).
  const render::Bounds& visible_bounds(const Scene& scene, const std::vector<bool>& visible);

  std::vector<std::uint64_t> bounds_revisions_;
  std::vector<bool> bounds_visible_;
  render::Bounds bounds_;
  render::Renderer renderer_;
  int samples_ = 0;
  std::unique_ptr<render::OffscreenTarget> target_;  // still frames, when multisampling
};

}  // namespace sweep::viewer
