// The questions before work could be lost ("Unsaved changes": Save / Discard / Cancel) and the
// Save As path, shown as the editor's UnsavedChangesFlow says.
#include "app/viewer/actions.hpp"
#include "app/viewer/dialog_actions.hpp"
#include "app/viewer/file_safety.hpp"
#include "app/viewer/panels/panel_support.hpp"
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
  ImGui::Text(s.unsaved.action() == editor::PendingAction::Quit  ? "Save them before quitting?"
              : s.unsaved.action() == editor::PendingAction::New ? "Save them before starting a new document?"
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
  if (ImGui::Button("Discard")) discard_changes(s);
  ImGui::SameLine();
  if (cancelled()) s.unsaved.cancel();
  if (s.unsaved.stage() != Stage::AskSave) ImGui::CloseCurrentPopup();
}

/// The Save As name field: a file name (or a path) taken relative to the folder the browser
/// shows, by the Save button and by Enter alike. Entering another folder keeps only the name, so
/// the file goes where the dialog shows. Returns the file to save to, or "" (a folder was typed:
/// it is shown instead; or nothing was typed).
std::string save_as_target(ViewerState& s) {
  TextField& field = s.fields.save_as;
  const std::string target = s.browser.go_to(field.get());
  if (!target.empty()) field.set(target);
  return target;
}

void ask_path(ViewerState& s) {
  const float width = 480.0f * ImGui::GetIO().FontGlobalScale;
  ImGui::Text("Save the document as:");
  TextField& field = s.fields.save_as;
  const std::filesystem::path shown = s.browser.folder();
  const BrowserPick pick = browser_list(s, s.fields.browser_filter);
  if (s.browser.folder() != shown) field.set(std::filesystem::path(field.get()).filename().string());
  if (!pick.file.empty()) field.set(pick.file);
  ImGui::SetNextItemWidth(width);
  const bool enter = ImGui::InputText("##path", field.text.data(), field.text.size(),
                                      ImGuiInputTextFlags_EnterReturnsTrue | kTextFieldFlags);
  mark_item(s, "save-as-name");
  if (!s.unsaved.error().empty()) {
    ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + width);
    ImGui::TextColored(kErrorColour, "%s", s.unsaved.error().c_str());
    ImGui::PopTextWrapPos();
  }
  const bool save = ImGui::Button("Save");
  mark_item(s, "save-as-save");
  if (save || enter || pick.activated) {
    const std::string target = pick.activated ? pick.file : save_as_target(s);
    if (!target.empty()) s.unsaved.saved(save_to(s, target), s.session.error());
  }
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

using Question = FileSafety::Question;

/// Enter answers a question with its first button.
bool enter_pressed() {
  return !ImGui::IsWindowAppearing() && (ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Enter)) ||
                                         ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_KeyPadEnter)));
}

void ask_recover(ViewerState& s) {
  const std::string& file = s.session.file();
  ImGui::Text("%s has unsaved edits from a session that did not end cleanly.",
              file.empty() ? "An untitled document" : std::filesystem::path(file).filename().string().c_str());
  ImGui::TextDisabled("copy: %s", s.safety.copy.string().c_str());
  static bool show = false;
  if (ImGui::Button("Recover") || enter_pressed()) recover_copy(s);
  ImGui::SameLine();
  if (ImGui::Button(file.empty() ? "Discard the copy" : "Open the saved file")) dismiss_copy(s);
  ImGui::SameLine();
  ImGui::Checkbox("Show the difference", &show);
  if (show) {
    if (s.safety.differences.empty()) ImGui::TextDisabled("(the same objects as the saved file)");
    for (const std::string& line : s.safety.differences) ImGui::BulletText("%s", line.c_str());
  }
  if (s.safety.question != Question::Recover) ImGui::CloseCurrentPopup();
}

void ask_reload(ViewerState& s) {
  ImGui::Text("%s changed on disk, and you have unsaved edits.",
              std::filesystem::path(s.session.file()).filename().string().c_str());
  // Enter keeps the edits: the safe answer.
  if (ImGui::Button("Keep mine") || enter_pressed()) keep_my_edits(s);
  ImGui::SameLine();
  if (ImGui::Button("Reload and discard mine")) reload_from_disk(s);
  if (s.safety.question != Question::Reload) ImGui::CloseCurrentPopup();
}

void ask_overwrite(ViewerState& s) {
  ImGui::Text("%s changed on disk since you kept your edits over it.",
              std::filesystem::path(s.session.file()).filename().string().c_str());
  ImGui::Text("Replace it with your version?");
  if (ImGui::Button("Overwrite") || enter_pressed()) overwrite_changed_file(s);  // Save was asked for
  ImGui::SameLine();
  if (cancelled()) s.safety.question = Question::None;
  if (s.safety.question != Question::Overwrite) ImGui::CloseCurrentPopup();
}

/// Opens popup `name` while the file-safety question is `question`, and runs `body` inside it.
void question(ViewerState& s, Question which, const char* name, void (*body)(ViewerState&)) {
  if (s.safety.question == which && !ImGui::IsPopupOpen(name)) ImGui::OpenPopup(name);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal(name, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  body(s);
  ImGui::EndPopup();
}

}  // namespace

void modals(ViewerState& s) {
  modal(s, Stage::AskSave, kAskSave, ask_save);
  if (!save_path_in_desktop_dialog(s)) modal(s, Stage::AskPath, kAskPath, ask_path);
  question(s, Question::Recover, "Recover unsaved edits", ask_recover);
  question(s, Question::Reload, "Changed on disk", ask_reload);
  question(s, Question::Overwrite, "Overwrite the changed file", ask_overwrite);
}

}  // namespace sweep::viewer::panels
