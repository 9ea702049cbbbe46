#pragma once
// What the curve-editing commands do: the selected Bezier joint's type, the points selected
// together and their transforms, the curvature comb and the snap toggles. Like actions.hpp:
// functions of the viewer state, no GL and no window.
#include "app/viewer/selected_curve.hpp"
#include "app/viewer/viewer_state.hpp"
#include "editor/bezier_joints.hpp"
#include "editor/point_transform.hpp"

#include <optional>
#include <vector>

namespace sweep::viewer {

/// selected_curve.hpp's, of the viewer's state.
int selected_joint(const ViewerState& s);
/// Precondition: selected_joint(s) >= 0.
editor::JointType selected_joint_type(const ViewerState& s);
/// Makes the selected joint a corner, smooth or symmetric: one undo step when points move
/// (convert_joint); a corner is remembered for the session (its points do not change).
void convert_selected_joint(ViewerState& s, editor::JointType type);

/// selected_curve.hpp's, of the viewer's state.
const editor::CurvatureComb* selected_comb(ViewerState& s);

/// A: every point of the selected curve.
void select_all_points(ViewerState& s);
/// The selected points with the handles of the Bezier joints and open ends among them, which
/// move with their joint as in a drag (bezier_joints.hpp). Ascending.
std::vector<int> points_with_handles(const ViewerState& s);
/// Converts the selected curve to kind `to` (convert_curve: exact to Bezier and to Hermite, a
/// fit within a thousandth of its size to B-spline or Catmull-Rom), one undo step; the status
/// says how ("converted 'profile' from bsp2 to bez2 exactly").
void convert_selected_curve(ViewerState& s, ObjectKind to);
/// Moves each selected point to the nearest point of the snapping grid (the Edit panel's grid
/// step, z kept for a 2D curve); a selected Bezier joint carries its unselected handles along.
void snap_selected_points(ViewerState& s);
/// Mirrors the selected points (at least two) about the plane through the centre of their box
/// perpendicular to `axis` (0 x, 1 y, 2 z; a 2D curve has no z): one undo step.
void mirror_selected_points(ViewerState& s, int axis);
/// G, R, E: asks for a transform of the selected points (with their joints' handles); the input
/// starts it in this frame, where the pointer and the camera are known (transform_input.cpp).
void request_transform(ViewerState& s, editor::TransformMode mode);

}  // namespace sweep::viewer
