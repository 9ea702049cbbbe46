#include "app/viewer/point_input.hpp"

#include "app/viewer/actions.hpp"
#include "editor/insert_at.hpp"
#include "editor/point_drag.hpp"
#include "model/edit/edit.hpp"
#include "model/edit/edit_insert.hpp"
#include "model/edit/shown_points.hpp"

#include <imgui.h>

#include <string>
#include <utility>
#include <vector>

namespace sweep::viewer {
namespace {

/// The point's target under the pointer: the grid's (grip_target), then, unless Ctrl is held or
/// an axis constrains it, the nearest snap target within reach. Sets drag.snap to what it
/// snapped to. Nullopt as grip_target says.
std::optional<glm::dvec3> drag_target(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse,
                                      bool planar) {
  PointDrag& drag = s.point_drag;
  editor::PointDragInput input;
  input.start = drag.start;
  input.planar = planar;
  input.axis = drag.axis;
  input.view_forward = s.camera.forward();
  input.snap = s.snap ? s.snap_size : 0.0;
  std::optional<glm::dvec3> target = editor::grip_target(mapping, drag.grip, mouse, input);
  drag.snap.reset();
  // A press without movement moves nothing (grip_target gives the start exactly): no snapping.
  if (!target || !drag.targets || mouse == drag.grip.pressed || drag.axis >= 0 || ImGui::GetIO().KeyCtrl) {
    return target;
  }
  drag.snap = editor::snap_target(*drag.targets, mapping, mouse + drag.grip.offset, s.curve_editing.snap);
  if (drag.snap) target = drag.snap->position;
  return target;
}

/// Moves the dragged point under the pointer. On release the constraint of the last frame is
/// kept: the axis key may be let go first.
void drag_point_to(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse, int held_axis,
                   bool released) {
  PointDrag& drag = s.point_drag;
  const int object = s.session.index_of(drag.object);
  if (object < 0) return;
  const Object& curve = s.doc().objects[std::size_t(object)];
  if (drag.point >= int(curve.as<PointsPart>().points.size())) return;
  drag.axis = released ? drag.axis : held_axis;
  const std::optional<glm::dvec3> target = drag_target(s, mapping, mouse, is_planar_curve(curve.kind()));
  if (!target || *target == shown_points(curve)[std::size_t(drag.point)]) return;
  // Alt breaks the joint's rule for this frame: the point moves alone.
  std::vector<PointMove> moves = editor::drag_moves(curve, drag.point, *target, drag.joint_type, ImGui::GetIO().KeyAlt);
  apply_continuous(s, [object, moves = std::move(moves)](Document& d) { return move_shown_points(d, object, moves); });
}

bool any_snapping(const editor::SnapOptions& options) {
  return options.points || options.curves || options.axis;
}

}  // namespace

void start_point_drag(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse, int point,
                      int held_axis) {
  const Object* curve = selected_control_curve(s);
  if (curve == nullptr) return;
  const glm::dvec3 start = shown_points(*curve)[std::size_t(point)];
  const std::optional<glm::dvec2> centre = editor::to_screen(mapping, start);
  if (!centre) return;
  const int joint = editor::joint_of(*curve, point);
  const editor::JointType type =
      joint >= 0 ? s.curve_editing.joints.type(*curve, curve->id, joint) : editor::JointType::Corner;
  s.point_drag = {true, s.selection.object, point, start, {mouse, *centre - mouse}, held_axis, type, {}, {}};
  if (any_snapping(s.curve_editing.snap)) {
    // Once per drag: the other objects do not move while it lasts.
    s.point_drag.targets = std::make_shared<editor::SnapTargets>(
        editor::gather_snap_targets(s.doc(), s.session.scene(), s.views.visibility(s.doc()), {s.selected(), point}));
  }
  s.selection.point = point;
  s.session.begin_step("move point");
}

void continue_point_drag(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse, int axis) {
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
    if (ImGui::IsMousePosValid()) drag_point_to(s, mapping, mouse, axis, true);  // where it was let go
    s.point_drag = {};
    s.session.end_step();
  } else if (ImGui::IsMousePosValid()) {
    drag_point_to(s, mapping, mouse, axis, false);
  }
}

bool insert_at_double_click(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse,
                            double radius) {
  const Object* curve = selected_control_curve(s);
  const int object = s.selected();
  if (curve == nullptr || !is_curve(curve->kind())) return false;
  const CurveSamples& samples = s.session.scene().objects[std::size_t(object)].curve;
  const std::optional<double> parameter = editor::parameter_at(*curve, samples, mapping, mouse, radius);
  if (!parameter) return false;
  const int inserted = inserted_point_index(*curve, *parameter);
  const double at = *parameter;
  if (run_edit(s, "insert point", [object, at](Document& d) { return insert_point_at(d, object, at); })) {
    s.selection.point = inserted;
    s.status = "inserted point " + std::to_string(inserted);
  }
  return true;
}

void draw_snap_marker(const ViewerState& s) {
  if (!s.point_drag.active || !s.point_drag.snap) return;
  draw_snap_ring(*s.point_drag.snap);
}

void draw_snap_ring(const editor::SnapHit& hit) {
  const ImVec2 centre(float(hit.screen.x), float(hit.screen.y));
  const ImU32 colour = hit.kind == editor::SnapKind::Point ? IM_COL32(40, 230, 255, 255) : IM_COL32(255, 80, 255, 255);
  ImGui::GetForegroundDrawList()->AddCircle(centre, 9.0f, colour, 0, 2.0f);
}

}  // namespace sweep::viewer
