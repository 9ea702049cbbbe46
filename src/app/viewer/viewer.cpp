// The viewer's main loop: wait for events (or a due frame), run the UI and input against the
// viewer state and the command table, draw, present. Panels live in panels/, input in
// input.cpp, actions in actions.cpp, the window in platform_glfw.cpp, scripted-run hooks in
// script_hooks.cpp, drawing in scene_view.cpp.
#include "app/viewer/viewer.hpp"

#include "app/viewer/actions.hpp"
#include "app/viewer/command_bindings.hpp"
#include "app/viewer/dialog_actions.hpp"
#include "app/viewer/file_safety.hpp"
#include "app/viewer/input.hpp"
#include "app/viewer/panels/panels.hpp"
#include "app/viewer/platform.hpp"
#include "app/viewer/scene_view.hpp"
#include "app/viewer/script_hooks.hpp"
#include "app/viewer/view_png.hpp"
#include "editor/redraw_schedule.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/riders.hpp"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace sweep::viewer {
namespace {

/// "name.swp* — Sweep": the file and whether it has unsaved changes.
std::string window_title(const ViewerState& s) {
  const std::string& path = s.session.file();
  const std::string name = path.empty() ? "untitled" : std::filesystem::path(path).filename().string();
  return name + (s.session.dirty() ? "*" : "") + " \xE2\x80\x94 Sweep";  // U+2014 EM DASH
}

/// How often the loop looks for a finished background evaluation (seconds): a result waits at
/// most this long, and the progress bar moves at this rate.
constexpr double kEvaluationPoll = 1.0 / 30.0;
/// Seconds between the frames that move the progress bar.
constexpr double kProgressInterval = 0.25;

/// editor::kViewerBackgroundWork, or SWEEP_BACKGROUND_WORK (0: evaluate on the drawing thread,
/// as before background evaluation; scripts/measure-freeze.sh compares the two).
std::int64_t background_work() {
  const char* value = std::getenv("SWEEP_BACKGROUND_WORK");
  if (value == nullptr || *value == '\0') return editor::kViewerBackgroundWork;
  return std::max<std::int64_t>(0, std::strtoll(value, nullptr, 10));
}

class Viewer {
 public:
  explicit Viewer(const ViewerOptions& options)
      : options_(options),
        platform_(options.window_size, !options.print_frame_time && options.frame_count == 0),
        scene_view_(options.samples),
        hooks_(options, state_) {
    state_.display = options.display;
    state_.show_ui = options.show_ui;
    state_.report_saves = !options.select.empty();
    state_.session.set_evaluation(options.evaluation);
    state_.session.set_background(background_work());  // the window never waits for a re-mesh
    init_file_safety(state_, editor::process_environment(), options.live_reload);
    init_desktop_dialogs();
    state_.stats.gl_description = render::gl_description();
    update_layout();
    bind_commands(commands_, state_);
    schedule_.request();
  }
  ~Viewer() { platform_.context().make_current(); }  // GL objects go before their context
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  ViewerState& state() { return state_; }

  /// The main loop. Returns the exit code.
  int run() {
    while (!platform_.closing()) {
      const bool continuous = hooks_.continuous();
      // Playing riders draw continuously; paused, nothing moves and nothing is drawn.
      schedule_.set_animating(state_.playback.playing() && longest_loop(state_.doc()) > 0.0);
      if (hooks_.wants_frame() || !state_.pending_screenshot.path.empty()) schedule_.request();
      if (platform_.wait(continuous ? 0.0 : wait_time())) schedule_.input(platform_.now());
      if (poll_background(state_, platform_.now())) schedule_.request();
      if (poll_evaluation()) schedule_.request();
      if (poll_dialogs(state_)) schedule_.request();
      if (!continuous && !schedule_.due(platform_.now())) continue;
      if (!frame()) return 1;
      if (hooks_.last_frame()) break;
    }
    on_clean_quit(state_);
    hooks_.print_summary(state_);
    return 0;
  }

