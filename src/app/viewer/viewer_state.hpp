#pragma once
// Everything the viewer's panels, input and commands work on, in one place: the edit session
// with its view state and selection, the questions before losing work, the camera and display
// settings, this frame's layout, messages and the panels' own fields. No GL and no GLFW.
#include "desktop/file_browser.hpp"
#include "desktop/file_chooser.hpp"
#include "desktop/file_watch.hpp"
#include "desktop/recovery.hpp"
#include "desktop/settings.hpp"
#include "editor/background_task.hpp"
#include "editor/bezier_joints.hpp"
#include "editor/curvature_comb.hpp"
#include "editor/edit_session.hpp"
#include "editor/playback.hpp"
#include "editor/point_drag.hpp"
#include "editor/point_transform.hpp"
#include "editor/snapping.hpp"
#include "editor/unsaved_changes.hpp"
#include "editor/view_state.hpp"
#include "editor/viewport_layout.hpp"
#include "render/camera.hpp"
#include "render/display_settings.hpp"
#include "render/renderer.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sweep::viewer {

class ItemPositions;  // app/viewer/item_positions.hpp

/// A fixed-size text buffer for ImGui::InputText.
struct TextField {
  std::array<char, 1024> text{};
  void set(const std::string& value);
  std::string get() const { return text.data(); }
};

/// A number field being typed in (number_field.cpp): which one, its text, and where typing is.
struct TypedNumber {
  std::uint32_t id = 0;  // the field's ImGui id; 0: none is typed in
  TextField text;
  std::string initial;   // the text it started with (the value, exactly)
  bool focused = false;  // the text field has taken the keyboard (a frame after the click)
  int frame = -1;        // the ImGui frame it was last drawn in
};

/// What the panels' input fields hold between frames.
struct PanelFields {
  TextField open;
  TextField save_as;
  TextField browser_filter;
  TextField material_name;     // Material panel: a new material's name
  TextField material_texture;  // the shown material's texture and bump paths
  TextField material_bump;
  editor::ObjectId material_for = editor::kNoObject;  // the material those two fields show
  TextField export_prefix;
  TextField screenshot;
  TextField rename;
  editor::ObjectId rename_for = editor::kNoObject;  // the object whose name `rename` holds
  TextField curve_name;
  TextField surface_name;
  int template_choice = 0;
  int surface_choice = 0;   // 0: surface of revolution, 1: generalized cylinder, 2: birail
  int profile_choice = -1;  // object index
  int sweep_choice = -1;    // gcyl: the sweep; birail: the first rail
  int rail2_choice = -1;    // birail: the second rail
  int surface_steps = 24;
  TextField rider_name;
  int rider_path_choice = -1;   // object index of the curve ridden
  int rider_model_choice = -1;  // and of the surface carried
  double split_t = 0.5;         // where Split cuts a Bezier piece
  TypedNumber typed_number;
};

/// Numbers for the stats panel and --frame-time.
struct ViewerStats {
  std::deque<double> frame_ms;    // the last frames' drawing times
  std::vector<double> remesh_ms;  // every re-mesh time: edits, undo, redo, evaluation changes
  render::RenderStats render;     // what the last frame drew
  std::string gl_description;
};

/// A control point being dragged in the view.
struct PointDrag {
  bool active = false;
  editor::ObjectId object = editor::kNoObject;
  int point = -1;
  glm::dvec3 start{0.0};    // where the point was on press
  editor::HandleGrip grip;  // where the pointer was pressed, and the handle's centre from there
  int axis = -1;            // axis constraint of the last frame
  /// The type of the Bezier joint the point is or is a handle of, when the drag began (the rule
  /// the drag keeps: bezier_joints.hpp); Corner for every other point.
  editor::JointType joint_type = editor::JointType::Corner;
  /// What the point may snap to, gathered on press (none when every snap toggle is off).
  std::shared_ptr<editor::SnapTargets> targets;
  std::optional<editor::SnapHit> snap;  // where it snapped in the last frame
};

/// The selected curve's comb, kept until the curve is evaluated again or the scale changes.
struct CombCache {
  editor::ObjectId object = editor::kNoObject;
  std::uint64_t revision = 0;  // the curve's EvaluatedObject::revision
  double factor = 0.0;
  editor::CurvatureComb comb;
};

/// A rubber band being drawn (Shift+drag in the view), in window units.
struct RubberBand {
  bool active = false;
  glm::dvec2 from{0.0};
  glm::dvec2 to{0.0};
};

/// The curve-editing tools' state: joint types chosen, the curvature comb, snapping, the rubber
/// band and the transform of several points (group_input.cpp).
struct CurveEditing {
  editor::JointTypes joints;  // types the user chose that the points alone do not say
  bool comb = false;          // the selected curve's curvature comb (K)
  double comb_scale = 1.0;    // times the automatic needle length (editor::default_comb_scale)
  editor::SnapOptions snap;   // what a dragged point snaps to besides the grid
  CombCache comb_cache;
  RubberBand band;
  std::optional<editor::TransformMode> requested;  // G, R or E pressed: starts in the input
  editor::PointTransform transform;
  editor::ObjectId transform_object = editor::kNoObject;
  bool transform_by_drag = false;  // a selected handle dragged: ends on release
  glm::dvec2 transform_grip{0.0};  // the dragged handle's centre minus the pointer on press
};

/// A camera drag with a mouse button (0 left, 1 right, 2 middle), or none.
struct CameraDrag {
  int button = -1;
  bool moved = false;
  glm::dvec2 last{0.0};
};

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

/// A PNG asked for (Save PNG of the view / of the window), written once the next frame is drawn
/// (script_hooks.cpp).
struct ScreenshotRequest {
  std::filesystem::path path;  // absolute; empty: none asked for
  bool with_panels = false;    // the whole window; otherwise the 3D view alone, without the UI
  int frames_to_wait = 0;      // frames drawn first (a menu item clicked closes its menu in the next)
  /// Of the view alone: drawn again at this size (0 x 0: the view's size on screen), with or
  /// without the control points, the curves and the ground grid, and no selection or hover.
  glm::ivec2 size{0, 0};
  bool control_points = true;
  bool curves = true;
  bool grid = true;
};

/// The Save PNG of the view dialog (panels/png_dialog.cpp): open while asking, and the answers,
/// which start as the view shows when it opens.
struct PngDialog {
  bool open = false;
  int size_choice = 0;  // index into png_sizes() (0: the view)
  bool control_points = true;
  bool curves = true;
  bool grid = true;
};

/// The camera riding along with a rider (view_actions.cpp): while `rider` is set, the camera is
/// placed with it before every frame (render::ride_camera), in perspective.
struct RideAlong {
  editor::ObjectId rider = editor::kNoObject;  // kNoObject: the orbit camera
  render::RideView view = render::RideView::Chase;
  render::Camera orbit;  // the orbit camera when the ride began, given back by Orbit (and Space)
  /// The model's size (radius, top, a train behind), measured again only when its mesh changes
  /// (revision).
  int radius_model = -1;
  std::uint64_t radius_revision = 0;
  RiderSize size;
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
};

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
  bool snap = false;
  double snap_size = 0.25;
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
  bool quit = false;  // the window closes after this frame
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
