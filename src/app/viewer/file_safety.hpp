#pragma once
// Never losing work: a recovery copy of unsaved edits in the state folder (offered back when the
// file is opened again), live reload when another program saves the open file, and the recent
// files and window layout kept in the config folder. Functions of the viewer state, called by
// the main loop and the actions; no GL.
#include "app/viewer/viewer_state.hpp"
#include "desktop/user_folders.hpp"

namespace sweep::viewer {

/// Finds the folders (XDG), loads the recent files and points ImGui at its layout file. A
/// folder that cannot be used is said in the error panel; the viewer works on without it.
void init_file_safety(ViewerState& s, const editor::Environment& env, bool live_reload);

/// After a document was shown (opened, recovered, reloaded): watch its file, and offer a
/// recovery copy newer than it.
void after_document_shown(ViewerState& s);
/// After a save to `path`: the copy goes, the watcher accepts our version.
void after_saved(ViewerState& s, const std::string& previous_file);
/// Remembers `path` in the recent files and writes the list.
void remember_recent_file(ViewerState& s, const std::string& path);
/// Writes ImGui's window layout to the config folder's imgui.ini atomically, when ImGui asks
/// (io.WantSaveIniSettings) or `now` (quitting). A failure is reported once per problem.
void save_window_layout(ViewerState& s, bool now = false);

/// Once per frame, after the UI: a finished edit step (re)arms the recovery timer; a document
/// back to its saved state has no copy.
void note_edits(ViewerState& s, double now);
/// Between frames: writes a due recovery copy, polls the file. Returns true when the view must
/// be drawn again (a reload, a question).
bool poll_background(ViewerState& s, double now);
/// Seconds until poll_background has something to do (< 0: nothing).
double background_wait(const ViewerState& s, double now);
/// The viewer quits normally: the copy goes (the user saved or chose to discard).
void on_clean_quit(ViewerState& s);
/// The user chose Discard for the unsaved changes (before opening another file or quitting):
/// the changes go, and so does their recovery copy, which would otherwise be offered next time.
void discard_changes(ViewerState& s);

// The answers to FileSafety::Question.
void recover_copy(ViewerState& s);            // Recover: the copy's document, as unsaved edits
void dismiss_copy(ViewerState& s);            // Open the saved file: the copy goes
void reload_from_disk(ViewerState& s);        // Reload: the file as it is now, edits dropped
void keep_my_edits(ViewerState& s);           // Keep mine: Save will ask before overwriting
void overwrite_changed_file(ViewerState& s);  // Overwrite: save over the changed file

}  // namespace sweep::viewer
