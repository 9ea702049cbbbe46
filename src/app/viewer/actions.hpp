#pragma once
// What the viewer does, as functions of its state: opening, saving, exporting, editing, undo,
// the camera and the profile view. The command table, the panels and the input call these;
// none of them touches GL or the window (quitting and screenshots are requests in the state).
#include "app/viewer/viewer_state.hpp"
#include "io/surface_export.hpp"
#include "model/document.hpp"

#include <filesystem>
#include <string>

namespace sweep::viewer {

// Files.
/// Loads `path`; on failure keeps the current document and sets the error. Returns success. A
/// large file is read in the background (poll_task shows it when read; returns true then).
/// background_actions.cpp
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
/// Where exports and PNGs go: the folder of `file` (made absolute against `working`); for an
/// untitled document (`file` empty) `last_folder` when set, else `working`. Normalised.
/// Precondition: `working` and a non-empty `last_folder` are absolute.
std::filesystem::path output_folder(const std::string& file, const std::filesystem::path& last_folder,
                                    const std::filesystem::path& working);
/// output_folder of the current file, s.last_folder and the process's working folder.
std::filesystem::path output_folder(const ViewerState& s);
/// What an export prefix or PNG name typed into the File panel names: an absolute path as it is,
/// a relative one inside `folder` (so "wineglass" is FOLDER/wineglass); normalised ("a/../b" is
/// "b"); an empty one is `fallback`. Precondition: `folder` is absolute.
std::filesystem::path resolve_output_path(const std::string& typed, const std::filesystem::path& folder,
                                          const std::string& fallback);
/// The name the export and PNG fields start with: the current file's stem, or "untitled".
std::string default_output_stem(const ViewerState& s);
/// Writes PREFIX_NAME.obj (.stl, .glb) for every named surface, as `sweep export --format` does
/// (editor::export_surfaces, evaluated with editor::export_evaluation), PREFIX resolved against
/// output_folder (resolve_output_path; empty: default_output_stem). The status names every file
/// written (the OBJ, its MTL and images) with its full path, one "wrote PATH (...)" line each,
/// then any warnings; a failure names the path and the cause in the error, and writes nothing.
/// A large document is exported in the background (poll_task reports it). background_actions.cpp
void export_document(ViewerState& s, const std::string& prefix, io::ExportFormat format,
                     io::GlbEncoding encoding = io::GlbEncoding::Float);
/// Writes PREFIX.svg of the document's planar curves, as `sweep export --format svg` does
/// (export_curves_svg), PREFIX resolved as for export_document; the status says what was written,
/// the Error panel that there is nothing to write or why the write failed.
void export_planar_curves(ViewerState& s, const std::string& prefix);
/// Applies what a finished background task (a large file opened, a large export) found.
/// Returns true when one finished. background_actions.cpp
bool poll_task(ViewerState& s);
/// Cancels the running background task: its result is dropped (an export writes nothing).
void cancel_task(ViewerState& s);
/// Save PNG of the view (`with_panels` false: the 3D view alone, without the panels) or of the
/// whole window: asks for it, to `name` resolved as resolve_output_path does (empty:
/// default_output_stem; ".png" added when the name has no extension). The next frame writes the
/// view, the one after it the window (so a menu the command was chosen from has closed), and
/// reports the full path (script_hooks.cpp).
void request_screenshot(ViewerState& s, const std::string& name, bool with_panels);
/// A size Save PNG of the view offers: its label and pixels (0 x 0: the view's own size).
struct PngSize {
  const char* label;
  glm::ivec2 pixels;
};
/// The view's own size first, then 1920 x 1080 and the sizes `sweep render`, the viewer and
/// `sweep snapshot` use.
const std::vector<PngSize>& png_sizes();
/// Opens the Save PNG of the view dialog with its answers as the view shows now (the view's
/// size; control points, curves and grid as displayed).
void open_png_dialog(ViewerState& s);
/// Asks for the PNG of the view to `name` (as request_screenshot) with the dialog's answers; the
/// next frame draws and writes it (view_png.cpp). Closes the dialog.
void request_view_png(ViewerState& s, const std::string& name);
/// A rectangle of framebuffer pixels, rows counted from the top.
struct PixelRect {
  int x = 0;
  int y = 0;
  int width = 0;
  int height = 0;
};
/// The pixels of the 3D view: the layout's free part (where the scene is centred, between the
/// panels and above the status bar), rounded inwards so no pixel partly outside it is in them.
/// Precondition: `framebuffer` > 0 both ways. Empty (0 wide) when the panels cover the width.
PixelRect view_rect(const editor::ViewportLayout& layout, glm::ivec2 framebuffer);
/// The camera that shows at `size` pixels what `camera` shows in `view` of a window of
/// `framebuffer` pixels (drawn at the window's aspect with its lens shift): the same centre and
/// the same height, wider or narrower as `size` is (Save PNG of the view). Precondition: all
/// sizes > 0. view_actions.cpp
render::Camera picture_camera(const render::Camera& camera, PixelRect view, glm::ivec2 framebuffer, glm::ivec2 size);
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
/// What I does for the selection, for the Edit menu: "Add a piece after the end" (a Bezier's last
/// point), "Add a point before the start", "Insert point after the selected one", ...
std::string insert_label(const ViewerState& s);
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
/// The profile view on or off (on ends a ride along).
void set_profile_view(ViewerState& s, bool on);

// Riders (view_actions.cpp). reset_camera, set_view, frame_selection, frame_all and the profile
// view end a ride first: they place the orbit camera.
/// Whether the camera rides along with a rider.
bool riding(const ViewerState& s);
/// Rides along with the rider `rider` (an id; kNoObject: ends the ride, as stop_riding does). The
/// orbit camera is kept to come back to; the profile view ends.
void ride_along(ViewerState& s, editor::ObjectId rider);
/// Back to the orbit camera: the one the ride began from, or (`keep_view`: a drag or the wheel in
/// the view while riding) the ride's present view, to orbit from where it is. Not riding: nothing.
void stop_riding(ViewerState& s, bool keep_view = false);
/// Before input and before drawing: a riding camera is placed with its rider at the playback's
/// time (render::ride_camera with the model's bounding radius, centred in the free part). A
/// rider that is gone (deleted, another file) ends the ride.
void follow_rider(ViewerState& s);
/// Play / pause (Shift+Space): enabled when the document has riders.
void toggle_playback(ViewerState& s);
/// Frame method, seam choice and adaptive tolerance: re-evaluates the scene (a view choice, not
/// an edit). Objects the tolerance is too small for (sampled otherwise) are named in the error
/// panel.
void set_evaluation(ViewerState& s, const EvaluationOptions& options);

/// Colours the surfaces by `mode`; the uv colours re-evaluate the scene with every surface's texture
/// coordinates (and leaving them drops the ones no material shows).
void set_color_mode(ViewerState& s, render::ColorMode mode);

}  // namespace sweep::viewer
