#include "app/viewer/panels/panel_support.hpp"

#include "app/viewer/item_positions.hpp"

#include <imgui.h>

#include <algorithm>
#include <cctype>

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

std::string mark_name(std::string_view label) {
  std::string out;
  for (const char ch : label) {
    const auto c = static_cast<unsigned char>(ch);
    if (std::isalnum(c)) {
      out.push_back(char(std::tolower(c)));
    } else if (!out.empty() && out.back() != '-') {
      out.push_back('-');
    }
  }
  while (!out.empty() && out.back() == '-') out.pop_back();
  return out;
}

void marked_combo(ItemPositions* positions, const char* label, const std::vector<std::string_view>& labels, int& choice,
                  const std::string& prefix) {
  choice = std::clamp(choice, 0, int(labels.size()) - 1);
  const std::string preview(labels[std::size_t(choice)]);
  const bool open = ImGui::BeginCombo(label, preview.c_str(), ImGuiComboFlags_HeightLargest);
  mark_item(positions, prefix);
  if (!open) return;
  for (std::size_t i = 0; i < labels.size(); ++i) {
    const std::string text(labels[i]);
    if (ImGui::Selectable(text.c_str(), int(i) == choice)) choice = int(i);
    mark_item(positions, prefix + "-" + mark_name(labels[i]));
  }
  ImGui::EndCombo();
}

}  // namespace sweep::viewer::panels
