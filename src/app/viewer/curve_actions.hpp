#pragma once
// What the curve-editing commands do: the selected Bezier joint's type, the points selected
// together and their transforms, the curvature comb and the snap toggles. Like actions.hpp:
// functions of the viewer state, no GL and no window.
#include "app/viewer/viewer_state.hpp"
#include "editor/bezier_joints.hpp"

#include <optional>

namespace sweep::viewer {

/// The Bezier joint the selected point is or is a handle of (bezier_joints.hpp), or -1.
int selected_joint(const ViewerState& s);
/// The selected joint's type as the editor keeps it (chosen, else as its points say).
/// Precondition: selected_joint(s) >= 0.
editor::JointType selected_joint_type(const ViewerState& s);
/// Makes the selected joint a corner, smooth or symmetric: one undo step when points move
/// (convert_joint); a corner is remembered for the session (its points do not change).
void convert_selected_joint(ViewerState& s, editor::JointType type);

}  // namespace sweep::viewer
