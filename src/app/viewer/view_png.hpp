#pragma once
// Save PNG of the view: the scene drawn again offscreen at the size asked for (the view's own by
// default), with the control points, curves and grid as asked, and without the selection, the
// hover or any panel: the picture a user puts in a report.
#include "app/viewer/actions.hpp"
#include "app/viewer/scene_view.hpp"
#include "app/viewer/viewer_state.hpp"

#include <glm/vec2.hpp>

namespace sweep::viewer {

/// Writes the PNG of the view asked for in `s.pending_screenshot` (not with_panels) and says so
/// with its full path and size (or the error). Precondition: the window's context is current,
/// framebuffer > 0 both ways.
void write_view_png(ViewerState& s, SceneView& scene, glm::ivec2 framebuffer);

}  // namespace sweep::viewer
