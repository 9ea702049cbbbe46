// The Open and Save As file browser: the folder's sub-folders and .swp files (editor::FileBrowser
// holds the listing and the highlight), typing filters them, Up/Down move the highlight, Enter
// opens a folder or picks a file, Backspace with nothing typed goes up.
#include "app/viewer/actions.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>

namespace sweep::viewer::panels {
namespace {

const ImVec4 kErrorColour(1.0f, 0.45f, 0.4f, 1.0f);

bool pressed(ImGuiKey key) {
  return ImGui::IsKeyPressed(ImGui::GetKeyIndex(key));
}

/// The keys of the browser while its window has the focus and no other text field is being typed
/// in (Backspace and Enter in the name field are the field's). Returns a file picked by Enter, or "".
std::string browser_keys(editor::FileBrowser& b, bool typing_elsewhere) {
  if (!ImGui::IsWindowFocused(ImGuiFocusedFlags_RootAndChildWindows) || typing_elsewhere) return {};
  if (pressed(ImGuiKey_DownArrow)) b.move(1);
  if (pressed(ImGuiKey_UpArrow)) b.move(-1);
  if (pressed(ImGuiKey_Backspace) && b.filter().empty()) b.go_up();
  if (pressed(ImGuiKey_Enter) || pressed(ImGuiKey_KeyPadEnter)) return b.activate();
  return {};
}

}  // namespace

BrowserPick browser_list(ViewerState& s, TextField& filter) {
  editor::FileBrowser& b = s.browser;
  BrowserPick pick;
  ImGui::TextDisabled("%s", b.folder().string().c_str());
  if (s.item_positions != nullptr) mark_item(s, "browser-folder " + b.folder().string());
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::IsWindowAppearing()) {
    filter.set("");
    ImGui::SetKeyboardFocusHere();
  }
  if (ImGui::InputTextWithHint("##filter", "type to filter", filter.text.data(), filter.text.size(), kTextFieldFlags)) {
    b.set_filter(filter.get());
  }
  const bool typing_elsewhere = ImGui::IsAnyItemActive() && !ImGui::IsItemActive();
  pick.file = browser_keys(b, typing_elsewhere);
  pick.activated = !pick.file.empty();
  const float rows = 12.0f;
  ImGui::BeginChild(
      "##entries", ImVec2(480.0f * ImGui::GetIO().FontGlobalScale, ImGui::GetTextLineHeightWithSpacing() * rows), true);
  if (ImGui::Selectable("../", false, ImGuiSelectableFlags_AllowDoubleClick) && ImGui::IsMouseDoubleClicked(0)) {
    b.go_up();
  }
  const auto& entries = b.entries();
  for (int i = 0; i < static_cast<int>(entries.size()); ++i) {
    const editor::BrowserEntry& e = entries[static_cast<std::size_t>(i)];
    const std::string label = e.folder ? e.name + "/" : e.name;
    const bool highlighted = i == b.highlighted();
    const bool clicked = ImGui::Selectable(label.c_str(), highlighted, ImGuiSelectableFlags_AllowDoubleClick);
    if (s.item_positions != nullptr) mark_item(s, "browser " + label);
    if (clicked) {
      b.highlight(i);
      const bool twice = ImGui::IsMouseDoubleClicked(0);
      if (twice || !e.folder) {
        pick.file = b.activate(i);  // a folder is entered (""), a file's path returned
        pick.activated = twice && !pick.file.empty();
        break;
      }
    }
    if (highlighted && ImGui::IsWindowAppearing()) ImGui::SetScrollHereY();
  }
  if (!b.error().empty()) ImGui::TextColored(kErrorColour, "%s", b.error().c_str());
  ImGui::EndChild();
  return pick;
}

void file_browser(ViewerState& s) {
  constexpr const char* kName = "Open a file";
  if (s.browser_for == BrowserPurpose::Open && !ImGui::IsPopupOpen(kName)) ImGui::OpenPopup(kName);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal(kName, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  const BrowserPick pick = browser_list(s, s.fields.browser_filter);
  TextField& path = s.fields.open;
  if (!pick.file.empty()) path.set(pick.file);
  std::string picked = pick.activated ? pick.file : std::string();
  ImGui::SetNextItemWidth(480.0f * ImGui::GetIO().FontGlobalScale);
  if (ImGui::InputText("##path", path.text.data(), path.text.size(),
                       ImGuiInputTextFlags_EnterReturnsTrue | kTextFieldFlags)) {
    picked = s.browser.go_to(path.get());
  }
  if (ImGui::Button("Open") && picked.empty()) picked = s.browser.go_to(path.get());
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel") ||
                      (!ImGui::IsWindowAppearing() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)));
  if (!picked.empty()) request_open(s, picked);
  if (!picked.empty() || cancel) {
    s.browser_for = BrowserPurpose::None;
    ImGui::CloseCurrentPopup();
  }
  ImGui::EndPopup();
}

}  // namespace sweep::viewer::panels
