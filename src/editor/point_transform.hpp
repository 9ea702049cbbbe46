#pragma once
// A modal transform of the selected control points, as Blender's G and R (and a scale key of the
// integrator's choice: S is the surface-mode key): the pointer drives it, X/Y/Z constrain it to
// an axis, a typed number overrides the pointer, Enter or a click confirms and Esc or a right
// click cancels. A pure state machine: it returns the points' new positions as PointMoves, and
// the caller applies them with move_points inside one undo step (EditSession::begin_step, apply
// per update, end_step), which checks the range as single-point edits do. Every update is
// computed from the start positions, so nothing accumulates within a transform. No GL.
#include "editor/picking.hpp"
#include "editor/point_selection.hpp"
#include "model/edit/edit.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace sweep::editor {

enum class TransformMode { Grab, Rotate, Scale };

/// What a transform starts from.
struct TransformStart {
  TransformMode mode = TransformMode::Grab;
  std::vector<int> indices;           // the selected points
  std::vector<glm::dvec3> positions;  // their positions at the start, in the order of `indices`
  glm::dvec3 centre{0.0};             // the pivot of rotate and scale (centre(), point_selection.hpp)
  /// Grab: the world point whose plane (or axis line) the pointer moves along: the centre for
  /// the G key, the pressed handle when the selection is dragged by one of its points.
  std::optional<glm::dvec3> anchor;
  /// Grab by an anchor: the grid step the anchor lands on (the others keep their offsets from
  /// it), only along the constraint axis when there is one; 0: no snapping.
  double grid = 0.0;
  bool planar = false;      // a 2D curve: the points stay in z = 0
  glm::dvec2 pointer{0.0};  // the pointer's window position when the transform began
  ScreenMapping mapping;
  glm::dvec3 view_forward{0.0, 0.0, -1.0};  // the camera's viewing direction
};

/// start for the selected points of a curve whose points are `points`, pivoting about their
/// centre(). Preconditions: selection not empty; every selected index < points.size().
TransformStart transform_start(TransformMode mode, std::span<const glm::dvec3> points, const PointSelection& selection,
                               bool planar);

class PointTransform {
 public:
  /// Begins a transform (replacing one in progress) with no axis and nothing typed.
  /// Preconditions: start.indices and start.positions have the same size; view_forward != 0.
  void start(TransformStart start);
  bool active() const { return active_; }
  TransformMode mode() const { return start_.mode; }

  /// The pointer moved to `pointer`: the points' new positions. A pointer that gives no target
  /// (its ray runs along the grab plane, or it sits on the centre's screen position when
  /// rotating) keeps the last one. While a number is typed it decides and the pointer is only
  /// remembered. Precondition: active().
  std::vector<PointMove> update(const glm::dvec2& pointer);
  /// The points' positions for the current pointer, axis and typed number (after a key).
  std::vector<PointMove> moves() const;

  /// X (0), Y (1) or Z (2) pressed: constrains to that axis, or removes the constraint when it
  /// is the current one. Returns false and changes nothing for z on a planar curve (its points
  /// have no z to move along or about). Precondition: 0 <= axis <= 2.
  bool toggle_axis(int axis);
  /// The constraint axis, or -1.
  int axis() const { return axis_; }

  /// A key typed into the number: a digit, '.' (once) or '-' (flips the sign, wherever it is
  /// pressed). Returns false for anything else. Grab moves by the number along the axis (x
  /// without one), rotate turns by that many degrees (right-handed about the rotation axis: the
  /// constraint axis, z for planar curves, else the one pointing at the viewer, which is
  /// anticlockwise on screen), scale multiplies by it. Text without a digit ("-", ".") does not
  /// override the pointer yet.
  bool type(char key);
  /// Backspace: removes the last typed character.
  void backspace();
  /// What was typed ("" when the pointer decides).
  const std::string& typed() const { return typed_; }

  /// Enter or a click: the final positions; the transform ends. Precondition: active().
  std::vector<PointMove> confirm();
  /// Esc or a right click: the start positions, to apply before ending the undo step (or to
  /// revert); the transform ends. Precondition: active().
  std::vector<PointMove> cancel();

  /// For the status bar: "Grab along x: 1.5", "Rotate 45° about z", "Scale 2 along y"; a typed
  /// number is shown as typed, in brackets: "Rotate [-9]° about z". "" when not active.
  std::string status() const;

 private:
  void update_pointer(const glm::dvec2& pointer);
  std::optional<double> typed_value() const;
  int rotation_axis_index() const;  // 0, 1, 2, or -1 for the view axis
  glm::dvec3 rotation_axis() const;
  glm::dvec3 grab_offset() const;
  double rotation_degrees() const;
  double scale_factor() const;
  glm::dvec3 transformed(const glm::dvec3& p) const;

  TransformStart start_;
  bool active_ = false;
  int axis_ = -1;
  std::string typed_;
  glm::dvec2 pointer_{0.0};
  std::optional<glm::dvec2> centre_on_screen_;
  glm::dvec3 pointer_offset_{0.0};    // grab: the pointer's world displacement on the plane or axis
  double pointer_turn_ = 0.0;         // rotate: radians anticlockwise on screen, unwrapped
  std::optional<double> last_angle_;  // rotate: the pointer's last angle about the centre
  double pointer_factor_ = 1.0;       // scale
};

}  // namespace sweep::editor
