// The selected curve's control points: snapping, a table of coordinates, and the edits of its
// kind (split/join Bezier pieces, insert/delete B-spline points).
#include "app/viewer/panels/number_field.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"
#include "model/edit/edit.hpp"

#include <imgui.h>

#include <algorithm>
#include <vector>

namespace sweep::viewer::panels {
namespace {

using editor::CommandId;

void drag_hint_and_snap(const PointTableParts& s, bool planar) {
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("Drag the handles in the view%s. Hold X or Y to move along one axis.",
                     planar ? " (2D points stay in the xy-plane)" : " (in the plane facing you; Z too)");
  ImGui::PopStyleColor();
  ImGui::Checkbox("Snap to grid", &s.snap);
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  const auto draw = [](double& value) {
    return ImGui::DragScalar("##grid", ImGuiDataType_Double, &value, float(0.01 * value), nullptr, nullptr, "%.4g",
                             ImGuiSliderFlags_NoRoundToFormat | ImGuiSliderFlags_NoInput);
  };
  setting_field(s, {"##grid", "grid size", s.snap_size, false, "grid"}, draw, [&s](double size) {
    if (!(size > 0.0)) return std::string("the grid size must be more than 0");
    s.snap_size = size;
    return std::string();
  });
}

/// One row: the point's number (selects it) and its coordinates, each an undoable number field
/// (dragged, or typed after a double-click or Ctrl+click).
void point_row(const PointTableParts& s, int index, int row, int dims, const std::vector<int>& partners) {
  ImGui::TableNextRow();
  ImGui::PushID(row);
  ImGui::TableSetColumnIndex(0);
  const bool chosen = std::find(partners.begin(), partners.end(), row) != partners.end();
  if (ImGui::Selectable(std::to_string(row).c_str(), chosen)) s.selection().point = row;
  const glm::dvec3 current = s.doc().objects[std::size_t(index)].as<PointsPart>().points[std::size_t(row)];
  for (int axis = 0; axis < dims; ++axis) {
    ImGui::TableSetColumnIndex(axis + 1);
    ImGui::PushID(axis);
    ImGui::SetNextItemWidth(-1.0f);
    const std::string name = std::string(1, "xyz"[axis]) + " of point " + std::to_string(row);
    const NumberField field{"##v", name, current[axis], false, "point " + std::to_string(row) + " " + "xyz"[axis]};
    const auto draw = [&s, row](double& value) {
      const bool moved = ImGui::DragScalar("##v", ImGuiDataType_Double, &value, 0.005f, nullptr, nullptr, "%.6g",
                                           ImGuiSliderFlags_NoRoundToFormat | ImGuiSliderFlags_NoInput);
      if (ImGui::IsItemActivated()) s.selection().point = row;
      return moved;
    };
    number_field(s, field, draw, "move point", [index, row, axis, current](double value) {
      glm::dvec3 moved = current;
      moved[axis] = value;
      return [index, row, moved](Document& d) { return move_point(d, index, row, moved); };
    });
    ImGui::PopID();
  }
  ImGui::PopID();
}

void table(const PointTableParts& s, int index, int dims) {
  const Object& object = s.doc().objects[std::size_t(index)];
  const int count = int(object.as<PointsPart>().points.size());
  const float height = std::min(12.5f, float(count) + 1.5f) * ImGui::GetFrameHeightWithSpacing();
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_ScrollY |
                                ImGuiTableFlags_SizingStretchProp;
  if (!ImGui::BeginTable("points", dims + 1, flags, ImVec2(0.0f, height))) return;
  ImGui::TableSetupScrollFreeze(0, 1);
  ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_WidthFixed, 28.0f * ImGui::GetIO().FontGlobalScale + 10.0f);
  ImGui::TableSetupColumn("x");
  ImGui::TableSetupColumn("y");
  if (dims == 3) ImGui::TableSetupColumn("z");
  ImGui::TableHeadersRow();
  const int point = s.selection().point;
  const std::vector<int> partners = point >= 0 && point < count ? seam_partners(object, point) : std::vector<int>{};
  ImGuiListClipper clipper;
  clipper.Begin(count);
  while (clipper.Step()) {
    for (int row = clipper.DisplayStart; row < clipper.DisplayEnd; ++row) point_row(s, index, row, dims, partners);
  }
  ImGui::EndTable();
}

void bezier_edits(const PointTableParts& s, editor::CommandTable& commands, int index) {
  const int count = int(s.doc().objects[std::size_t(index)].as<PointsPart>().points.size());
  const int point = s.selection().point;
  const bool has_point = point >= 0 && point < count;
  const int pieces = int(piece_count(s.doc().objects[std::size_t(index)].kind(), count));
  const int piece = has_point ? std::clamp(point / 3, 0, std::max(0, pieces - 1)) : 0;
  ImGui::SetNextItemWidth(120.0f);
  setting_field(s, {"##t", "t", s.split_t, false, "split t"}, float_slider("##t", 0.01f, 0.99f, "t=%.2f"),
                [&s](double t) {
                  if (!(t > 0.0 && t < 1.0)) return std::string("t must be between 0 and 1 (a point inside the piece)");
                  s.split_t = t;
                  return std::string();
                });
  ImGui::SameLine();
  if (ImGui::Button(("Split piece " + std::to_string(piece)).c_str())) {
    const double t = s.split_t;
    if (run_edit(s, "split piece", [index, piece, t](Document& d) { return split_bezier_piece(d, index, piece, t); })) {
      s.selection().point = 3 * piece + 3;  // the new joint
    }
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("de Casteljau: the curve keeps its shape, the piece becomes two");
  const bool joint = has_point && point % 3 == 0 && point > 0 && point < count - 1;
  ImGui::SameLine();
  if (!joint) ImGui::BeginDisabled();
  if (ImGui::Button("Join at joint") &&
      run_edit(s, "join pieces", [index, point](Document& d) { return join_bezier_pieces(d, index, point); })) {
    s.selection().point = point - 1;
  }
  if (!joint) ImGui::EndDisabled();
  if (!has_point) return;
  ImGui::SameLine();
  command_button(commands, CommandId::DeletePoint, "Delete");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Deleting a joint joins its pieces");
}

}  // namespace

void point_table(const PointTableParts& s, editor::CommandTable& commands, int index) {
  const ObjectKind kind = s.doc().objects[std::size_t(index)].kind();
  const bool planar = is_planar_curve(kind);
  drag_hint_and_snap(s, planar);
  table(s, index, planar ? 2 : 3);
  if (point_layout(kind).has_joints()) {
    bezier_edits(s, commands, index);
    return;
  }
  command_button(commands, CommandId::InsertPoint, "Insert after");
  ImGui::SameLine();
  command_button(commands, CommandId::DeletePoint, "Delete point");
}

}  // namespace sweep::viewer::panels
