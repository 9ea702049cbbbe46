#pragma once
// The pen: a curve drawn by clicking, as in a drawing program. A click puts down a node; a press
// dragged before it is let go shapes the node's handles where the kind has them. What a node and
// its drag become in the curve's point list is read from the kind's point layout
// (model/kinds/point_layout.hpp), so a kind with control points gets the pen by declaring its
// layout. No GL: the viewer's pen_input.cpp feeds it positions on its drawing plane.
#include "model/edit/edit.hpp"
#include "model/object.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <span>
#include <vector>

namespace sweep::editor {

/// One place the pen put down: where it was pressed, and the drag from there to where it was
/// let go (0 for a click).
struct PenNode {
  glm::dvec3 at{0.0};
  glm::dvec3 drag{0.0};
};

/// True for the kinds the pen draws: every curve kind whose layout has control points.
bool pen_draws(ObjectKind kind);

/// The nodes a curve of `kind` needs at least, open or closed: the layout's least groups (a
/// Bezier's one piece has two joints), and at least 2 for a closed one.
std::size_t pen_least_nodes(ObjectKind kind, bool closed);

/// The point list of a `kind` curve through `nodes` (at least pen_least_nodes), read from the
/// kind's layout, entry by entry of each node's group:
/// - a Position is the node's place;
/// - a Handle (Bezier) between two positions shapes the piece to the next node: the first is
///   this node's outgoing handle, at + drag, the second the next node's incoming one, at - drag
///   (symmetric handles); a node put down by a click has its handle a third of the way along the
///   piece's chord (a straight piece where both ends were clicked). An open curve's last node
///   has no piece after it, so no handles;
/// - a Tangent (Hermite) is 3 × drag, so that the handle the editor shows at p + t/3 lies where
///   the pointer was let go; for a click, the Catmull-Rom tangent (half the chord between the
///   neighbours; the chord to the one neighbour at an open end).
/// A closed curve has a piece from the last node back to the first and ends with the layout's
/// seam repeats (so is_closed_polygon holds). Drags mean nothing to a kind of positions only
/// (B-spline, Catmull-Rom, Kochanek-Bartels, polyline).
std::vector<glm::dvec3> pen_points(ObjectKind kind, std::span<const PenNode> nodes, bool closed);

/// The points of open curve `points` (of `kind`) after the pen put down a node at its end `end`
/// (extend_curve) and dragged it by `drag`, read from the layout as pen_points reads it: the Handle
/// beside the end joint (Bezier) is at the joint - drag, where the incoming handle of a drawn
/// joint is; a Tangent of the end point (Hermite) is 3 × drag in the direction of drawing (so
/// negated at the start, which the curve runs away from). Kinds of positions only are unchanged.
/// Precondition: the list ends (at `end`) on a whole group of the layout.
std::vector<glm::dvec3> pen_shape_end(ObjectKind kind, std::vector<glm::dvec3> points, CurveEnd end,
                                      const glm::dvec3& drag);

/// A stroke of the pen being drawn: its kind and nodes.
class PenStroke {
 public:
  explicit PenStroke(ObjectKind kind) : kind_(kind) {}
  ObjectKind kind() const { return kind_; }
  const std::vector<PenNode>& nodes() const { return nodes_; }
  /// Puts down a node at `at` (a press).
  void press(const glm::dvec3& at) { nodes_.push_back({at, glm::dvec3(0.0)}); }
  /// The last node's drag: the pointer is at `pointer`. Precondition: a node is down.
  void drag_to(const glm::dvec3& pointer) { nodes_.back().drag = pointer - nodes_.back().at; }
  /// Takes the last node back (Backspace while drawing). Does nothing without nodes.
  void remove_last() {
    if (!nodes_.empty()) nodes_.pop_back();
  }
  /// Enough nodes for a curve of the kind, open or closed.
  bool complete(bool closed) const { return nodes_.size() >= pen_least_nodes(kind_, closed); }
  /// pen_points of the nodes. Precondition: complete(closed).
  std::vector<glm::dvec3> points(bool closed) const { return pen_points(kind_, nodes_, closed); }

 private:
  ObjectKind kind_;
  std::vector<PenNode> nodes_;
};

}  // namespace sweep::editor
