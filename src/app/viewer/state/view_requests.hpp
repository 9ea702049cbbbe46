#pragma once
// What the viewer measures and what it was asked to do over the next frames: the stats panel's
// numbers, a PNG to write, the Save PNG dialog's answers and a camera riding along with a rider.
#include "editor/view_state.hpp"
#include "render/camera.hpp"
#include "render/renderer.hpp"

#include <glm/vec2.hpp>

#include <cstdint>
#include <deque>
#include <filesystem>
#include <string>
#include <vector>

namespace sweep::viewer {

/// Numbers for the stats panel and --frame-time.
struct ViewerStats {
  std::deque<double> frame_ms;    // the last frames' drawing times
  std::vector<double> remesh_ms;  // every re-mesh time: edits, undo, redo, evaluation changes
  render::RenderStats render;     // what the last frame drew
  std::string gl_description;
};

/// A PNG asked for (Save PNG of the view / of the window), written once the next frame is drawn
/// (script_hooks.cpp).
struct ScreenshotRequest {
  std::filesystem::path path;  // absolute; empty: none asked for
  bool with_panels = false;    // the whole window; otherwise the 3D view alone, without the UI
  int frames_to_wait = 0;      // frames drawn first (a menu item clicked closes its menu in the next)
  /// Of the view alone: drawn again at this size (0 x 0: the view's size on screen), with or
  /// without the control points, the curves and the ground grid, and no selection or hover.
  glm::ivec2 size{0, 0};
  bool control_points = true;
  bool curves = true;
  bool grid = true;
};

/// The Save PNG of the view dialog (panels/png_dialog.cpp): open while asking, and the answers,
/// which start as the view shows when it opens.
struct PngDialog {
  bool open = false;
  int size_choice = 0;  // index into png_sizes() (0: the view)
  bool control_points = true;
  bool curves = true;
  bool grid = true;
};

/// The camera riding along with a rider (view_actions.cpp): while `rider` is set, the camera is
/// placed with it before every frame (render::ride_camera), in perspective.
struct RideAlong {
  editor::ObjectId rider = editor::kNoObject;  // kNoObject: the orbit camera
  render::RideView view = render::RideView::Chase;
  render::Camera orbit;  // the orbit camera when the ride began, given back by Orbit (and Space)
  /// The model's size (radius, top, a train behind), measured again only when its mesh changes
  /// (revision).
  int radius_model = -1;
  std::uint64_t radius_revision = 0;
  RiderSize size;
};
}  // namespace sweep::viewer
