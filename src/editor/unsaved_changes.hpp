#pragma once
// The questions before work could be lost, as one small state machine, so the flow is tested
// without a window: request open/quit -> (unsaved changes?) ask "save first?" -> (no file
// yet?) ask for a path -> run the action. Save As on its own is the same path question with
// nothing to run after it.
#include <string>

namespace sweep::editor {

/// What waits for the answers.
enum class PendingAction { None, Open, New, Quit };

class UnsavedChangesFlow {
 public:
  enum class Stage {
    Idle,     // nothing asked
    AskSave,  // "save your changes first?" (Save / Discard / Cancel)
    AskPath,  // "save as:" a path (Save / Cancel)
    Ready,    // the pending action may run: take_ready()
  };

  /// The user asked to open `path` or to quit. A clean document goes straight to Ready.
  void request(PendingAction action, std::string path, bool dirty);
  /// Save As asked for directly (Ctrl+Shift+S, or Ctrl+S on an untitled document).
  void ask_path();

  /// AskSave -> Save. With a file the caller saves to it and reports saved(); without one
  /// the flow asks for a path.
  void choose_save(bool has_file);
  /// AskSave -> Discard: the changes go, the action runs.
  void choose_discard();
  /// Cancel in either question: nothing runs.
  void cancel();
  /// The outcome of the save the flow asked for. Success: Ready when an action waits, else
  /// Idle. Failure: the question stays open with `error` shown in it.
  void saved(bool ok, std::string error = {});

  /// When Ready: the action to run now (the flow goes Idle); else PendingAction::None.
  PendingAction take_ready();

  Stage stage() const { return stage_; }
  PendingAction action() const { return action_; }
  /// The file to open (PendingAction::Open).
  const std::string& path() const { return path_; }
  /// The last failed save's message, shown in the open question ("" if none).
  const std::string& error() const { return error_; }

 private:
  Stage stage_ = Stage::Idle;
  PendingAction action_ = PendingAction::None;
  std::string path_;
  std::string error_;
};

}  // namespace sweep::editor
