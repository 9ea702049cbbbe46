// The selected curve's editing tools, under its point table: the selected Bezier joint's type
// and its conversions, the curvature comb with its plot, the points selected together and the
// snap toggles. Every button is a command of the table.
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"
#include "app/viewer/panels/value_slider.hpp"
#include "app/viewer/selected_curve.hpp"

#include <imgui.h>

#include <cfloat>
#include <string>
#include <vector>

namespace sweep::viewer::panels {
namespace {

using editor::CommandId;

/// A command's button labelled `text` alone, its keys in the tooltip (where a row is narrow).
void compact_button(editor::CommandTable& commands, CommandId id, const char* text) {
  const bool enabled = commands.enabled(id);
  ImGui::BeginDisabled(!enabled);
  if (ImGui::Button(text)) commands.run(id);
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("%s [%s]", std::string(commands.get(id).label).c_str(), commands.shortcut_label(id).c_str());
}

/// "Joint 3: smooth" and the three conversions; a hint when no joint is selected.
void joint_row(const CurveToolParts& s, editor::CommandTable& commands) {
  const int joint = selected_joint(s.session(), s.selection());
  if (joint < 0) {
    ImGui::TextDisabled("select a joint or a handle to see its type");
    return;
  }
  const std::string type(editor::joint_type_label(selected_joint_type(s.session(), s.selection(), s.editing)));
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
    compact_button(commands, id, text);
    mark_item(s, text);
  }
}

/// The joints on the plot: thin lines at their share of the curve's length.
void mark_joints(const editor::CurvatureComb& comb, const ImVec2& low, const ImVec2& high) {
  const double total = comb.arc_length.empty() ? 0.0 : comb.arc_length.back();
  if (!(total > 0.0)) return;
  ImDrawList* draw = ImGui::GetWindowDrawList();
  for (double at : comb.joint_arc_lengths) {
    const float x = low.x + float(at / total) * (high.x - low.x);
    draw->AddLine(ImVec2(x, low.y), ImVec2(x, high.y), IM_COL32(255, 190, 60, 160));
  }
}

/// The curvature comb's toggle and scale, and a plot of the curvature along the curve.
void comb_section(const CurveToolParts& s, editor::CommandTable& commands) {
  bool on = s.editing.comb;
  if (ImGui::Checkbox(with_shortcut(commands, CommandId::ToggleComb, "Curvature comb").c_str(), &on)) {
    commands.run(CommandId::ToggleComb);
  }
  mark_item(s, "comb");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Needles across the curve, as long as its curvature (from the exact derivatives), pointing\n"
        "away from the bend; their tips joined. A jump at a joint breaks the line.");
  const editor::CurvatureComb* comb = selected_comb(s.session(), s.selection(), s.views(), s.editing);
  if (comb == nullptr) return;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  float factor = float(s.editing.comb_scale);
  if (value_slider_float("##comb scale", &factor, 0.1f, 10.0f, "scale %.2f", ImGuiSliderFlags_Logarithmic)) {
    s.editing.comb_scale = double(factor);
    comb = selected_comb(s.session(), s.selection(), s.views(), s.editing);
  }
  const std::vector<float> plot = editor::curvature_plot(*comb, 160);
  if (plot.empty()) return;
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::PlotLines("##curvature", plot.data(), int(plot.size()), 0, "curvature along the curve", FLT_MAX, FLT_MAX,
                   ImVec2(0.0f, 60.0f));  // width 0: the item width
  mark_joints(*comb, ImGui::GetItemRectMin(), ImGui::GetItemRectMax());
}

/// How many points are selected, and the transforms of several: Grab, Rotate, Scale, Mirror.
void selection_row(const CurveToolParts& s, editor::CommandTable& commands) {
  const std::size_t count = s.selection().points().size();
  ImGui::Text("%zu point%s selected", count, count == 1 ? "" : "s");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Shift+click adds or removes a handle, Shift+drag selects the handles in a rectangle,\n"
        "A selects them all; drag one of them to move them together.");
  ImGui::SameLine();
  command_button(commands, CommandId::SelectAllPoints, "All");
  const std::pair<CommandId, const char*> transforms[] = {
      {CommandId::Grab, "Grab"}, {CommandId::Rotate, "Rotate"}, {CommandId::Scale, "Scale"}};
  for (const auto& [id, text] : transforms) {
    command_button(commands, id, text);
    ImGui::SameLine();
  }
  const int axes = is_planar_curve(s.doc().objects[std::size_t(s.selected())].kind()) ? 2 : 3;  // a 2D curve has no z
  // Beside them when it fits (a 2D curve's x and y do), else on a line of its own: never cut off
  // at the panel's edge.
  const ImGuiStyle& style = ImGui::GetStyle();
  const float button = ImGui::CalcTextSize("x").x + 2.0f * style.FramePadding.x;
  if (ImGui::GetContentRegionAvail().x < ImGui::CalcTextSize("Mirror").x + float(axes) * (style.ItemSpacing.x + button))
    ImGui::NewLine();
  ImGui::TextUnformatted("Mirror");
  for (int axis = 0; axis < axes; ++axis) {
    ImGui::SameLine();
    const CommandId id = CommandId(int(CommandId::MirrorX) + axis);
    command_button(commands, id, std::string(1, "xyz"[axis]));
  }
}

/// The snap toggles: what a dragged point snaps to besides the grid (each a command).
void snap_toggles(const CurveToolParts& s) {
  editor::SnapOptions& snap = s.editing.snap;
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

void curve_tools(const CurveToolParts& s, editor::CommandTable& commands, int index) {
  const ObjectKind kind = s.doc().objects[std::size_t(index)].kind();
  comb_section(s, commands);
  if (point_layout(kind).has_joints()) joint_row(s, commands);
  if (!has_editable_points(kind)) return;
  selection_row(s, commands);
  snap_toggles(s);
}

}  // namespace sweep::viewer::panels
