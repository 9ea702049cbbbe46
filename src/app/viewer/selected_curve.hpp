#pragma once
// What the selection says about the selected curve, from the parts that say it (the session, the
// selection, the view states and the curve-editing tools), so that both the commands
// (curve_actions.hpp, on the whole state) and the curve tools panel (on its parts) ask here.
// curve_actions.cpp
#include "app/viewer/state/curve_editing.hpp"
#include "editor/bezier_joints.hpp"
#include "editor/curvature_comb.hpp"
#include "editor/edit_session.hpp"
#include "editor/view_state.hpp"

namespace sweep::viewer {

/// The selected curve, if it has control points, else nullptr.
const Object* control_curve(const editor::EditSession& session, const editor::Selection& selection);
/// The Bezier joint the selected point is or is a handle of (bezier_joints.hpp), or -1.
int selected_joint(const editor::EditSession& session, const editor::Selection& selection);
/// The selected joint's type as the editor keeps it (chosen, else as its points say).
/// Precondition: selected_joint(session, selection) >= 0.
editor::JointType selected_joint_type(const editor::EditSession& session, const editor::Selection& selection,
                                      const CurveEditing& editing);
/// The selected curve's curvature comb while the comb is on and a curve is selected and shown,
/// else null. Made again (into editing.comb_cache) only when the curve was evaluated again or
/// the scale changed.
const editor::CurvatureComb* selected_comb(const editor::EditSession& session, const editor::Selection& selection,
                                           const editor::ViewStates& views, CurveEditing& editing);

}  // namespace sweep::viewer