 private:
  /// Installs a finished background evaluation, which wants a frame; while one runs past
  /// panels::kProgressDelay, so does its progress bar.
  bool poll_evaluation() {
    editor::EditSession& session = state_.session;
    if (poll_task(state_)) return true;
    if (session.poll()) {
      if (!session.error().empty()) state_.error = session.error();  // the evaluation failed
      if (state_.frame_when_evaluated && !session.evaluating()) {
        state_.frame_when_evaluated = false;
        reset_camera(state_);
      }
      return true;
    }
    const double seconds = state_.task ? state_.task->seconds() : session.evaluation_seconds();
    if ((!session.evaluating() && !state_.task) || seconds < panels::kProgressDelay) return false;
    // The bar moves a few times a second: each frame draws the whole scene, which in software
    // rendering takes the CPU the evaluation needs.
    const double now = platform_.now();
    if (now - last_progress_frame_ < kProgressInterval) return false;
    last_progress_frame_ = now;
    return true;
  }

  /// Until the next frame is due or the background (recovery copy, file poll, an evaluation
  /// to install) has work.
  double wait_time() const {
    const double now = platform_.now();
    const double frame = schedule_.wait_time(now);
    double background = background_wait(state_, now);
    if (state_.session.evaluating())
      background = background < 0.0 ? kEvaluationPoll : std::min(background, kEvaluationPoll);
    if (background < 0.0) return frame;
    return frame < 0.0 ? background : std::min(frame, background);
  }

  /// Open and Save As: the desktop's dialog wakes the loop when it is done.
  void init_desktop_dialogs() {
    const editor::Environment env = editor::process_environment();
    const editor::UserFolder config = editor::config_folder(env);
    init_dialogs(state_, env, config.ok() ? config.path / "settings.txt" : std::filesystem::path());
    state_.dialogs.wake = &Platform::wake;
  }

  void update_layout() {
    render::GlContext& context = platform_.context();
    const bool timeline = !riders_of(state_.doc()).empty();
    state_.layout = editor::compute_layout(context.window_size(), context.framebuffer_size(), platform_.content_scale(),
                                           state_.show_ui, timeline);
    state_.camera.lens_shift = state_.layout.lens_shift;  // centre the scene between the panels
  }

  /// Window requests: the close button and dropped files.
  void handle_window_requests() {
    if (platform_.take_close_request()) {
      if (options_.frame_count > 0) {
        state_.quit = true;
      } else {
        request_quit(state_);  // asks first when there are unsaved changes
      }
    }
    const std::vector<std::string> dropped = platform_.take_dropped_files();
    if (!dropped.empty()) open_dropped(state_, dropped);
  }

  /// The UI and input of one frame: everything that may change the state.
  void update(glm::ivec2 framebuffer) {
    // What was open when this frame's keys were pressed: the new frame closes a menu on Esc.
    state_.interface_was_open =
        ImGui::IsPopupOpen("", ImGuiPopupFlags_AnyPopupId | ImGuiPopupFlags_AnyPopupLevel) || ImGui::IsAnyItemActive();
    platform_.begin_ui_frame();
    state_.playback.tick(platform_.now(), longest_loop(state_.doc()));
    follow_rider(state_);  // input picks with the camera the frame shows
    handle_input(state_, commands_, platform_.take_key_presses(), platform_.held_axis(), framebuffer);
    panels::draw_all(state_, commands_);
    run_ready_action(state_);
    note_edits(state_, platform_.now());
    follow_rider(state_);  // after a scrub, an edit or a new choice of rider
    // A step left open by a field that vanished while active (e.g. the selection changed) is
    // closed, so it cannot swallow later edits or block undo.
    if (state_.session.in_step() && !state_.point_drag.active && !state_.curve_editing.transform.active() &&
        !state_.pen.drawing() && !ImGui::IsAnyItemActive()) {
      state_.session.end_step();
    }
    platform_.set_title(window_title(state_));
    platform_.end_ui_frame();
    save_window_layout(state_);
  }

