#pragma once
// The pen's state (pen_actions.hpp): whether it is on, the kind it draws, the stroke being drawn
// and the curve it has become in the document, and the coordinates typed for the next point.
#include "editor/pen.hpp"
#include "editor/snapping.hpp"
#include "editor/view_state.hpp"
#include "model/edit/edit.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <memory>
#include <optional>

namespace sweep::viewer {

/// The plane the pen draws on: through `origin`, facing `normal`.
struct PenPlane {
  glm::dvec3 origin{0.0};
  glm::dvec3 normal{0.0, 0.0, 1.0};
};

struct PenTool {
  bool on = false;
  ObjectKind kind = ObjectKind::BSpline2;  // what the next stroke draws (the Pen panel's choice)
  /// The stroke being drawn (one undo step, open from its first node to its end), its plane, and
  /// its curve once it has enough nodes to be one (kNoObject before).
  std::optional<editor::PenStroke> stroke;
  PenPlane plane;
  editor::ObjectId object = editor::kNoObject;
  /// The left button is held on the last node: moving it drags the node's handles.
  bool holding = false;
  glm::dvec2 pressed{0.0};  // where, in window units
  /// What the nodes may snap to, gathered when the stroke starts (none when snapping is off).
  std::shared_ptr<editor::SnapTargets> targets;
  std::optional<editor::SnapHit> snap;  // where the pointer snapped this frame
  std::optional<glm::dvec3> hover;      // where a click would put a node this frame (none: off the plane)
  glm::dvec3 typed{0.0};                // the Pen panel's coordinates for a typed point
  /// An open curve continued from its end (the first click had that end selected): each node is
  /// extend_curve at that end, one undo step from the press to the release.
  editor::ObjectId extending = editor::kNoObject;
  CurveEnd end = CurveEnd::End;
  glm::dvec3 last{0.0};  // the last node put down there
  int added = 0;         // nodes put down there so far

  /// A stroke is drawn or a curve continued: the other keys wait.
  bool drawing() const { return stroke.has_value() || extending != editor::kNoObject; }
};

}  // namespace sweep::viewer
