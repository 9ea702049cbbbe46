#pragma once
// The viewer's ImGui panels, one file each. A panel that edits the document is a function of
// its parts of the viewer's state (panel_parts.hpp: what it shows and edits, nothing else) and
// the command table; the viewer-level panels (menus, File, Display, the timeline, the progress,
// the questions, the browser, Save PNG) take the whole state and change it through the actions
// (app/viewer/actions.hpp). No GL here: this folder compiles with headers that #error on GL and
// GLFW.
#include "app/viewer/panels/panel_parts.hpp"
#include "editor/commands.hpp"

#include <cstdint>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace sweep::viewer::panels {

/// The main panel (left), the edit panel (right, top), the error panel and the modal
/// questions, placed by state.layout. main_window.cpp
void draw_all(ViewerState& s, editor::CommandTable& commands);

void menu_bar(ViewerState& s, editor::CommandTable& commands);    // menu_bar.cpp
void file_panel(ViewerState& s, editor::CommandTable& commands);  // file_panel.cpp
/// Exports and PNGs, closed until opened (its header is marked "export-panel"). file_panel.cpp
void export_panel(ViewerState& s, editor::CommandTable& commands);
void display_panel(ViewerState& s, editor::CommandTable& commands);  // display_panel.cpp
void objects_panel(const ObjectsParts& p);                           // objects_panel.cpp
void create_panel(const CreateParts& p);                             // create_panel.cpp
/// The pen (B): on or off, its kind, a typed point, Close and Finish. pen_panel.cpp
void pen_panel(ViewerState& s, editor::CommandTable& commands);
void material_panel(const MaterialParts& p);  // material_panel.cpp
void stats_panel(const StatsParts& p);        // stats_panel.cpp
/// The selected object: name, numbers and the edits its kind allows. edit_panel.cpp
void edit_panel(const EditParts& p, editor::CommandTable& commands);
/// The selected curve's points as a table, with split/join/insert/delete. point_table.cpp
void point_table(const PointTableParts& p, editor::CommandTable& commands, int index);
/// The selected curve's joint type, curvature comb, selected points and snapping. curve_tools.cpp
void curve_tools(const CurveToolParts& p, editor::CommandTable& commands, int index);
/// The selected surface's scale, twist, caps and height. surface_fields.cpp
void surface_fields(const EditContext& c, int index);
/// The selected rider's path, model, seconds, start and up. rider_fields.cpp
void rider_fields(const EditContext& c, int index);
/// The riders' timeline strip (play, scrub, speed, ride along), while the layout has room for it
/// (the document has riders). timeline_panel.cpp
void timeline_panel(ViewerState& s, editor::CommandTable& commands);
void error_panel(const ErrorParts& p);  // error_panel.cpp
/// Seconds a background evaluation runs before its progress bar shows (quick ones never do).
inline constexpr double kProgressDelay = 0.25;
/// The running background evaluation's progress and Cancel, after kProgressDelay.
/// progress_panel.cpp
void progress_panel(ViewerState& s);
/// What the status bar shows and in which colour.
struct StatusLine {
  enum class Tone : std::uint8_t { Plain, Warning, Error };
  std::string text;  // one line of the message
  std::string more;  // where the other lines are ("(and 2 more: point here to see them)"), or ""
  Tone tone = Tone::Plain;
};
/// The status bar's line: the error's first line (its file:line:column for a bad file), red, or
/// amber when it is a warning; else the status's first warning line, amber (an export that wrote
/// its files but warns: the warning is what needs reading); else the status's first line. More
/// lines are pointed to. status_bar.cpp
StatusLine status_line(const StatusParts& p);
/// `text` cut in the middle to at most `width` as `measure` gives widths ("/home/me/models/...
/// /vase_hull.stl"): its start (a message's file:line:column) and its end (a path's file name)
/// stay, the cut is "...", and never inside a UTF-8 character. `text` itself when it fits.
/// status_bar.cpp
std::string elide_middle(const std::string& text, float width, const std::function<float(std::string_view)>& measure);
/// The last message along the bottom of the window, below the view. status_bar.cpp
void status_bar(const StatusParts& p);
/// Every command with its keys and the mouse, while state.show_help. help_window.cpp
void help_window(const HelpParts& p, const editor::CommandTable& commands);
/// One line of the Help window: the keys (or the mouse action) and what they do.
struct HelpRow {
  std::string keys;
  std::string does;
};
/// Every command of the table in its order, with all its shortcuts ("-" for none). help_window.cpp
std::vector<HelpRow> help_rows(const editor::CommandTable& commands);
/// What the mouse does in the view. help_window.cpp
std::vector<HelpRow> mouse_help_rows();
/// "Unsaved changes", "Save as" (with the browser), and the file-safety questions: a recovery
/// copy to recover, a file changed on disk under unsaved edits, saving over such a file. modals.cpp
void modals(ViewerState& s);
/// Save PNG of the view...: name, size, control points, curves and grid, while
/// state.png_dialog.open. png_dialog.cpp
void png_dialog(ViewerState& s);

/// What the browser list gave this frame: a file clicked (its path) or activated (double-click,
/// Enter) to open or save to.
struct BrowserPick {
  std::string file;
  bool activated = false;
};
/// The browser's (s.browser) folder, filter field and list; its rows are marked for scripts as
/// "browser NAME" ("browser work/" for a folder) (file_browser_panel.cpp).
BrowserPick browser_list(ViewerState& s, TextField& filter);
/// The Open browser, while state.browser_for is Open (file_browser_panel.cpp).
void file_browser(ViewerState& s);

}  // namespace sweep::viewer::panels
