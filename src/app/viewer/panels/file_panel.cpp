// File: the current file, open (path field, recent files, drop) and save; Export and PNGs (closed
// until opened: rarer than opening and creating): OBJ, STL, glb, SVG and PNGs (of the view, of the
// window), beside the SWP file.
#include "app/viewer/actions.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <tuple>

namespace sweep::viewer::panels {
namespace {

void open_controls(ViewerState& s, editor::CommandTable& commands) {
  TextField& field = s.fields.open;
  bool open = ImGui::InputText("##open", field.text.data(), field.text.size(),
                               ImGuiInputTextFlags_EnterReturnsTrue | kTextFieldFlags);
  ImGui::SameLine();
  open |= ImGui::Button("Open");
  if (open) commands.run(editor::CommandId::Open);
  command_button(commands, editor::CommandId::OpenBrowser);
  if (!s.recent.empty() && ImGui::TreeNode("Recent files")) {
    std::string chosen;
    for (const std::string& path : s.recent) {
      if (ImGui::Selectable(path.c_str())) chosen = path;
    }
    ImGui::TreePop();
    if (!chosen.empty()) request_open(s, chosen);
  }
  ImGui::TextDisabled("or drop a .swp file onto the window");
}

/// A full-width name field with `tooltip`.
void name_field(TextField& field, const char* id, const char* tooltip) {
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::InputText(id, field.text.data(), field.text.size(), kTextFieldFlags);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
}

/// A command button on the current line, marked for scripted tests as `mark`, with the
/// command's full label as its tooltip.
void output_button(ViewerState& s, editor::CommandTable& commands, editor::CommandId id, const std::string& text,
                   const char* mark) {
  command_button(commands, id, text);
  mark_item(s, mark);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(commands.get(id).label).c_str());
}

/// One finding, wrapped to the panel's width (a warning in the status bar's warning colour, a
/// note dimmed): a click selects the surface it names, if it is still there.
void finding_row(ViewerState& s, const PrintFindingRow& row) {
  const float width = ImGui::GetContentRegionAvail().x;
  const ImVec2 size = ImGui::CalcTextSize(row.shown.c_str(), nullptr, false, width);
  const ImVec2 at = ImGui::GetCursorPos();
  if (ImGui::Selectable("##finding", s.selection.object == row.object, 0, ImVec2(width, size.y))) {
    if (s.session.index_of(row.object) >= 0) s.selection.select(row.object);
  }
  const ImVec2 after = ImGui::GetCursorPos();
  ImGui::SetCursorPos(at);
  ImGui::PushStyleColor(ImGuiCol_Text, row.fails ? kWarningText : ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::PushTextWrapPos(at.x + width);
  ImGui::TextUnformatted(row.shown.c_str());
  ImGui::PopTextWrapPos();
  ImGui::PopStyleColor();
  ImGui::SetCursorPos(after);
}

/// The print height field, the 3MF button and the last print export's findings: a click on one
/// selects the surface it names.
void print_controls(ViewerState& s, editor::CommandTable& commands) {
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("Print");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.0f);
  if (ImGui::InputDouble("mm tall##print-height", &s.fields.print_height_mm, 0.0, 0.0, "%.1f")) {
    s.fields.print_height_mm = std::clamp(s.fields.print_height_mm, 0.0, 100000.0);
  }
  mark_item(s, "print-height");
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("3MF and STL: the printed model's height in millimetres (0: 1 model unit = 1 mm)");
  }
  ImGui::SameLine();
  output_button(s, commands, editor::CommandId::Export3mf, "3MF", "export-3mf");
  const PrintFindings& findings = s.print_findings;
  if (findings.file.empty()) return;
  if (findings.rows.empty()) {
    ImGui::TextDisabled("%s: printable, every check passed", std::filesystem::path(findings.file).filename().c_str());
    return;
  }
  ImGui::TextDisabled("Printability of %s (click to select):", std::filesystem::path(findings.file).filename().c_str());
  for (std::size_t k = 0; k < findings.rows.size(); ++k) {
    ImGui::PushID(static_cast<int>(k));
    finding_row(s, findings.rows[k]);
    mark_item(s, ("print-finding-" + std::to_string(k)).c_str());
    ImGui::PopID();
  }
}

/// Exports and PNGs: the folder they go to, the prefix and name fields (relative to that folder,
/// or absolute), and the buttons.
void output_controls(ViewerState& s, editor::CommandTable& commands) {
  using editor::CommandId;
  ImGui::TextDisabled("Exports and PNGs go into");
  ImGui::TextWrapped("%s", output_folder(s).string().c_str());
  name_field(s.fields.export_prefix, "##export",
             "PREFIX: every named surface is written as PREFIX_NAME.obj (.stl, .glb), the planar curves as "
             "PREFIX.svg, in the folder above; "
             "an absolute path is used as it is");
  mark_item(s, "export-prefix");
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("Export as");
  for (const auto& [id, text, mark] :
       {std::tuple(CommandId::ExportObj, "OBJ", "export-obj"), std::tuple(CommandId::ExportStl, "STL", "export-stl"),
        std::tuple(CommandId::ExportGlb, "glb", "export-glb"),
        std::tuple(CommandId::ExportGlbQuantized, "glb (quantized)", "export-glb-quantized"),
        std::tuple(CommandId::ExportSvg, "SVG", "export-svg")}) {
    ImGui::SameLine();
    output_button(s, commands, id, text, mark);
  }
  print_controls(s, commands);
  name_field(s.fields.screenshot, "##screenshot", "NAME.png in the folder above (an absolute path is used as it is)");
  mark_item(s, "png-name");
  ImGui::AlignTextToFramePadding();
  ImGui::TextUnformatted("Save PNG of");
  ImGui::SameLine();
  output_button(s, commands, CommandId::SavePng, "the view", "png-view");
  ImGui::SameLine();
  output_button(s, commands, CommandId::SaveWindowPng, "the window", "png-window");
}

}  // namespace

void file_panel(ViewerState& s, editor::CommandTable& commands) {
  using editor::CommandId;
  if (!ImGui::CollapsingHeader("File", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const std::string& file = s.session.file();
  // Wrapped: a long path and "(unsaved changes)" are not cut off at the panel's edge.
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
  ImGui::TextWrapped("%s%s", file.empty() ? "(no file)" : file.c_str(), s.session.dirty() ? "  (unsaved changes)" : "");
  ImGui::PopStyleColor();
  open_controls(s, commands);
  command_button(commands, CommandId::Save);
  ImGui::SameLine();
  command_button(commands, CommandId::SaveAs);
  if (ImGui::Checkbox("Reload when changed on disk", &s.safety.live_reload)) {
    s.safety.watcher.watch(s.safety.live_reload ? file : std::string());
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip("Saved in another editor: the viewer reloads the file within half a second, keeping the view");
  }
}

void export_panel(ViewerState& s, editor::CommandTable& commands) {
  const bool open = ImGui::CollapsingHeader("Export and PNGs");
  mark_item(s, "export-panel");  // where scripted tests open it
  if (open) output_controls(s, commands);
}

}  // namespace sweep::viewer::panels