  /// One frame. Returns false when a scripted screenshot cannot be written.
  bool frame() {
    const auto start = std::chrono::steady_clock::now();
    bool fast = schedule_.fast(platform_.now());
    update_layout();
    handle_window_requests();
    const glm::ivec2 framebuffer = platform_.context().framebuffer_size();
    update(framebuffer);
    const auto updated = std::chrono::steady_clock::now();
    if (!state_.pending_screenshot.path.empty()) {
      fast = false;                        // a PNG is multisampled, as a still frame
      state_.session.finish_evaluation();  // and shows the document as it is
    }
    if (framebuffer.x > 0 && framebuffer.y > 0) {  // not minimised
      if (!state_.pending_screenshot.path.empty() && !state_.pending_screenshot.with_panels) {
        write_view_png(state_, scene_view_, framebuffer);
      }
      scene_view_.draw(state_, framebuffer, fast);
      platform_.draw_ui();
      if (!hooks_.after_draw(state_, framebuffer)) {
        std::fprintf(stderr, "sweep: %s\n", state_.error.c_str());
        return false;
      }
      platform_.context().present();
    }
    const auto end = std::chrono::steady_clock::now();
    hooks_.frame_done(state_, std::chrono::duration<double, std::milli>(end - start).count(),
                      std::chrono::duration<double, std::milli>(updated - start).count(), fast);
    schedule_.drawn(fast, platform_.now());
    if (state_.quit) platform_.close();
    return true;
  }

  ViewerOptions options_;
  ViewerState state_;
  editor::CommandTable commands_;
  Platform platform_;
  SceneView scene_view_;  // after the platform: its GL objects go first
  ScriptHooks hooks_;
  editor::RedrawSchedule schedule_;
  double last_progress_frame_ = -1e300;
};

void print_no_display() {
  std::fprintf(stderr,
               "sweep: no display to open a window on (DISPLAY/WAYLAND_DISPLAY unset or unusable); "
               "use `sweep render FILE.swp -o OUT.png` to render headless\n");
}

/// Starts the viewer on `doc`; returns the exit code.
int start(const ViewerOptions& options, Document doc) {
  std::unique_ptr<Viewer> viewer;
  try {
    viewer = std::make_unique<Viewer>(options);
  } catch (const NoDisplayError&) {
    print_no_display();
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 1;
  }
  ViewerState& s = viewer->state();
  if (!options.file.empty() && !show_document(s, std::move(doc), options.file)) {
    std::fprintf(stderr, "%s\n", s.error.c_str());
    return 1;
  }
  if (options.file.empty()) {
    reset_camera(s);          // the empty grid from above at an angle, as File > New shows it (not edge-on)
    after_document_shown(s);  // an untitled document's copy is offered
  }
  if (options.play && longest_loop(s.doc()) > 0.0) s.playback.play();
  if (!options.ride.empty()) {
    const int rider = s.doc().find(options.ride);
    if (rider < 0 || !is_rider(s.doc().objects[std::size_t(rider)].kind())) {
      std::fprintf(stderr, "sweep: --ride: no rider named '%s'\n", options.ride.c_str());
      return 1;
    }
    s.ride.view = options.first_person ? render::RideView::FirstPerson : render::RideView::Chase;
    ride_along(s, s.session.id_of(rider));
  }
  if (!options.select.empty() && !select_by_name(s, options.select)) {
    std::fprintf(stderr, "sweep: no object named '%s'\n", options.select.c_str());
    return 1;
  }
  return viewer->run();
}

}  // namespace

int run_viewer(const ViewerOptions& options) {
  if (!display_variable_set()) {
    print_no_display();
    return 1;
  }
  // Load before opening a window, so a bad file fails with its file:line:column and no window.
  Document doc;
  if (!options.file.empty()) {
    try {
      doc = io::load_swp_file(options.file);
    } catch (const io::ParseError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 1;
    }
  }
  return start(options, std::move(doc));
}

}  // namespace sweep::viewer
