// The Help window (F1): every command of the table with all its keys, then the mouse. Built from
// the command table, so a new command or key shows here without a second list.
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>

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

/// The rows as a table of two columns.
void table(const char* id, const std::vector<HelpRow>& rows) {
  if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_BordersInnerV))
    return;
  for (const HelpRow& row : rows) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(row.keys.c_str());
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(row.does.c_str());
  }
  ImGui::EndTable();
}

}  // namespace

std::vector<HelpRow> help_rows(const editor::CommandTable& commands) {
  std::vector<HelpRow> rows;
  for (const editor::Command& command : commands.commands()) {
    const std::string keys = commands.all_shortcuts_label(command.id);
    rows.push_back({keys.empty() ? "-" : keys, std::string(command.label)});
  }
  return rows;
}

std::vector<HelpRow> mouse_help_rows() {
  std::vector<HelpRow> rows;
  for (const auto& [does, what] : kMouse) rows.push_back({does, what});
  return rows;
}

void help_window(ViewerState& s, const editor::CommandTable& commands) {
  if (!s.show_help) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(
      ImVec2(viewport->WorkPos.x + float(s.layout.free_left()) + 24.0f, viewport->WorkPos.y + 48.0f),
      ImGuiCond_Appearing);
  ImGui::SetNextWindowSize(ImVec2(660.0f, 0.0f), ImGuiCond_Appearing);
  if (!ImGui::Begin("Help", &s.show_help, ImGuiWindowFlags_NoCollapse)) {
    ImGui::End();
    return;
  }
  mark_window(s, "help");
  ImGui::TextDisabled("Every command, as the menus and keys run it");
  table("##commands", help_rows(commands));
  ImGui::Separator();
  ImGui::TextDisabled("The mouse in the view");
  table("##mouse", mouse_help_rows());
  ImGui::End();
}

}  // namespace sweep::viewer::panels
