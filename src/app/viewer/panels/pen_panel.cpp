// The Pen panel: the pen on or off (B), the kind it draws, where it draws, and a point put down at
// typed coordinates (on the pen's plane), with Close and Finish for the stroke being drawn.
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"
#include "app/viewer/pen_actions.hpp"
#include "editor/pen.hpp"
#include "model/document.hpp"

#include <imgui.h>

#include <algorithm>
#include <string>
#include <vector>

namespace sweep::viewer::panels {
namespace {

/// Every kind the pen draws, in ObjectKind order.
std::vector<ObjectKind> pen_kinds() {
  std::vector<ObjectKind> kinds;
  for (int k = 0; k <= int(ObjectKind::Rider); ++k) {
    if (editor::pen_draws(ObjectKind(k))) kinds.push_back(ObjectKind(k));
  }
  return kinds;
}

void kind_combo(ViewerState& s) {
  static const std::vector<ObjectKind> kKinds = pen_kinds();
  std::vector<std::string_view> labels;
  for (const ObjectKind kind : kKinds) labels.push_back(kind_info(kind).label);
  int choice = int(std::find(kKinds.begin(), kKinds.end(), s.pen.kind) - kKinds.begin());
  ImGui::BeginDisabled(s.pen.drawing());  // a stroke keeps its kind
  marked_combo(s.item_positions, "draws", labels, choice, "pen-kind");
  ImGui::EndDisabled();
  s.pen.kind = kKinds[std::size_t(choice)];
}

/// The coordinates of a point on the pen's plane, typed, and the button that puts it down: x and
/// y on the xy-plane, x and z on the ground (its height is the plane's).
void typed_point(ViewerState& s) {
  const PenPlane plane = s.pen.drawing() ? s.pen.plane : pen_plane(s);
  glm::dvec3& typed = s.pen.typed;
  const bool ground = plane.normal.y != 0.0;
  ImGui::PushItemWidth(90.0f);
  ImGui::InputDouble("x", &typed.x, 0.0, 0.0, "%.6g");
  mark_item(s, "pen-x");
  ImGui::SameLine();
  ImGui::InputDouble(ground ? "z" : "y", ground ? &typed.z : &typed.y, 0.0, 0.0, "%.6g");
  mark_item(s, ground ? "pen-z" : "pen-y");
  ImGui::PopItemWidth();
  ImGui::SameLine();
  if (ImGui::Button("Put down")) {
    glm::dvec3 at = typed;
    if (ground) at.y = plane.origin.y;
    if (!ground) at.z = 0.0;
    if (!s.pen.on) toggle_pen(s);
    pen_place(s, at);
  }
  mark_item(s, "pen-put-down");
}

}  // namespace

void pen_panel(ViewerState& s, editor::CommandTable& commands) {
  const bool open = ImGui::CollapsingHeader("Pen (draw a curve by clicking)");
  mark_item(s, "pen-panel");
  if (!open) return;
  ImGui::PushID("pen");
  bool on = s.pen.on;
  if (ImGui::Checkbox("Pen on [B]", &on)) commands.run(editor::CommandId::Pen);
  mark_item(s, "pen-on");
  kind_combo(s);
  const PenPlane plane = s.pen.drawing() ? s.pen.plane : pen_plane(s);
  if (const int continued = pen_continues(s); continued >= 0) {
    ImGui::TextWrapped("The pen continues '%s' from its selected end.", display_name(s.doc(), continued).c_str());
    if (ImGui::Button("Draw a new curve instead")) s.selection.point = -1;
    mark_item(s, "pen-new-curve");
  }
  if (plane.normal.y != 0.0) {
    ImGui::TextDisabled("draws on the level plane y = %.4g", plane.origin.y);
  } else {
    ImGui::TextDisabled("draws on the xy-plane (z = 0)");
  }
  ImGui::TextWrapped(
      "Click: a point. Drag: a joint's handles (Bezier) or a tangent (Hermite). Click the first point: closed. "
      "Enter or Esc: done. Backspace: take the last point back. Snapping as for a dragged point.");
  typed_point(s);
  if (s.pen.stroke) {
    if (ImGui::Button("Close")) pen_close(s);
    mark_item(s, "pen-close");
    ImGui::SameLine();
    if (ImGui::Button("Finish")) pen_finish(s);
    mark_item(s, "pen-finish");
    ImGui::SameLine();
    ImGui::Text("%zu put down", s.pen.stroke->nodes().size());
  }
  ImGui::PopID();
}

}  // namespace sweep::viewer::panels
