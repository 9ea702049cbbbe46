#pragma once
// The pointer on control points: a press on a handle starts a drag that follows the joint rules
// (bezier_joints.hpp) and snaps to other points, curves and the axis (snapping.hpp; Ctrl held
// suspends it); a double-click on the selected curve inserts a point there (edit_insert.hpp).
// Called by input.cpp, which decides what a press is for.
#include "app/viewer/viewer_state.hpp"
#include "editor/picking.hpp"
#include "editor/snapping.hpp"

#include <glm/vec2.hpp>

namespace sweep::viewer {

/// Starts dragging control point `point` of the selected curve with the pointer at `mouse`.
void start_point_drag(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse, int point,
                      int held_axis);
/// A point drag in progress: follows the pointer until the left button is let go (one undo step).
void continue_point_drag(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse, int axis);
/// A double-click at `mouse` on the selected curve (within `radius` window units): inserts a
/// point there and selects it. Returns whether the click was on the selected curve.
bool insert_at_double_click(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse,
                            double radius);
/// Where the dragged point snapped this frame, as a ring in the view (ImGui's foreground).
void draw_snap_marker(const ViewerState& s);
/// A ring where a point snapped: cyan on a control point, magenta on a curve or the axis (the
/// dragged point's and the pen's marker).
void draw_snap_ring(const editor::SnapHit& hit);

}  // namespace sweep::viewer
