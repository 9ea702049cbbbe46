#include "app/viewer/panels/panel_support.hpp"

#include "app/viewer/item_positions.hpp"

#include <imgui.h>

#include <algorithm>

namespace sweep::viewer::panels {

void command_button(editor::CommandTable& commands, editor::CommandId id, const std::string& text) {
  const bool enabled = commands.enabled(id);
  const std::string label = text.empty() ? commands.button_label(id) : with_shortcut(commands, id, text);
  if (!enabled) ImGui::BeginDisabled();
  if (ImGui::Button(label.c_str())) commands.run(id);
  if (!enabled) ImGui::EndDisabled();
}

void command_menu_item(editor::CommandTable& commands, editor::CommandId id, const std::string& text, bool checked) {
  const std::string label = text.empty() ? std::string(commands.get(id).label) : text;
  const std::string shortcut = commands.shortcut_label(id);
  if (ImGui::MenuItem(label.c_str(), shortcut.empty() ? nullptr : shortcut.c_str(), checked, commands.enabled(id))) {
    commands.run(id);
  }
}

std::string with_shortcut(const editor::CommandTable& commands, editor::CommandId id, const std::string& text) {
  const std::string shortcut = commands.shortcut_label(id);
  return shortcut.empty() ? text : text + " [" + shortcut + "]";
}

bool curve_combo(const Document& doc, const char* label, const std::vector<int>& candidates, int& choice,
                 const char* none) {
  if (std::find(candidates.begin(), candidates.end(), choice) == candidates.end()) {
    choice = none || candidates.empty() ? -1 : candidates.front();
  }
  const std::string preview = choice >= 0 ? display_name(doc, choice) : none ? none : "(no curve)";
  if (!ImGui::BeginCombo(label, preview.c_str())) return false;
  bool chosen = false;
  if (none && ImGui::Selectable(none, choice < 0)) {
    choice = -1;
    chosen = true;
  }
  for (int i : candidates) {
    if (ImGui::Selectable(display_name(doc, i).c_str(), i == choice)) {
      choice = i;
      chosen = true;
    }
  }
  ImGui::EndCombo();
  return chosen;
}

void mark_item(ItemPositions* positions, std::string_view name) {
  if (positions == nullptr) return;
  const float box = ImGui::GetFrameHeight();
  const ImVec2 corner = ImGui::GetItemRectMin();
  positions->mark(name, glm::vec2(corner.x + 0.5f * box, corner.y + 0.5f * box));
}

void mark_window(ItemPositions* positions, std::string_view name) {
  if (positions == nullptr) return;
  const ImVec2 corner = ImGui::GetWindowPos();
  positions->mark(name, glm::vec2(corner.x, corner.y + ImGui::GetWindowSize().y));
}

}  // namespace sweep::viewer::panels
