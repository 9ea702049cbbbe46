#pragma once
// What the viewer does, as functions of its state: opening, saving, exporting, editing, undo,
// the camera and the profile view. The command table, the panels and the input call these;
// none of them touches GL or the window (quitting and screenshots are requests in the state).
#include "app/viewer/viewer_state.hpp"
#include "model/document.hpp"

#include <string>

namespace sweep::viewer {

// Files.
/// Loads `path`; on failure keeps the current document and sets the error. Returns success.
bool open_file(ViewerState& s, const std::string& path);
/// Shows a loaded (valid) document in place of the current one; a viewer tolerance below the
/// new scene's floor (kMinRelativeTolerance of its size) is raised to it. Returns success.
bool show_document(ViewerState& s, Document doc, const std::string& path);
/// Saves to `path`; sets the status, or the error. Returns success.
bool save_to(ViewerState& s, const std::string& path);
/// Save As: asks for a path (the field starts at the current file, or untitled.swp).
void ask_save_path(ViewerState& s);
/// Ctrl+O: the file browser, at the current file's folder (or the working folder).
void open_browser(ViewerState& s, BrowserPurpose purpose);
/// Ctrl+S: saves to the current file, or asks for a path (or, when the file changed on disk
/// since edits were kept over it, asks before overwriting).
void save_current(ViewerState& s);
/// Opens `path` now, or after asking when there are unsaved changes.
void request_open(ViewerState& s, const std::string& path);
/// Starts an untitled, empty document now, or after asking when there are unsaved changes.
void request_new(ViewerState& s);
/// Quits now, or after asking when there are unsaved changes.
void request_quit(ViewerState& s);
/// Runs what the unsaved-changes questions let through (after the modals each frame).
void run_ready_action(ViewerState& s);
/// Writes PREFIX_NAME.obj for every named surface (editor::export_surfaces).
void export_obj(ViewerState& s, const std::string& prefix);
/// Of several dropped files the last .swp is opened; the others are named in the status.
void open_dropped(ViewerState& s, const std::vector<std::string>& paths);

// Edits.
/// One undoable edit; its error (if any) goes to the error panel. Returns success.
bool run_edit(ViewerState& s, const std::string& label, const editor::EditSession::Operation& operation);
/// One change of a continuous edit (a drag, typing): the caller opened the step.
bool apply_continuous(ViewerState& s, const editor::EditSession::Operation& operation);
void undo(ViewerState& s);
void redo(ViewerState& s);
/// The selected curve, if it has control points, else nullptr.
const Object* selected_control_curve(const ViewerState& s);
void delete_selected_point(ViewerState& s);
/// Inserts a B-spline point halfway to the next one (or past the last, continuing the polygon).
void insert_after_selected_point(ViewerState& s);
/// Selects the object named `name` (or with that display name). Returns false if none is.
bool select_by_name(ViewerState& s, const std::string& name);

// View.
void reset_camera(ViewerState& s);
void set_view(ViewerState& s, render::ViewPreset preset);
/// F: frames the selected object (its samples, mesh and control points), or everything when
/// nothing (visible) is selected; keeps the orientation and projection (the profile view too).
void frame_selection(ViewerState& s);
/// Home: frames every visible object (every object when none is), keeping orientation and projection.
void frame_all(ViewerState& s);
void set_profile_view(ViewerState& s, bool on);
/// Frame method, seam choice and adaptive tolerance: re-evaluates the scene (a view choice, not
/// an edit). Objects the tolerance is too small for (sampled otherwise) are named in the error
/// panel.
void set_evaluation(ViewerState& s, const EvaluationOptions& options);

/// Colours the surfaces by `mode`; the uv colours re-evaluate the scene with every surface's texture
/// coordinates (and leaving them drops the ones no material shows).
void set_color_mode(ViewerState& s, render::ColorMode mode);

}  // namespace sweep::viewer
