// The selected curve's editing tools, under its point table: the selected Bezier joint's type
// and its conversions, the curvature comb with its plot, the points selected together and the
// snap toggles. Every button is a command of the table.
#include "app/viewer/curve_actions.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>

#include <string>

namespace sweep::viewer::panels {
namespace {

using editor::CommandId;

/// "Joint 3: smooth" and the three conversions; a hint when no joint is selected.
void joint_row(ViewerState& s, editor::CommandTable& commands) {
  const int joint = selected_joint(s);
  if (joint < 0) {
    ImGui::TextDisabled("select a joint or a handle to see its type");
    return;
  }
  const std::string type(editor::joint_type_label(selected_joint_type(s)));
  ImGui::Text("Joint %d: %s", joint, type.c_str());
  mark_item(s, "joint type");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "A joint's handles move with it; a smooth joint keeps its handles in line, a symmetric one\n"
        "also equally long. Hold Alt while dragging to break the rule for that drag.");
  const std::pair<CommandId, const char*> buttons[] = {
      {CommandId::JointCorner, "Corner"}, {CommandId::JointSmooth, "Smooth"}, {CommandId::JointSymmetric, "Symmetric"}};
  for (const auto& [id, text] : buttons) {
    ImGui::SameLine();
    command_button(commands, id, text);
    mark_item(s, text);
  }
}

/// The snap toggles: what a dragged point snaps to besides the grid (each a command).
void snap_toggles(ViewerState& s) {
  editor::SnapOptions& snap = s.curve_editing.snap;
  ImGui::TextUnformatted("Snap to");
  const std::pair<bool*, const char*> toggles[] = {
      {&snap.points, "points"}, {&snap.curves, "curves"}, {&snap.axis, "axis"}};
  for (const auto& [on, text] : toggles) {
    ImGui::SameLine();
    ImGui::Checkbox(text, on);
    mark_item(s, std::string("snap ") + text);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "A dragged point snaps to other control points, to the samples of other curves and to the\n"
          "y axis (x = 0) within a few pixels; a ring shows where. Hold Ctrl to drag without snapping.");
  }
}

}  // namespace

void curve_tools(ViewerState& s, editor::CommandTable& commands, int index) {
  const ObjectKind kind = s.doc().objects[std::size_t(index)].kind();
  if (kind == ObjectKind::Bezier2 || kind == ObjectKind::Bezier3) joint_row(s, commands);
  if (has_editable_points(kind)) snap_toggles(s);
}

}  // namespace sweep::viewer::panels
