#include "editor/unsaved_changes.hpp"

#include <utility>

namespace sweep::editor {

void UnsavedChangesFlow::request(PendingAction action, std::string path, bool dirty) {
  action_ = action;
  path_ = std::move(path);
  error_.clear();
  stage_ = dirty ? Stage::AskSave : Stage::Ready;
}

void UnsavedChangesFlow::ask_path() {
  error_.clear();
  stage_ = Stage::AskPath;
}

void UnsavedChangesFlow::choose_save(bool has_file) {
  if (stage_ != Stage::AskSave) return;
  if (!has_file) ask_path();  // the action waits for Save As
}

void UnsavedChangesFlow::choose_discard() {
  if (stage_ != Stage::AskSave) return;
  error_.clear();
  stage_ = Stage::Ready;
}

void UnsavedChangesFlow::cancel() {
  *this = {};
}

void UnsavedChangesFlow::saved(bool ok, std::string error) {
  if (stage_ != Stage::AskSave && stage_ != Stage::AskPath) return;
  if (!ok) {
    error_ = std::move(error);
    return;
  }
  error_.clear();
  stage_ = action_ == PendingAction::None ? Stage::Idle : Stage::Ready;
}

PendingAction UnsavedChangesFlow::take_ready() {
  if (stage_ != Stage::Ready) return PendingAction::None;
  const PendingAction action = action_;
  stage_ = Stage::Idle;
  action_ = PendingAction::None;
  return action;
}

}  // namespace sweep::editor
