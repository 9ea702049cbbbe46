#pragma once
// Draws the viewer's scene into the window: what the state shows (visible objects, control
// polygons, the editor's overlay) through the shared renderer. Still frames are multisampled
// offscreen and resolved into the (single-sampled) window; fast frames, while the view moves,
// go straight to the window, which on a software rasterizer is several times cheaper.
#include "app/viewer/viewer_state.hpp"
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

  render::Renderer& renderer() { return renderer_; }

 private:
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
