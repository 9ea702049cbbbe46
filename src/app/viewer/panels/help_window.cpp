// The Help window (F1): every command of the table once, with all its keys, in the order of the
// menus, then the mouse. Built from the command table, so a new command or key shows here without
// a second list. As tall as the window allows, and it scrolls.
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <cfloat>
#include <string>
#include <vector>

namespace sweep::viewer::panels {
namespace {

/// What the mouse does in the view (input.cpp), as the README's mouse table says it.
constexpr const char* kMouse[][2] = {
    {"left drag", "rotate (arcball); in the profile view: pan"},
    {"right drag / wheel", "zoom"},
    {"middle drag", "pan"},
    {"left click", "select a curve, or grab a handle of the selected curve"},
    {"with the pen (B): click / drag", "put down a point / a joint with handles; click the first point to close"},
    {"X / Y / Z held while dragging a handle", "move it along that axis only"},
    {"Shift+click a handle", "add it to the selected points, or take it out"},
    {"Shift+drag", "select the handles inside the rectangle (of the selected curve)"},
    {"drag a selected handle", "move every selected point with it"},
    {"Alt held while dragging", "move the point alone (a Bezier joint's rule is broken)"},
    {"Ctrl held while dragging", "no snapping to points, curves or the axis"},
    {"double-click on the selected curve", "insert a point there"},
    {"G / R / E, then move", "grab, rotate, scale; X/Y/Z, a number, Enter or click; Esc cancels"},
    {"drag / wheel while riding along", "leave the ride and orbit from where the camera is"},
};

/// The commands in the order of the menus (File, Edit, View, Help; the File panel's Open of a
/// typed path beside Open...). A command missing here comes after them, in the table's order.
std::vector<editor::CommandId> menu_order() {
  using enum editor::CommandId;
  return {// File
          New, OpenBrowser, Open, Save, SaveAs, DesktopFileDialogs, ExportObj, ExportStl, ExportGlb, ExportGlbQuantized,
          Export3mf, ExportSvg, SavePng, SaveWindowPng, Quit,
          // Edit
          Undo, Redo, Pen, InsertPoint, ConvertToBezier, ConvertToHermite, ConvertToBSpline, ConvertToCatmullRom,
          DeletePoint, SelectAllPoints, Grab, Rotate, Scale, MirrorX, MirrorY, MirrorZ, SnapSelectionToGrid,
          JointCorner, JointSmooth, JointSymmetric, SnapToPoints, SnapToCurves, SnapToAxis,
          // View
          CycleSurfaces, ToggleNormals, CycleCurves, TogglePoints, ToggleGrid, ToggleComb, ProfileView, FrameSelection,
          FrameAll, ResetCamera, ViewFront, ViewTop, ViewSide, PlayPause,
          // Help
          Help};
}

/// The rows as a table of two columns; the last row's keys are marked `last` for scripts.
void table(const HelpParts& s, const char* id, const std::vector<HelpRow>& rows, const char* last = nullptr) {
  if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerV))
    return;
  for (const HelpRow& row : rows) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(row.keys.c_str());
    if (last != nullptr && &row == &rows.back()) mark_item(s.item_positions, last);
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(row.does.c_str());
  }
  ImGui::EndTable();
}

}  // namespace

std::vector<HelpRow> help_rows(const editor::CommandTable& commands) {
  // Each command once, whatever the list says.
  std::vector<editor::CommandId> order;
  const auto add = [&order](editor::CommandId id) {
    if (std::find(order.begin(), order.end(), id) == order.end()) order.push_back(id);
  };
  for (editor::CommandId id : menu_order()) add(id);
  for (const editor::Command& command : commands.commands()) add(command.id);
  std::vector<HelpRow> rows;
  for (editor::CommandId id : order) {
    const std::string keys = commands.all_shortcuts_label(id);
    rows.push_back({keys.empty() ? "-" : keys, std::string(commands.get(id).label)});
  }
  return rows;
}

std::vector<HelpRow> mouse_help_rows() {
  std::vector<HelpRow> rows;
  for (const auto& [does, what] : kMouse) rows.push_back({does, what});
  return rows;
}

void help_window(const HelpParts& s, const editor::CommandTable& commands) {
  if (!s.show_help) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float top = 48.0f * s.layout.ui_scale;
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + float(s.layout.free_left()) + 24.0f, viewport->WorkPos.y + top),
                          ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(660.0f * s.layout.ui_scale, 0.0f), ImGuiCond_Appearing);
  // No taller than the room above the status bar, so its lower edge and scroll bar stay in the
  // window (the commands and the mouse are taller than most windows): the rest scrolls.
  const float room = viewport->WorkSize.y - top - s.layout.status_height - s.layout.margin;
  ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(FLT_MAX, std::max(120.0f, room)));
  if (!ImGui::Begin("Help", &s.show_help, ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  mark_window(s.item_positions, "help");
  ImGui::TextDisabled("Every command, as the menus and keys run it");
  table(s, "##commands", help_rows(commands));
  ImGui::Separator();
  ImGui::TextDisabled("The mouse in the view");
  table(s, "##mouse", mouse_help_rows(), "help-last-row");  // scripts scroll until it shows
  ImGui::End();
}

}  // namespace sweep::viewer::panels
