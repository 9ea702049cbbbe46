#pragma once
// The viewer's state while points are edited in the view: a point dragged, the curve-editing
// tools (joint types, the curvature comb, snapping, the rubber band, the transform of several
// points) and a camera drag.
#include "editor/bezier_joints.hpp"
#include "editor/curvature_comb.hpp"
#include "editor/point_drag.hpp"
#include "editor/point_transform.hpp"
#include "editor/snapping.hpp"
#include "editor/view_state.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <optional>

namespace sweep::viewer {

/// A control point being dragged in the view.
struct PointDrag {
  bool active = false;
  editor::ObjectId object = editor::kNoObject;
  int point = -1;
  glm::dvec3 start{0.0};    // where the point was on press
  editor::HandleGrip grip;  // where the pointer was pressed, and the handle's centre from there
  int axis = -1;            // axis constraint of the last frame
  /// The type of the Bezier joint the point is or is a handle of, when the drag began (the rule
  /// the drag keeps: bezier_joints.hpp); Corner for every other point.
  editor::JointType joint_type = editor::JointType::Corner;
  /// What the point may snap to, gathered on press (none when every snap toggle is off).
  std::shared_ptr<editor::SnapTargets> targets;
  std::optional<editor::SnapHit> snap;  // where it snapped in the last frame
};

/// The selected curve's comb, kept until the curve is evaluated again or the scale changes.
struct CombCache {
  editor::ObjectId object = editor::kNoObject;
  std::uint64_t revision = 0;  // the curve's EvaluatedObject::revision
  double factor = 0.0;
  editor::CurvatureComb comb;
};

/// A rubber band being drawn (Shift+drag in the view), in window units.
struct RubberBand {
  bool active = false;
  glm::dvec2 from{0.0};
  glm::dvec2 to{0.0};
};

/// The curve-editing tools' state: joint types chosen, the curvature comb, snapping, the rubber
/// band and the transform of several points (group_input.cpp).
struct CurveEditing {
  editor::JointTypes joints;  // types the user chose that the points alone do not say
  bool comb = false;          // the selected curve's curvature comb (K)
  double comb_scale = 1.0;    // times the automatic needle length (editor::default_comb_scale)
  editor::SnapOptions snap;   // what a dragged point snaps to besides the grid
  CombCache comb_cache;
  RubberBand band;
  std::optional<editor::TransformMode> requested;  // G, R or E pressed: starts in the input
  editor::PointTransform transform;
  editor::ObjectId transform_object = editor::kNoObject;
  bool transform_by_drag = false;  // a selected handle dragged: ends on release
  glm::dvec2 transform_grip{0.0};  // the dragged handle's centre minus the pointer on press
};

/// A camera drag with a mouse button (0 left, 1 right, 2 middle), or none.
struct CameraDrag {
  int button = -1;
  bool moved = false;
  glm::dvec2 last{0.0};
};
}  // namespace sweep::viewer
