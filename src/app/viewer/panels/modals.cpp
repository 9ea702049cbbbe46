// The questions before work could be lost ("Unsaved changes": Save / Discard / Cancel) and the
// Save As path, shown as the editor's UnsavedChangesFlow says.
#include "app/viewer/actions.hpp"
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>

#include <filesystem>

namespace sweep::viewer::panels {
namespace {

using Stage = editor::UnsavedChangesFlow::Stage;
constexpr const char* kAskSave = "Unsaved changes";
constexpr const char* kAskPath = "Save as";
const ImVec4 kErrorColour(1.0f, 0.45f, 0.4f, 1.0f);

/// Cancel, by button or by Escape (not on the frame the question appears: the Escape that
/// asked it may still be down).
bool cancelled() {
  return ImGui::Button("Cancel") ||
         (!ImGui::IsWindowAppearing() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)));
}

void ask_save(ViewerState& s) {
  const std::string& file = s.session.file();
  ImGui::Text("%s has unsaved changes.",
              file.empty() ? "The document" : std::filesystem::path(file).filename().string().c_str());
  ImGui::Text(s.unsaved.action() == editor::PendingAction::Quit ? "Save them before quitting?"
                                                                : "Save them before opening another file?");
  if (!s.unsaved.error().empty()) ImGui::TextColored(kErrorColour, "%s", s.unsaved.error().c_str());
  if (ImGui::Button("Save")) {
    if (file.empty()) {
      s.fields.save_as.set("untitled.swp");
      s.unsaved.choose_save(false);  // the action runs after Save As succeeds
    } else {
      s.unsaved.choose_save(true);
      s.unsaved.saved(save_to(s, file), s.session.error());
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("Discard")) s.unsaved.choose_discard();
  ImGui::SameLine();
  if (cancelled()) s.unsaved.cancel();
  if (s.unsaved.stage() != Stage::AskSave) ImGui::CloseCurrentPopup();
}

void ask_path(ViewerState& s) {
  const float width = 480.0f * ImGui::GetIO().FontGlobalScale;
  ImGui::Text("Save the document as:");
  if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
  ImGui::SetNextItemWidth(width);
  TextField& field = s.fields.save_as;
  const bool enter =
      ImGui::InputText("##path", field.text.data(), field.text.size(), ImGuiInputTextFlags_EnterReturnsTrue);
  if (!s.unsaved.error().empty()) {
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
    ImGui::TextColored(kErrorColour, "%s", s.unsaved.error().c_str());
    ImGui::PopTextWrapPos();
  }
  if (ImGui::Button("Save") || enter) s.unsaved.saved(save_to(s, field.get()), s.session.error());
  ImGui::SameLine();
  if (cancelled()) s.unsaved.cancel();
  if (s.unsaved.stage() != Stage::AskPath) ImGui::CloseCurrentPopup();
}

/// Opens popup `name` while the flow is at `stage`, and runs `body` inside it.
void modal(ViewerState& s, Stage stage, const char* name, void (*body)(ViewerState&)) {
  if (s.unsaved.stage() == stage && !ImGui::IsPopupOpen(name)) ImGui::OpenPopup(name);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal(name, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  body(s);
  ImGui::EndPopup();
}

}  // namespace

void modals(ViewerState& s) {
  modal(s, Stage::AskSave, kAskSave, ask_save);
  modal(s, Stage::AskPath, kAskPath, ask_path);
}

}  // namespace sweep::viewer::panels
