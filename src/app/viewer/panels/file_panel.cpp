// File: the current file, open (path field, recent files, drop), save, OBJ export, PNG.
#include "app/viewer/actions.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>

namespace sweep::viewer::panels {
namespace {

void open_controls(ViewerState& s, editor::CommandTable& commands) {
  TextField& field = s.fields.open;
  bool open = ImGui::InputText("##open", field.text.data(), field.text.size(), ImGuiInputTextFlags_EnterReturnsTrue);
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

}  // namespace

void file_panel(ViewerState& s, editor::CommandTable& commands) {
  using editor::CommandId;
  if (!ImGui::CollapsingHeader("File", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const std::string& file = s.session.file();
  ImGui::TextDisabled("%s%s", file.empty() ? "(no file)" : file.c_str(),
                      s.session.dirty() ? "  (unsaved changes)" : "");
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
  ImGui::Separator();
  ImGui::InputText("##export", s.fields.export_prefix.text.data(), s.fields.export_prefix.text.size());
  ImGui::SameLine();
  command_button(commands, CommandId::ExportObj);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Writes PREFIX_NAME.obj for every named surface");
  ImGui::InputText("##screenshot", s.fields.screenshot.text.data(), s.fields.screenshot.text.size());
  ImGui::SameLine();
  command_button(commands, CommandId::SavePng);
  if (!s.status.empty()) ImGui::TextWrapped("%s", s.status.c_str());
}

}  // namespace sweep::viewer::panels
