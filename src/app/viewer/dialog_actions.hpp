#pragma once
// Open and Save As through the desktop's own file dialog (desktop/file_chooser.hpp) when the
// setting allows and the desktop has one; the in-app browser otherwise, or when the desktop's
// dialog fails. The dialog runs beside the window; its answer is acted on by poll_dialogs.
#include "app/viewer/viewer_state.hpp"

namespace sweep::viewer {

/// This run's preference: SWEEP_FILE_CHOOSER ("auto" or "in-app") if set, else `settings_file`'s
/// (empty: the default, automatic, and the toggle is not kept).
void init_dialogs(ViewerState& s, const editor::Environment& env, const std::filesystem::path& settings_file);
/// Ctrl+O: starts the desktop's Open dialog and returns true, or returns false when the in-app
/// browser is to be shown.
bool start_open_dialog(ViewerState& s);
/// Called where the Save As question would be drawn: a new question goes to the desktop's Save
/// dialog when there is one. True while that dialog has it (the in-app question is not drawn).
bool save_path_in_desktop_dialog(ViewerState& s);
/// Acts on a dialog that has finished: opens or saves what was chosen, shows a failure and the
/// in-app browser instead. True when the window should draw a frame.
bool poll_dialogs(ViewerState& s);
/// The File menu's "Use the desktop's file dialog": automatic or always in-app, kept in settings.txt.
void toggle_desktop_dialogs(ViewerState& s);
bool desktop_dialogs_on(const ViewerState& s);

}  // namespace sweep::viewer
