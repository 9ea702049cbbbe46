#pragma once
// The viewer's state for keeping files safe and choosing them: recovery copies and live reload
// (file_safety.cpp), and the desktop's own file dialogs (dialog_actions.cpp).
#include "desktop/file_chooser.hpp"
#include "desktop/file_watch.hpp"
#include "desktop/recovery.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sweep::viewer {

/// Keeping work safe (file_safety.cpp): recovery copies, live reload of the file when another
/// program changes it, and the questions they ask.
struct FileSafety {
  std::optional<editor::RecoveryStore> recovery;  // none when there is no state folder
  editor::RecoveryTimer timer;
  std::uint64_t seen_revision = 0;  // the session's revision last looked at
  editor::FileWatcher watcher;
  bool live_reload = true;
  bool changed_on_disk = false;  // edits kept over a changed file: Save asks before overwriting
  enum class Question : std::uint8_t { None, Recover, Reload, Overwrite };
  Question question = Question::None;
  std::filesystem::path copy;            // Recover: the copy offered
  std::vector<std::string> differences;  // Recover: what it changes, by object name
  std::filesystem::path recent_file;     // where recent files are kept ("" when nowhere)
  std::string ini_file;                  // ImGui's window layout ("" when nowhere)
  std::string layout_problem;            // why the layout was last not written ("" when it was)
};

/// What the Open and Save As browser is for.
enum class BrowserPurpose : std::uint8_t { None, Open, SaveAs };

/// The desktop's own file dialog for Open and Save As (dialog_actions.cpp).
struct DesktopDialogs {
  /// This run's: settings.txt's, or SWEEP_FILE_CHOOSER's; the File menu toggles it (and keeps it).
  editor::ChooserPreference preference = editor::ChooserPreference::Auto;
  std::filesystem::path settings_file;          // empty: not kept
  std::optional<editor::ChooserSystem> system;  // probed at the first Open or Save As
  std::unique_ptr<editor::FileChoice> open;     // the dialog open now, if any
  /// Who answers the Save As question now being asked (None: no question).
  enum class SavePath : std::uint8_t { None, Desktop, InApp } save_path = SavePath::None;
  std::function<void()> wake;  // called on the dialog's thread when it is done (wakes the loop)
  bool fallback_said = false;  // the status said once that no desktop dialog is there
};
}  // namespace sweep::viewer
