#pragma once
// Everything the viewer's input, commands and actions work on, in one place: the edit session
// with its view state and selection, the questions before losing work, the camera and display
// settings, this frame's layout and messages, and the parts in state/ (the panels' fields, curve
// editing, file safety, requests). No GL and no GLFW. A panel is handed only the parts it edits
// (panels/panel_parts.hpp); the viewer-level panels (File, Display, timeline, the questions) run
// actions on the whole.
#include "app/viewer/state/curve_editing.hpp"
#include "app/viewer/state/file_state.hpp"
#include "app/viewer/state/panel_fields.hpp"
#include "app/viewer/state/pen_tool.hpp"
#include "app/viewer/state/print_findings.hpp"
#include "app/viewer/state/view_requests.hpp"
#include "desktop/file_browser.hpp"
#include "desktop/settings.hpp"
#include "editor/background_task.hpp"
#include "editor/edit_session.hpp"
#include "editor/playback.hpp"
#include "editor/unsaved_changes.hpp"
#include "editor/view_state.hpp"
#include "editor/viewport_layout.hpp"
#include "render/camera.hpp"
#include "render/display_settings.hpp"

#include <deque>
#include <filesystem>
#include <glm/vec2.hpp>
#include <memory>

#include <optional>
#include <string>
#include <vector>

namespace sweep::viewer {

class ItemPositions;  // app/viewer/item_positions.hpp

struct ViewerState {
  editor::EditSession session;
  editor::ViewStates views;
  editor::Selection selection;
  editor::UnsavedChangesFlow unsaved;
  render::DisplaySettings display;
  render::Camera camera;
  render::Camera camera_before_profile;
  bool profile_view = false;
  editor::Playback playback;  // the riders' clock (the timeline strip, Shift+Space)
  RideAlong ride;
  editor::ViewportLayout layout;  // this frame's
  bool show_ui = true;
  bool show_help = false;     // the Help window (F1)
  bool report_saves = false;  // scripted runs: print "saved PATH" on stdout

  PointDrag point_drag;
  CameraDrag camera_drag;
  CurveEditing curve_editing;
  PenTool pen;  // drawing curves by clicking (pen_actions.hpp)
  bool snap = false;
  double snap_size = 0.25;
  /// The model coordinates under the pointer in the profile view (the plane z = 0), for the
  /// status bar; none elsewhere or over a panel (input.cpp).
  std::optional<glm::dvec2> cursor;
  /// The Adaptive toggle's tolerance while it is off (model units; 0: not chosen yet, the
  /// toggle then starts at 1e-3 of the scene's size). On, it is session.evaluation().tolerance.
  double adaptive_tolerance = 0.0;
  /// The over-limit messages last put into `error` (actions.cpp), so that a tolerance that
  /// fits again takes them away without touching other errors.
  std::string over_limit_error;

  std::string error;   // shown in the Error panel (file:line:column for parse errors)
  std::string status;  // the last thing done
  std::deque<std::string> recent;
  /// The folder of the file last opened or saved (absolute): an untitled document's exports and
  /// PNGs go there (empty: the working folder).
  std::filesystem::path last_folder;
  FileSafety safety;
  editor::FileBrowser browser;
  BrowserPurpose browser_for = BrowserPurpose::None;
  DesktopDialogs dialogs;
  PanelFields fields;
  ViewerStats stats;
  ScreenshotRequest pending_screenshot;
  PngDialog png_dialog;
  PrintFindings print_findings;  // the last 3MF or STL export's, in the Export panel
  bool quit = false;             // the window closes after this frame
  /// A file opened while its evaluation runs in the background: the camera frames the scene
  /// when the evaluation is installed (until then the scene is empty).
  bool frame_when_evaluated = false;
  /// A large file being opened or a large export being written (background_actions.cpp), and
  /// cancelled ones whose threads are finishing.
  std::unique_ptr<editor::BackgroundTask> task;
  std::vector<std::unique_ptr<editor::BackgroundTask>> retired_tasks;
  /// A menu, popup or typed field was open when this frame's keys were pressed (so Esc closes it).
  bool interface_was_open = false;
  /// Where named widgets end up (panels::mark_item), owned by ScriptHooks. Null unless a
  /// scripted test asked, so a normal frame does no work for it.
  ItemPositions* item_positions = nullptr;

  const Document& doc() const { return session.document(); }
  /// The selected object's index, or -1.
  int selected() const { return selection.index(session); }
};

}  // namespace sweep::viewer
