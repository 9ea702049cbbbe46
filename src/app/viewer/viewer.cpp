#include "app/viewer/viewer.hpp"

#include "app/viewer/edit_session.hpp"
#include "app/viewer/glfw_context.hpp"
#include "core/edit.hpp"
#include "core/obj_writer.hpp"
#include "core/scene.hpp"
#include "core/swp_parser.hpp"
#include "headless/png_file.hpp"
#include "render/camera.hpp"
#include "render/gl_context.hpp"
#include "render/picking.hpp"
#include "render/renderer.hpp"

// glad before GLFW, so GLFW does not pull in the system GL header (its own block: clang-format
// sorts includes within a block).
#include <glad/gl.h>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <deque>
#include <exception>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sweep::viewer {
namespace {

using render::CurveMode;
using render::SurfaceMode;

constexpr std::size_t kMaxRecentFiles = 10;
constexpr int kFrameTimeWindow = 120;  // frames averaged for the stats panel

/// A fixed-size text buffer for ImGui::InputText.
struct TextField {
  std::array<char, 1024> text{};
  void set(const std::string& value) {
    const std::size_t n = std::min(value.size(), text.size() - 1);
    std::copy_n(value.begin(), n, text.begin());
    text[n] = '\0';
  }
  std::string get() const { return text.data(); }
};

/// A file name made from an object name, for exported OBJ files ("srev#3" -> "srev3").
std::string file_safe(const std::string& name) {
  std::string out;
  for (char c : name) {
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '-' || c == '.') out += c;
  }
  return out.empty() ? "object" : out;
}

/// A key press as GLFW reported it.
struct KeyPress {
  int key = 0;
  int mods = 0;
};

const glm::vec3 kHighlight{1.0f, 0.55f, 0.1f};  // the selected curve
const glm::vec3 kHandle{1.0f, 0.9f, 0.1f};      // its control points
const glm::vec3 kHandleHovered{1.0f, 1.0f, 1.0f};
const glm::vec3 kHandleSelected{0.2f, 0.9f, 1.0f};  // the selected point and its seam partners
const glm::vec3 kFold{1.0f, 0.2f, 1.0f};            // sweep samples where a tube folds over itself
const glm::vec3 kGrid{0.24f, 0.26f, 0.30f};
const glm::vec3 kGridXAxis{0.55f, 0.25f, 0.25f};  // the line y = 0
const glm::vec3 kGridYAxis{0.25f, 0.50f, 0.25f};  // the line x = 0
constexpr double kHandlePickRadius = 9.0;         // screen units
constexpr double kCurvePickRadius = 7.0;
constexpr float kHandleSize = 9.0f;
constexpr float kHandleBigSize = 13.0f;

/// A "nice" grid spacing (1, 2 or 5 times a power of ten) near `rough`.
double nice_step(double rough) {
  if (!(rough > 0.0) || !std::isfinite(rough)) return 1.0;
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  const double m = rough / power;
  return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * power;
}

class Viewer {
 public:
  explicit Viewer(const ViewerOptions& options) : options_(options) {
    settings_ = options.display;
    session_.set_evaluation(options.evaluation);
  }
  ~Viewer() { shut_down(); }
  Viewer(const Viewer&) = delete;
  Viewer& operator=(const Viewer&) = delete;

  /// Opens the window, ImGui and the renderer. Throws NoDisplayError or std::runtime_error.
  void start_up() {
    register_glfw_provider();
    render::ContextRequest request;
    request.size = options_.window_size;
    request.samples = options_.samples;
    request.title = "Sweep";
    context_ = render::create_context("glfw", request);
    window_ = static_cast<GLFWwindow*>(context_->native_window());
    glfwSetWindowUserPointer(window_, this);
    glfwSetDropCallback(window_, [](GLFWwindow* window, int count, const char** paths) {
      auto* self = static_cast<Viewer*>(glfwGetWindowUserPointer(window));
      for (int i = 0; i < count; ++i) self->dropped_.emplace_back(paths[i]);
    });
    // Key presses are queued here rather than polled through ImGui: ImGui 1.86 only sees the
    // key state at each frame, so a tap shorter than a (slow) frame would be lost.
    glfwSetKeyCallback(window_, [](GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
      if (action == GLFW_PRESS || action == GLFW_REPEAT) {
        static_cast<Viewer*>(glfwGetWindowUserPointer(window))->pressed_keys_.push_back({key, mods});
      }
    });
    // Closing the window with unsaved changes asks first.
    glfwSetWindowCloseCallback(window_, [](GLFWwindow* window) {
      auto* self = static_cast<Viewer*>(glfwGetWindowUserPointer(window));
      if (self->session_.dirty() && self->options_.frames == 0) {
        glfwSetWindowShouldClose(window, GLFW_FALSE);
        self->ask_before(Pending::Quit, "");
      }
    });
    // Frame pacing by vsync, except when measuring or capturing, where it would only add waiting.
    glfwSwapInterval(options_.frames > 0 || options_.print_frame_time ? 0 : 1);

    renderer_ = std::make_unique<render::Renderer>();
    gl_description_ = render::gl_description();

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini dropped into the working directory
    ImGui::StyleColorsDark();
    float scale_x = 1.0f;
    float scale_y = 1.0f;
    glfwGetWindowContentScale(window_, &scale_x, &scale_y);
    if (scale_x > 1.0f) {
      ImGui::GetStyle().ScaleAllSizes(scale_x);
      ImGui::GetIO().FontGlobalScale = scale_x;
    }
    panel_right_ = 8.0f + 360.0f * std::max(scale_x, 1.0f);  // until the panel is first drawn
    // ImGui installs its own input callbacks and chains to the key and drop callbacks set above.
    ImGui_ImplGlfw_InitForOpenGL(window_, true);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    imgui_ready_ = true;
  }

  /// Loads `path`; on failure keeps the current scene and shows the error. Returns success.
  bool open_file(const std::string& path) {
    try {
      return show_document(load_swp_file(path), path);
    } catch (const ParseError& e) {
      error_ = e.what();  // file:line:column: ...
    } catch (const std::exception& e) {
      error_ = path + ": " + e.what();
    }
    return false;
  }

  /// Shows a loaded (valid) document in place of the current one. Returns success.
  bool show_document(Document doc, const std::string& path) {
    try {
      session_.load(std::move(doc), path);
      settings_.visible.assign(session_.document().objects.size(), true);
      deselect();
      reset_camera();
      if (profile_view_) frame_profile_view();
      error_.clear();
      status_ = "opened " + path;
      remember_recent(path);
      after_file_change();
      return true;
    } catch (const std::exception& e) {  // e.g. out of memory while evaluating
      error_ = path + ": " + e.what();
    }
    return false;
  }

  /// Selects the object named `name` (or with that display name). Returns false if none is.
  bool select_by_name(const std::string& name) {
    const Document& doc = session_.document();
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      if (display_name(doc, static_cast<int>(i)) == name) {
        select_object(static_cast<int>(i));
        return true;
      }
    }
    return false;
  }

  const std::string& error() const { return error_; }

  /// The main loop. Returns the exit code.
  int run() {
    int frame = 0;
    auto previous = std::chrono::steady_clock::now();
    std::vector<double> measured_ms;
    while (!glfwWindowShouldClose(window_)) {
      glfwPollEvents();
      open_dropped_files();

      ImGui_ImplOpenGL3_NewFrame();
      ImGui_ImplGlfw_NewFrame();
      const std::vector<int> taps = hold_tapped_keys();
      ImGui::NewFrame();
      handle_input();
      if (options_.show_ui) draw_ui();
      draw_modals();
      end_abandoned_step();
      update_title();
      ImGui::Render();
      release_tapped_keys(taps);

      const glm::ivec2 framebuffer = context_->framebuffer_size();
      const glm::ivec2 window = context_->window_size();
      if (framebuffer.x <= 0 || framebuffer.y <= 0) {  // minimised: nothing to draw
        glfwWaitEventsTimeout(0.1);
        continue;
      }
      settings_.pixel_ratio = window.x > 0 ? float(framebuffer.x) / float(window.x) : 1.0f;
      camera_.lens_shift = {panel_share() - edit_share(), 0.0};  // centre the scene between the panels
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      renderer_->draw(session_.document(), session_.scene(), camera_, framebuffer, settings_);
      renderer_->draw_overlay(camera_, framebuffer, build_overlay(), settings_.pixel_ratio);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

      ++frame;
      // Scripted runs get the handles once the panels have stopped moving (auto-sized windows
      // settle over a few frames, and the scene is centred between them).
      if (!options_.select.empty() && !handles_printed_) {
        const glm::dvec2 layout(panel_right_, edit_left_);
        stable_frames_ = layout == last_layout_ ? stable_frames_ + 1 : 0;
        last_layout_ = layout;
        if (stable_frames_ >= 3) {
          print_handles();
          handles_printed_ = true;
        }
      }
      const bool last_frame = options_.frames > 0 && frame >= options_.frames;
      if (last_frame && !options_.screenshot.empty()) {
        if (!save_screenshot(options_.screenshot, framebuffer)) {
          std::fprintf(stderr, "sweep: %s\n", error_.c_str());
          return 1;
        }
      } else if (!pending_screenshot_.empty()) {
        save_screenshot(pending_screenshot_, framebuffer);
        pending_screenshot_.clear();
      }
      context_->present();

      const auto now = std::chrono::steady_clock::now();
      const double ms = std::chrono::duration<double, std::milli>(now - previous).count();
      previous = now;
      if (frame > 2) {  // the first frames include start-up and the uploads
        measured_ms.push_back(ms);
        frame_ms_.push_back(ms);
        if (frame_ms_.size() > kFrameTimeWindow) frame_ms_.pop_front();
      }
      if (last_frame) break;
    }
    if (options_.print_frame_time && !measured_ms.empty()) {
      double sum = 0.0;
      for (double ms : measured_ms) sum += ms;
      std::sort(measured_ms.begin(), measured_ms.end());
      std::printf("frames %zu, mean frame time %.2f ms, median %.2f ms, triangles %zu, vertices %zu\n",
                  measured_ms.size(), sum / double(measured_ms.size()), measured_ms[measured_ms.size() / 2],
                  renderer_->stats().triangles, renderer_->stats().vertices);
      if (!remesh_ms_.empty()) {
        double remesh_sum = 0.0;
        for (double ms : remesh_ms_) remesh_sum += ms;
        std::printf("edits %zu, mean re-mesh %.3f ms, max %.3f ms\n", remesh_ms_.size(),
                    remesh_sum / double(remesh_ms_.size()), *std::max_element(remesh_ms_.begin(), remesh_ms_.end()));
      }
    }
    return 0;
  }

 private:
  enum class Pending { None, Quit, Open };

  /// A control point being dragged in the 3D (or profile) view.
  struct PointDrag {
    bool active = false;
    int object = -1;
    int point = -1;
    glm::dvec3 start{0.0};         // where the point was on press
    glm::dvec2 pixel_offset{0.0};  // handle centre minus pointer on press, so it does not jump
    int axis = -1;                 // axis constraint of the last frame
  };

  /// ImGui 1.86 sees keys as up/down at each frame, so a tap shorter than a frame (a quick
  /// Enter in a field, Escape in a dialog, or synthetic input) would be lost. Keys pressed since
  /// the last frame are held down for this frame, with their modifiers; returns them.
  std::vector<int> hold_tapped_keys() {
    ImGuiIO& io = ImGui::GetIO();
    std::vector<int> taps;
    for (const KeyPress& press : pressed_keys_) {
      if (press.key < 0 || press.key >= int(IM_ARRAYSIZE(io.KeysDown)) || io.KeysDown[press.key]) continue;
      io.KeysDown[press.key] = true;
      io.KeyCtrl = io.KeyCtrl || (press.mods & GLFW_MOD_CONTROL) != 0;
      io.KeyShift = io.KeyShift || (press.mods & GLFW_MOD_SHIFT) != 0;
      io.KeyAlt = io.KeyAlt || (press.mods & GLFW_MOD_ALT) != 0;
      io.KeySuper = io.KeySuper || (press.mods & GLFW_MOD_SUPER) != 0;
      taps.push_back(press.key);
    }
    return taps;
  }

  /// After the frame: the held keys (and modifiers) go back to their real state.
  void release_tapped_keys(const std::vector<int>& taps) {
    if (taps.empty()) return;
    ImGuiIO& io = ImGui::GetIO();
    const auto down = [this](int key) { return glfwGetKey(window_, key) == GLFW_PRESS; };
    for (int key : taps) io.KeysDown[key] = down(key);
    io.KeyCtrl = down(GLFW_KEY_LEFT_CONTROL) || down(GLFW_KEY_RIGHT_CONTROL);
    io.KeyShift = down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT);
    io.KeyAlt = down(GLFW_KEY_LEFT_ALT) || down(GLFW_KEY_RIGHT_ALT);
    io.KeySuper = down(GLFW_KEY_LEFT_SUPER) || down(GLFW_KEY_RIGHT_SUPER);
  }

  void shut_down() {
    if (imgui_ready_) {
      ImGui_ImplOpenGL3_Shutdown();
      ImGui_ImplGlfw_Shutdown();
      ImGui::DestroyContext();
      imgui_ready_ = false;
    }
    if (context_) context_->make_current();
    renderer_.reset();  // GL objects go before their context
    context_.reset();
  }

  const Document& doc() const { return session_.document(); }

  /// Share of the window's width covered by the main panel (0 without the UI).
  double panel_share() const {
    const glm::ivec2 window = context_ ? context_->window_size() : options_.window_size;
    if (!options_.show_ui || window.x <= 0) return 0.0;
    return std::clamp(double(panel_right_) / double(window.x), 0.0, 0.6);
  }

  /// Share of the window's width covered by the edit panel on the right (0 without the UI).
  double edit_share() const {
    const glm::ivec2 window = context_ ? context_->window_size() : options_.window_size;
    if (!options_.show_ui || window.x <= 0 || edit_left_ <= 0.0f) return 0.0;
    return std::clamp(1.0 - double(edit_left_) / double(window.x), 0.0, 0.35);
  }

  /// Aspect ratio of the part of the window the panels leave free, which framing fills.
  double aspect() const {
    const glm::ivec2 size = context_ ? context_->framebuffer_size() : options_.window_size;
    return size.y > 0 ? (1.0 - panel_share() - edit_share()) * double(size.x) / double(size.y) : 1.0;
  }

  /// How world points map to window positions this frame.
  render::ScreenMapping screen_mapping() const {
    const glm::ivec2 framebuffer = context_->framebuffer_size();
    const ImVec2 display = ImGui::GetIO().DisplaySize;
    const double fb_aspect = framebuffer.y > 0 ? double(framebuffer.x) / double(framebuffer.y) : 1.0;
    return render::screen_mapping(camera_, {double(display.x), double(display.y)}, fb_aspect);
  }

  void reset_camera() {
    if (profile_view_) {
      frame_profile_view();
      return;
    }
    const render::Projection projection = camera_.projection;
    camera_.reset(render::scene_bounds(session_.scene()), aspect());
    camera_.projection = projection;
  }

  void set_view(render::ViewPreset preset) {
    camera_.set_view(preset);
    camera_.frame(render::scene_bounds(session_.scene()), aspect());
  }

  /// Front, orthographic, framed on the planar curves (all curves if there are none).
  void frame_profile_view() {
    render::Bounds bounds;
    for (bool planar_only : {true, false}) {
      for (std::size_t i = 0; i < doc().objects.size(); ++i) {
        const ObjectKind kind = doc().objects[i].kind;
        if (!is_curve(kind) || (planar_only && !is_planar_curve(kind))) continue;
        for (const Frame& f : session_.scene().objects[i].curve.frames) bounds.add(f.V);
      }
      if (!bounds.empty()) break;
    }
    if (bounds.empty()) bounds = render::scene_bounds(session_.scene());
    camera_.set_view(render::ViewPreset::Front);
    camera_.projection = render::Projection::Orthographic;
    camera_.frame(bounds, aspect());
  }

  void set_profile_view(bool on) {
    if (on == profile_view_) return;
    profile_view_ = on;
    if (on) {
      camera_before_profile_ = camera_;
      frame_profile_view();
    } else {
      camera_ = camera_before_profile_;
    }
  }

  void remember_recent(const std::string& path) {
    std::error_code ec;
    std::string absolute = std::filesystem::absolute(path, ec).lexically_normal().string();
    if (ec) absolute = path;
    recent_.erase(std::remove(recent_.begin(), recent_.end(), absolute), recent_.end());
    recent_.push_front(absolute);
    if (recent_.size() > kMaxRecentFiles) recent_.pop_back();
  }

  /// Fields that follow the current file name.
  void after_file_change() {
    const std::string& path = session_.file();
    open_field_.set(path);
    save_as_field_.set(path);
    const std::string stem = std::filesystem::path(path).stem().string();
    export_field_.set(stem);
    screenshot_field_.set(stem + ".png");
  }

  void update_title() {
    const std::string& path = session_.file();
    const std::string name = path.empty() ? "untitled" : std::filesystem::path(path).filename().string();
    // U+2014 EM DASH, as UTF-8.
    const std::string title = name + (session_.dirty() ? "*" : "") + " \xE2\x80\x94 Sweep";
    if (title != title_ && window_) {
      glfwSetWindowTitle(window_, title.c_str());
      title_ = title;
    }
  }

  // --- Unsaved changes ------------------------------------------------------------------------

  /// Runs `action` now, or after asking when there are unsaved changes.
  void ask_before(Pending action, const std::string& path) {
    pending_ = action;
    pending_path_ = path;
    if (session_.dirty()) {
      confirm_requested_ = true;
    } else {
      run_pending();
    }
  }

  void run_pending() {
    const Pending action = pending_;
    pending_ = Pending::None;
    switch (action) {
      case Pending::Quit:
        glfwSetWindowShouldClose(window_, GLFW_TRUE);
        break;
      case Pending::Open:
        open_file(pending_path_);
        break;
      case Pending::None:
        break;
    }
  }

  void request_open(const std::string& path) { ask_before(Pending::Open, path); }
  void request_quit() { ask_before(Pending::Quit, ""); }

  /// Ctrl+S: saves to the current file, or asks for one.
  void save_current() {
    if (session_.file().empty()) {
      save_as_requested_ = true;
      return;
    }
    save_to(session_.file());
  }

  bool save_to(const std::string& path) {
    if (session_.in_step()) session_.end_step();  // a field still being typed in counts
    if (!session_.save(path)) {
      error_ = session_.error();
      return false;
    }
    status_ = "saved " + path;
    error_.clear();
    remember_recent(path);
    after_file_change();
    if (!options_.select.empty()) {
      std::printf("saved %s\n", path.c_str());
      std::fflush(stdout);
    }
    return true;
  }

  void open_dropped_files() {
    // Of several dropped files the last .swp wins; others are ignored with a note.
    std::vector<std::string> dropped;
    dropped.swap(dropped_);
    std::string chosen;
    for (const std::string& path : dropped) {
      if (std::filesystem::path(path).extension() == ".swp") {
        chosen = path;
      } else {
        status_ = "not an SWP file: " + path;
      }
    }
    if (!chosen.empty()) request_open(chosen);
  }

  // --- Selection ------------------------------------------------------------------------------

  void deselect() {
    selected_ = -1;
    selected_point_ = -1;
    hovered_point_ = -1;
  }

  void select_object(int index) {
    if (index != selected_) selected_point_ = -1;
    selected_ = index;
  }

  /// The selected object if it is a curve with control points, else nullptr.
  const Object* selected_control_curve() const {
    if (selected_ < 0 || selected_ >= int(doc().objects.size())) return nullptr;
    const Object& object = doc().objects[std::size_t(selected_)];
    return has_control_points(object.kind) ? &object : nullptr;
  }

  /// Keeps the selection pointing at something that exists after an edit, undo or redo.
  void fix_selection() {
    if (selected_ >= int(doc().objects.size())) deselect();
    if (selected_ < 0) return;
    const Object& object = doc().objects[std::size_t(selected_)];
    if (selected_point_ >= int(object.points.size())) selected_point_ = int(object.points.size()) - 1;
    if (hovered_point_ >= int(object.points.size())) hovered_point_ = -1;
  }

  /// Window positions of the selected curve's control points (nullopt: behind the eye).
  std::vector<std::optional<glm::dvec2>> handle_positions(const render::ScreenMapping& mapping) const {
    std::vector<std::optional<glm::dvec2>> positions;
    if (const Object* curve = selected_control_curve()) {
      for (const glm::dvec3& p : curve->points) positions.push_back(render::to_screen(mapping, p));
    }
    return positions;
  }

  /// The handle under the pointer, or -1. Of overlapping handles the nearest to the pointer wins.
  int handle_under(const render::ScreenMapping& mapping, const glm::dvec2& pointer) const {
    int best = -1;
    double best_distance = kHandlePickRadius;
    const auto positions = handle_positions(mapping);
    for (std::size_t i = 0; i < positions.size(); ++i) {
      if (!positions[i]) continue;
      const double d = glm::length(*positions[i] - pointer);
      if (d <= best_distance) {
        best_distance = d;
        best = int(i);
      }
    }
    return best;
  }

  /// The visible curve whose samples (or control polygon, when shown) pass nearest the
  /// pointer within kCurvePickRadius, or -1.
  int curve_under(const render::ScreenMapping& mapping, const glm::dvec2& pointer) const {
    int best = -1;
    double best_distance = kCurvePickRadius;
    const auto consider = [&](int index, const auto& points) {
      std::optional<glm::dvec2> previous;
      for (const glm::dvec3& p : points) {
        const std::optional<glm::dvec2> q = render::to_screen(mapping, p);
        if (q) {
          const double d = previous ? render::distance_to_segment(pointer, *previous, *q) : glm::length(pointer - *q);
          if (d < best_distance) {
            best_distance = d;
            best = index;
          }
        }
        previous = q;
      }
    };
    for (std::size_t i = 0; i < doc().objects.size(); ++i) {
      const Object& object = doc().objects[i];
      if (!is_curve(object.kind) || !settings_.is_visible(i)) continue;
      if (settings_.curves != CurveMode::Off) {
        std::vector<glm::dvec3> samples;
        samples.reserve(session_.scene().objects[i].curve.frames.size());
        for (const Frame& f : session_.scene().objects[i].curve.frames) samples.push_back(f.V);
        consider(int(i), samples);
      }
      if (settings_.control_points && has_control_points(object.kind)) consider(int(i), object.points);
    }
    return best;
  }

  // --- Input ----------------------------------------------------------------------------------

  /// The axis (0 x, 1 y, 2 z) held down to constrain a drag, or -1.
  int held_axis() const {
    if (glfwGetKey(window_, GLFW_KEY_X) == GLFW_PRESS) return 0;
    if (glfwGetKey(window_, GLFW_KEY_Y) == GLFW_PRESS) return 1;
    if (glfwGetKey(window_, GLFW_KEY_Z) == GLFW_PRESS) return 2;
    return -1;
  }

  void handle_keys(const std::vector<KeyPress>& keys) {
    for (const KeyPress& press : keys) {
      const bool ctrl = (press.mods & (GLFW_MOD_CONTROL | GLFW_MOD_SUPER)) != 0;
      const bool shift = (press.mods & GLFW_MOD_SHIFT) != 0;
      if (ctrl) {
        switch (press.key) {
          case GLFW_KEY_Z:
            shift ? redo() : undo();
            break;
          case GLFW_KEY_Y:
            redo();
            break;
          case GLFW_KEY_S:
            if (shift) {
              save_as_requested_ = true;
            } else {
              save_current();
            }
            break;
          default:
            break;
        }
        continue;
      }
      switch (press.key) {
        case GLFW_KEY_S:
          settings_.surface = render::next(settings_.surface);
          break;
        case GLFW_KEY_C:
          settings_.curves = render::next(settings_.curves);
          break;
        case GLFW_KEY_P:
          settings_.control_points = !settings_.control_points;
          break;
        case GLFW_KEY_V:
          set_profile_view(!profile_view_);
          break;
        case GLFW_KEY_SPACE:
          reset_camera();
          break;
        case GLFW_KEY_DELETE:
        case GLFW_KEY_BACKSPACE:
          delete_selected_point();
          break;
        case GLFW_KEY_INSERT:
        case GLFW_KEY_I:
          insert_after_selected_point();
          break;
        case GLFW_KEY_ESCAPE:
          request_quit();
          break;
        default:
          break;
      }
    }
  }

  /// Keyboard and mouse for the 3D view; whatever ImGui is using is left to ImGui.
  void handle_input() {
    ImGuiIO& io = ImGui::GetIO();
    std::vector<KeyPress> keys;
    keys.swap(pressed_keys_);
    // Keys typed into an ImGui field (or meant for a dialog) belong to it.
    if (!io.WantCaptureKeyboard) handle_keys(keys);

    const render::ScreenMapping mapping = screen_mapping();
    const glm::dvec2 mouse(io.MousePos.x, io.MousePos.y);
    // Arcball coordinates are centred on the free part of the window, where the scene is.
    const double panel = panel_share() * double(io.DisplaySize.x);
    const double edit_panel = edit_share() * double(io.DisplaySize.x);
    const glm::dvec2 window_size(double(io.DisplaySize.x) - panel - edit_panel, io.DisplaySize.y);
    const glm::dvec2 pointer(mouse.x - panel, mouse.y);

    if (point_drag_.active) {
      if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
        if (ImGui::IsMousePosValid()) drag_point_to(mapping, mouse, true);  // where it was let go
        point_drag_.active = false;
        session_.end_step();
      } else if (ImGui::IsMousePosValid()) {
        drag_point_to(mapping, mouse);
      }
      return;
    }

    hovered_point_ = -1;
    if (!io.WantCaptureMouse && drag_button_ < 0 && ImGui::IsMousePosValid()) {
      hovered_point_ = handle_under(mapping, mouse);
      if (hovered_point_ >= 0) ImGui::SetMouseCursor(ImGuiMouseCursor_Hand);
    }
    if (!io.WantCaptureMouse) {
      if (ImGui::IsMouseClicked(ImGuiMouseButton_Left) && drag_button_ < 0) {
        if (hovered_point_ >= 0) {
          start_point_drag(mapping, mouse, hovered_point_);
          return;
        }
        const int curve = curve_under(mapping, mouse);
        if (curve >= 0) {
          select_object(curve);
          return;
        }
      }
      for (int button = 0; button < 3; ++button) {
        if (ImGui::IsMouseClicked(button) && drag_button_ < 0) {
          drag_button_ = button;
          drag_last_ = pointer;
          drag_moved_ = false;
        }
      }
      if (io.MouseWheel != 0.0f) camera_.zoom(std::pow(0.88, double(io.MouseWheel)));
    }
    if (drag_button_ >= 0) {
      if (!ImGui::IsMouseDown(drag_button_) || !ImGui::IsMousePosValid()) {
        // A left click on empty space (no drag) clears the selection.
        if (drag_button_ == ImGuiMouseButton_Left && !drag_moved_) deselect();
        drag_button_ = -1;
        return;
      }
      if (pointer == drag_last_) return;
      drag_moved_ = true;
      const glm::dvec2 from = render::arcball_point(drag_last_, window_size);
      const glm::dvec2 to = render::arcball_point(pointer, window_size);
      switch (drag_button_) {
        case ImGuiMouseButton_Left:
          // The profile view stays a front view: its left drag pans.
          if (profile_view_) {
            camera_.pan(to - from);
          } else {
            camera_.arcball_rotate(from, to);
          }
          break;
        case ImGuiMouseButton_Right:
          camera_.zoom(std::exp(2.0 * (from.y - to.y)));
          break;  // drag up: closer
        case ImGuiMouseButton_Middle:
          camera_.pan(to - from);
          break;
        default:
          break;
      }
      drag_last_ = pointer;
    }
  }

  void start_point_drag(const render::ScreenMapping& mapping, const glm::dvec2& mouse, int point) {
    const Object* curve = selected_control_curve();
    if (curve == nullptr) return;
    const glm::dvec3 start = curve->points[std::size_t(point)];
    const std::optional<glm::dvec2> centre = render::to_screen(mapping, start);
    if (!centre) return;
    point_drag_ = {true, selected_, point, start, *centre - mouse, held_axis()};
    selected_point_ = point;
    session_.begin_step("move point");
  }

  /// Moves the dragged point under the pointer: in the xy-plane for 2D curves, in the plane
  /// facing the camera for 3D ones, or along an axis while X, Y or Z is held.
  void drag_point_to(const render::ScreenMapping& mapping, const glm::dvec2& mouse, bool released = false) {
    const int object = point_drag_.object;
    if (object < 0 || object >= int(doc().objects.size())) return;
    const Object& curve = doc().objects[std::size_t(object)];
    if (point_drag_.point >= int(curve.points.size())) return;
    const render::Ray ray = render::pointer_ray(mapping, mouse + point_drag_.pixel_offset);
    const glm::dvec3 start = point_drag_.start;
    const bool planar = is_planar_curve(curve.kind);
    // On release keep the constraint of the last frame: the axis key may be let go first.
    const int axis = released ? point_drag_.axis : held_axis();
    point_drag_.axis = axis;
    std::optional<glm::dvec3> hit;
    glm::bvec3 snap_mask(true);
    if (planar) {
      if (axis == 2) return;  // a 2D point has no z to move along
      hit = render::intersect_plane(ray, glm::dvec3(0.0), {0.0, 0.0, 1.0});
      if (hit) {
        hit->z = 0.0;
        if (axis == 0) hit->y = start.y;
        if (axis == 1) hit->x = start.x;
      }
      snap_mask = {axis != 1, axis != 0, false};
    } else if (axis >= 0) {
      glm::dvec3 direction(0.0);
      direction[axis] = 1.0;
      hit = render::closest_on_line(ray, start, direction);
      snap_mask = {axis == 0, axis == 1, axis == 2};
    } else {
      hit = render::intersect_plane(ray, start, camera_.forward());
    }
    if (!hit) return;
    glm::dvec3 target = *hit;
    if (snap_ && snap_size_ > 0.0) target = render::snap_to_grid(target, snap_size_, snap_mask);
    if (target == curve.points[std::size_t(point_drag_.point)]) return;
    const int point = point_drag_.point;
    apply_continuous([object, point, target](Document& d) { return move_point(d, object, point, target); });
  }

  // --- Edits ----------------------------------------------------------------------------------

  /// After any change of the document: selection, visibility flags and timing.
  void after_edit() {
    settings_.visible.resize(doc().objects.size(), true);
    rename_for_ = -1;  // the name field shows the name as it now is
    fix_selection();
    remesh_ms_.push_back(session_.last_remesh_ms());
  }

  /// One undoable edit; its error (if any) goes to the error panel.
  bool run_edit(const std::string& label, const EditSession::Operation& operation) {
    if (!session_.edit(label, operation)) {
      error_ = session_.error();
      return false;
    }
    error_.clear();
    after_edit();
    return true;
  }

  /// One change of a continuous edit (drag, typing); the step is opened by the caller.
  bool apply_continuous(const EditSession::Operation& operation) {
    if (!session_.apply(operation)) {
      error_ = session_.error();
      return false;
    }
    after_edit();
    return true;
  }

  /// For the last ImGui item: one undo step from its activation to its deactivation, with
  /// `operation` applied whenever it reports a change.
  void continuous_item(bool changed, const std::string& label, const EditSession::Operation& operation) {
    if (ImGui::IsItemActivated()) session_.begin_step(label);
    if (changed) {
      if (!session_.in_step()) session_.begin_step(label);
      apply_continuous(operation);
    }
    if (ImGui::IsItemDeactivated() && !point_drag_.active) session_.end_step();
  }

  /// A step left open by a field that vanished while active (e.g. the selection changed)
  /// is closed, so it cannot swallow later edits or block undo.
  void end_abandoned_step() {
    if (session_.in_step() && !point_drag_.active && !ImGui::IsAnyItemActive()) session_.end_step();
  }

  void undo() {
    if (session_.undo()) {
      after_edit();
      status_ = "undone";
    }
  }

  void redo() {
    if (session_.redo()) {
      after_edit();
      status_ = "redone";
    }
  }

  void delete_selected_point() {
    const Object* curve = selected_control_curve();
    if (curve == nullptr || selected_point_ < 0) return;
    const int object = selected_;
    const int point = selected_point_;
    if (run_edit("delete point", [object, point](Document& d) { return delete_point(d, object, point); })) {
      selected_point_ = std::min(point, int(doc().objects[std::size_t(object)].points.size()) - 1);
    }
  }

  /// Inserts a B-spline point halfway to the next one (or past the last, continuing the polygon).
  void insert_after_selected_point() {
    const Object* curve = selected_control_curve();
    if (curve == nullptr || selected_point_ < 0) return;
    if (curve->kind != ObjectKind::BSpline2 && curve->kind != ObjectKind::BSpline3) {
      error_ = "points are inserted into B-splines; split a Bezier piece instead";
      return;
    }
    const std::vector<glm::dvec3>& points = curve->points;
    const std::size_t i = std::size_t(selected_point_);
    const glm::dvec3 position = i + 1 < points.size() ? 0.5 * (points[i] + points[i + 1])
                                : i > 0               ? points[i] + 0.5 * (points[i] - points[i - 1])
                                                      : points[i];
    const int object = selected_;
    const int before = selected_point_ + 1;
    if (run_edit("insert point", [object, before, position](Document& d) {
          return insert_bspline_point(d, object, before, position);
        })) {
      selected_point_ = before;
    }
  }

  void export_obj(const std::string& prefix) {
    int written = 0;
    try {
      for (std::size_t i = 0; i < doc().objects.size(); ++i) {
        if (!is_surface(doc().objects[i].kind)) continue;
        const std::string name = display_name(doc(), static_cast<int>(i));
        const std::string path = prefix + "_" + file_safe(name) + ".obj";
        save_obj_file(path, session_.scene().objects[i].mesh, "sweep: " + name + " from " + session_.file());
        ++written;
      }
      status_ = written == 0 ? "no surfaces to export"
                             : "wrote " + std::to_string(written) + " OBJ file(s) " + prefix + "_*.obj";
      error_.clear();
    } catch (const std::exception& e) {
      error_ = std::string("export failed: ") + e.what();
    }
  }

  bool save_screenshot(const std::string& path, glm::ivec2 framebuffer) {
    try {
      glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
      glReadBuffer(GL_BACK);
      headless::save_png_file(path, render::read_framebuffer(framebuffer));
      status_ = "saved " + path;
      return true;
    } catch (const std::exception& e) {
      error_ = std::string("screenshot failed: ") + e.what();
      return false;
    }
  }

  /// For scripted tests (--select): the selected curve's handles in window coordinates.
  void print_handles() {
    const render::ScreenMapping mapping = screen_mapping();
    const auto positions = handle_positions(mapping);
    std::printf("selected %s, %zu handles\n", selected_ >= 0 ? display_name(doc(), selected_).c_str() : "nothing",
                positions.size());
    for (std::size_t i = 0; i < positions.size(); ++i) {
      if (positions[i]) std::printf("handle %zu %.2f %.2f\n", i, positions[i]->x, positions[i]->y);
    }
    std::printf("edit %.2f %.2f\n", double(edit_left_), double(edit_bottom_));
    std::printf("panel %.2f\n", double(panel_right_));
    std::fflush(stdout);
  }

  // --- Overlay --------------------------------------------------------------------------------

  std::vector<render::OverlayBatch> build_overlay() const {
    using Batch = render::OverlayBatch;
    std::vector<Batch> overlay;
    if (profile_view_) add_grid(overlay);
    if (settings_.curves != CurveMode::Off) add_folds(overlay);
    if (selected_ < 0 || selected_ >= int(doc().objects.size())) return overlay;
    const Object& object = doc().objects[std::size_t(selected_)];
    if (!settings_.is_visible(std::size_t(selected_))) return overlay;
    if (is_curve(object.kind)) {
      Batch strip;
      strip.primitive = Batch::Primitive::LineStrip;
      strip.color = kHighlight;
      for (const Frame& f : session_.scene().objects[std::size_t(selected_)].curve.frames)
        strip.positions.emplace_back(f.V);
      overlay.push_back(std::move(strip));
    }
    if (!has_control_points(object.kind)) return overlay;
    Batch polygon;
    polygon.primitive = Batch::Primitive::LineStrip;
    polygon.color = kHandle * 0.7f;
    Batch handles;
    handles.color = kHandle;
    handles.point_size = kHandleSize;
    Batch hovered = handles;
    hovered.color = kHandleHovered;
    hovered.point_size = kHandleBigSize;
    hovered.positions.clear();
    Batch chosen = hovered;
    chosen.color = kHandleSelected;
    std::vector<int> partners;
    if (selected_point_ >= 0 && selected_point_ < int(object.points.size())) {
      partners = seam_partners(object, selected_point_);
    }
    for (std::size_t i = 0; i < object.points.size(); ++i) {
      const glm::vec3 p(object.points[i]);
      polygon.positions.push_back(p);
      if (std::find(partners.begin(), partners.end(), int(i)) != partners.end()) {
        chosen.positions.push_back(p);
      } else if (int(i) == hovered_point_) {
        hovered.positions.push_back(p);
      } else {
        handles.positions.push_back(p);
      }
    }
    overlay.push_back(std::move(polygon));
    overlay.push_back(std::move(handles));
    overlay.push_back(std::move(hovered));
    overlay.push_back(std::move(chosen));
    return overlay;
  }

  /// The sweep samples of every visible generalized cylinder where its tube folds over itself.
  void add_folds(std::vector<render::OverlayBatch>& overlay) const {
    render::OverlayBatch folds;
    folds.color = kFold;
    folds.point_size = 5.0f;
    const Scene& scene = session_.scene();
    for (std::size_t i = 0; i < doc().objects.size() && i < scene.objects.size(); ++i) {
      const Object& object = doc().objects[i];
      if (object.kind != ObjectKind::GeneralizedCylinder || !settings_.is_visible(i)) continue;
      const std::vector<Frame>& sweep = scene.objects[std::size_t(object.sweep)].curve.frames;
      for (const FoldRange& range : scene.objects[i].diagnostics.folds) {
        for (int k = std::max(0, range.first_sample); k <= range.last_sample && k < int(sweep.size()); ++k) {
          folds.positions.emplace_back(sweep[std::size_t(k)].V);
        }
      }
    }
    if (!folds.positions.empty()) overlay.push_back(std::move(folds));
  }

  /// A grid in the xy-plane around the view, with the axes in colour.
  void add_grid(std::vector<render::OverlayBatch>& overlay) const {
    using Batch = render::OverlayBatch;
    const double half_height = camera_.half_height_at_target();
    double step = nice_step(half_height / 5.0);
    // The snapping grid when it is not too dense to see.
    if (snap_ && snap_size_ > 0.0 && snap_size_ >= half_height / 60.0) step = snap_size_;
    const double reach = half_height * 3.0;  // covers wide windows and the lens shift
    const glm::dvec3 centre = camera_.target;
    const double x0 = std::floor((centre.x - reach) / step) * step;
    const double y0 = std::floor((centre.y - reach) / step) * step;
    const int lines = std::min(400, int(std::ceil(2.0 * reach / step)) + 1);
    Batch grid;
    grid.primitive = Batch::Primitive::Lines;
    grid.color = kGrid;
    grid.on_top = false;
    for (int k = 0; k < lines; ++k) {
      const double x = x0 + k * step;
      const double y = y0 + k * step;
      grid.positions.emplace_back(float(x), float(y0), 0.0f);
      grid.positions.emplace_back(float(x), float(y0 + double(lines - 1) * step), 0.0f);
      grid.positions.emplace_back(float(x0), float(y), 0.0f);
      grid.positions.emplace_back(float(x0 + double(lines - 1) * step), float(y), 0.0f);
    }
    overlay.push_back(std::move(grid));
    Batch x_axis;
    x_axis.primitive = Batch::Primitive::Lines;
    x_axis.color = kGridXAxis;
    x_axis.on_top = false;
    x_axis.positions = {glm::vec3(float(centre.x - reach), 0.0f, 0.0f), glm::vec3(float(centre.x + reach), 0.0f, 0.0f)};
    Batch y_axis = x_axis;
    y_axis.color = kGridYAxis;
    y_axis.positions = {glm::vec3(0.0f, float(centre.y - reach), 0.0f), glm::vec3(0.0f, float(centre.y + reach), 0.0f)};
    overlay.push_back(std::move(x_axis));
    overlay.push_back(std::move(y_axis));
  }

  // --- Panels ---------------------------------------------------------------------------------

  void draw_ui() {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float margin = 8.0f * ImGui::GetStyle().FramePadding.y / 3.0f;
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + margin, viewport->WorkPos.y + margin), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(360.0f * ImGui::GetIO().FontGlobalScale, viewport->WorkSize.y - 2.0f * margin),
                             ImGuiCond_FirstUseEver);
    // Never taller than the window, also after it shrinks: the panel scrolls instead.
    ImGui::SetNextWindowSizeConstraints(
        ImVec2(160.0f, 120.0f), ImVec2(viewport->WorkSize.x, std::max(120.0f, viewport->WorkSize.y - 2.0f * margin)));
    ImGui::SetNextWindowBgAlpha(0.88f);
    if (ImGui::Begin("Sweep", nullptr, ImGuiWindowFlags_MenuBar)) {
      draw_menu_bar();
      draw_file_panel();
      draw_display_panel();
      draw_objects_panel();
      draw_create_panel();
      draw_material_panel();
      draw_stats_panel();
    }
    panel_right_ = ImGui::GetWindowPos().x + ImGui::GetWindowSize().x;
    ImGui::End();

    // The edit panel: fixed to the top right, as tall as its contents (at most the window).
    const float edit_width = 350.0f * std::max(1.0f, ImGui::GetIO().FontGlobalScale);
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - margin, viewport->WorkPos.y + margin),
                            ImGuiCond_Always, ImVec2(1.0f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(edit_width, 0.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(edit_width, 60.0f),
                                        ImVec2(edit_width, std::max(120.0f, viewport->WorkSize.y - 2.0f * margin)));
    ImGui::SetNextWindowBgAlpha(0.88f);
    if (ImGui::Begin("Edit", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse)) draw_selection_panel();
    edit_left_ = ImGui::GetWindowPos().x;
    edit_bottom_ = ImGui::GetWindowPos().y + ImGui::GetWindowSize().y;
    ImGui::End();
    draw_error_panel();
  }

  void draw_menu_bar() {
    if (!ImGui::BeginMenuBar()) return;
    if (ImGui::BeginMenu("File")) {
      if (ImGui::MenuItem("Save", "Ctrl+S")) save_current();
      if (ImGui::MenuItem("Save As...", "Ctrl+Shift+S")) save_as_requested_ = true;
      ImGui::Separator();
      if (ImGui::MenuItem("Quit", "Esc")) request_quit();
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
      const std::string undo_text = "Undo " + session_.undo_label();
      const std::string redo_text = "Redo " + session_.redo_label();
      if (ImGui::MenuItem(undo_text.c_str(), "Ctrl+Z", false, session_.can_undo())) undo();
      if (ImGui::MenuItem(redo_text.c_str(), "Ctrl+Y", false, session_.can_redo())) redo();
      ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
      bool profile = profile_view_;
      if (ImGui::MenuItem("Profile view (xy)", "V", &profile)) set_profile_view(profile);
      ImGui::EndMenu();
    }
    ImGui::EndMenuBar();
  }

  void draw_file_panel() {
    if (!ImGui::CollapsingHeader("File", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const std::string& file = session_.file();
    ImGui::TextDisabled("%s%s", file.empty() ? "(no file)" : file.c_str(),
                        session_.dirty() ? "  (unsaved changes)" : "");
    bool open = ImGui::InputText("##open", open_field_.text.data(), open_field_.text.size(),
                                 ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    open |= ImGui::Button("Open");
    if (open) request_open(open_field_.get());
    if (!recent_.empty() && ImGui::TreeNode("Recent files")) {
      std::string chosen;
      for (const std::string& path : recent_) {
        if (ImGui::Selectable(path.c_str())) chosen = path;
      }
      ImGui::TreePop();
      if (!chosen.empty()) request_open(chosen);
    }
    ImGui::TextDisabled("or drop a .swp file onto the window");
    if (ImGui::Button("Save [Ctrl+S]")) save_current();
    ImGui::SameLine();
    if (ImGui::Button("Save As...")) save_as_requested_ = true;
    ImGui::Separator();
    ImGui::InputText("##export", export_field_.text.data(), export_field_.text.size());
    ImGui::SameLine();
    if (ImGui::Button("Export OBJ")) export_obj(export_field_.get());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Writes PREFIX_NAME.obj for every surface");
    ImGui::InputText("##screenshot", screenshot_field_.text.data(), screenshot_field_.text.size());
    ImGui::SameLine();
    if (ImGui::Button("Save PNG")) pending_screenshot_ = screenshot_field_.get();
    if (!status_.empty()) ImGui::TextWrapped("%s", status_.c_str());
  }

  void draw_display_panel() {
    if (!ImGui::CollapsingHeader("Display", ImGuiTreeNodeFlags_DefaultOpen)) return;
    int surface = static_cast<int>(settings_.surface);
    if (ImGui::Combo("Surfaces [s]", &surface, "Smooth shaded\0Wireframe + normals\0Off\0")) {
      settings_.surface = static_cast<SurfaceMode>(surface);
    }
    int curves = static_cast<int>(settings_.curves);
    if (ImGui::Combo("Curves [c]", &curves, "Curves\0Curves + frames\0Off\0")) {
      settings_.curves = static_cast<CurveMode>(curves);
    }
    ImGui::Checkbox("Control points [p]", &settings_.control_points);
    bool profile = profile_view_;
    if (ImGui::Checkbox("Profile view (xy) [v]", &profile)) set_profile_view(profile);
    if (!profile_view_) {
      bool ortho = camera_.projection == render::Projection::Orthographic;
      ImGui::SameLine();
      if (ImGui::Checkbox("Orthographic", &ortho)) {
        camera_.projection = ortho ? render::Projection::Orthographic : render::Projection::Perspective;
      }
      if (ImGui::Button("Front")) set_view(render::ViewPreset::Front);
      ImGui::SameLine();
      if (ImGui::Button("Top")) set_view(render::ViewPreset::Top);
      ImGui::SameLine();
      if (ImGui::Button("Side")) set_view(render::ViewPreset::Side);
      ImGui::SameLine();
    }
    if (ImGui::Button("Reset [space]")) reset_camera();
    // How sweeps are framed: re-evaluates the scene (a view choice, not an edit of the file).
    EvaluationOptions evaluation = session_.evaluation();
    int method = evaluation.frames.method == FrameMethod::RotationMinimizing ? 0 : 1;
    int seam = evaluation.seam == SeamMode::Symmetric ? 1 : 0;
    bool changed = ImGui::Combo("Frames", &method, "rotation-minimizing\0projection (original)\0");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("How 3D sweep curves carry their frames");
    changed |= ImGui::Combo("Seam", &seam, "full\0symmetric\0");
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "How a tube along a closed sweep closes: spread the whole seam angle, or only\nwhat the profile's rotational "
          "symmetry does not absorb");
    if (changed) {
      evaluation.frames.method = method == 0 ? FrameMethod::RotationMinimizing : FrameMethod::Projection;
      evaluation.seam = seam == 1 ? SeamMode::Symmetric : SeamMode::Full;
      try {
        session_.set_evaluation(evaluation);
      } catch (const std::exception& e) {
        error_ = std::string("cannot re-evaluate: ") + e.what();
      }
    }
    ImGui::TextDisabled(profile_view_ ? "drag: left/middle pan, right zoom"
                                      : "drag: left rotate, right zoom, middle pan");
  }

  /// STEPS of object `index` as an undoable slider (one step per drag or typed value).
  void steps_slider(int index) {
    const Object& object = doc().objects[std::size_t(index)];
    int steps = object.steps;
    ImGui::SetNextItemWidth(-60.0f);
    // Logarithmic so both 5 and 500 are reachable; Ctrl+click types any value.
    const bool changed =
        ImGui::SliderInt("STEPS", &steps, 1, std::max(1000, object.steps), "%d", ImGuiSliderFlags_Logarithmic) &&
        steps != object.steps && steps >= 1;
    continuous_item(changed, "set STEPS", [index, steps](Document& d) { return set_steps(d, index, steps); });
  }

  void draw_object_row(std::size_t i) {
    const Object& object = doc().objects[i];
    ImGui::PushID(static_cast<int>(i));
    bool visible = settings_.is_visible(i);
    if (ImGui::Checkbox("##visible", &visible)) {
      settings_.visible.resize(doc().objects.size(), true);
      settings_.visible[i] = visible;
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show or hide");
    ImGui::SameLine();
    const std::string label =
        display_name(doc(), static_cast<int>(i)) + "  (" + std::string(keyword(object.kind)) + ")";
    if (ImGui::Selectable(label.c_str(), selected_ == int(i))) select_object(int(i));
    if (object.kind == ObjectKind::GeneralizedCylinder) {
      ImGui::Indent();
      ImGui::TextDisabled("profile %s, sweep %s", display_name(doc(), object.profile).c_str(),
                          display_name(doc(), object.sweep).c_str());
      ImGui::Unindent();
    }
    ImGui::PopID();
  }

  void draw_objects_panel() {
    if (!ImGui::CollapsingHeader("Objects", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (doc().objects.empty()) ImGui::TextDisabled("(empty scene)");
    for (bool surfaces : {false, true}) {
      bool any = false;
      for (const Object& o : doc().objects) any |= is_surface(o.kind) == surfaces;
      if (!any) continue;
      if (ImGui::TreeNodeEx(surfaces ? "Surfaces" : "Curves", ImGuiTreeNodeFlags_DefaultOpen)) {
        // A deletion inside the loop would shift the rows: rows only select, edits come later.
        for (std::size_t i = 0; i < doc().objects.size(); ++i) {
          if (is_surface(doc().objects[i].kind) == surfaces) draw_object_row(i);
        }
        ImGui::TreePop();
      }
    }
  }

  /// The selected object: name, numbers, points, and the edits its kind allows.
  void draw_selection_panel() {
    if (ImGui::Button("Undo")) undo();
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Ctrl+Z: %s", session_.can_undo() ? session_.undo_label().c_str() : "nothing to undo");
    ImGui::SameLine();
    if (ImGui::Button("Redo")) redo();
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("Ctrl+Shift+Z / Ctrl+Y: %s",
                        session_.can_redo() ? session_.redo_label().c_str() : "nothing to redo");
    if (selected_ < 0 || selected_ >= int(doc().objects.size())) {
      ImGui::TextDisabled("click a curve in the view, or a name in Objects");
      return;
    }
    const int index = selected_;
    ImGui::PushID("selection");
    const Object& object = doc().objects[std::size_t(index)];
    ImGui::Text("%s  (%s)", display_name(doc(), index).c_str(), std::string(keyword(object.kind)).c_str());

    // Rename: Enter commits.
    if (rename_for_ != index) {
      rename_field_.set(object.name);
      rename_for_ = index;
    }
    ImGui::SetNextItemWidth(-130.0f);
    if (ImGui::InputTextWithHint("##name", "(anonymous)", rename_field_.text.data(), rename_field_.text.size(),
                                 ImGuiInputTextFlags_EnterReturnsTrue)) {
      const std::string name = rename_field_.get();
      if (name != object.name) run_edit("rename", [index, name](Document& d) { return rename_object(d, index, name); });
      rename_for_ = -1;
    }
    ImGui::SameLine();
    if (ImGui::Button("Rename")) {
      const std::string name = rename_field_.get();
      run_edit("rename", [index, name](Document& d) { return rename_object(d, index, name); });
      rename_for_ = -1;
    }
    ImGui::SameLine();
    if (ImGui::Button("Delete")) {
      const std::string label = "delete " + display_name(doc(), index);
      if (run_edit(label, [index](Document& d) { return delete_object(d, index); })) {
        if (std::size_t(index) < settings_.visible.size()) settings_.visible.erase(settings_.visible.begin() + index);
        deselect();
        ImGui::PopID();
        return;
      }
    }

    if (is_curve(object.kind) || object.kind == ObjectKind::SurfaceOfRevolution) steps_slider(index);
    if (object.kind == ObjectKind::Circle) {
      double radius = object.radius;
      ImGui::SetNextItemWidth(-60.0f);
      const bool changed =
          ImGui::DragScalar("radius", ImGuiDataType_Double, &radius, float(std::max(1e-3, 0.005 * radius)), nullptr,
                            nullptr, "%.6g", ImGuiSliderFlags_NoRoundToFormat) &&
          radius != object.radius;
      continuous_item(changed, "set radius", [index, radius](Document& d) { return set_radius(d, index, radius); });
    }
    if (has_control_points(object.kind)) draw_point_editing(index);
    ImGui::PopID();
  }

  void draw_point_editing(int index) {
    const Object& object = doc().objects[std::size_t(index)];
    const bool planar = is_planar_curve(object.kind);
    const bool bezier = object.kind == ObjectKind::Bezier2 || object.kind == ObjectKind::Bezier3;
    const int dims = planar ? 2 : 3;
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("Drag the handles in the view%s. Hold X or Y to move along one axis.",
                       planar ? " (2D points stay in the xy-plane)" : " (in the plane facing you; Z too)");
    ImGui::PopStyleColor();
    ImGui::Checkbox("Snap to grid", &snap_);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::InputDouble("##grid", &snap_size_, 0.0, 0.0, "%.4g");
    if (!(snap_size_ > 0.0)) snap_size_ = 0.25;

    const float row_height = ImGui::GetFrameHeightWithSpacing();
    const float table_height = std::min(12.5f, float(object.points.size()) + 1.5f) * row_height;
    if (ImGui::BeginTable("points", dims + 1,
                          ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV | ImGuiTableFlags_ScrollY |
                              ImGuiTableFlags_SizingStretchProp,
                          ImVec2(0.0f, table_height))) {
      ImGui::TableSetupScrollFreeze(0, 1);
      ImGui::TableSetupColumn("#", ImGuiTableColumnFlags_WidthFixed, 28.0f * ImGui::GetIO().FontGlobalScale + 10.0f);
      ImGui::TableSetupColumn("x");
      ImGui::TableSetupColumn("y");
      if (dims == 3) ImGui::TableSetupColumn("z");
      ImGui::TableHeadersRow();
      const std::vector<int> partners = selected_point_ >= 0 && selected_point_ < int(object.points.size())
                                            ? seam_partners(object, selected_point_)
                                            : std::vector<int>{};
      ImGuiListClipper clipper;
      clipper.Begin(int(object.points.size()));
      while (clipper.Step()) {
        for (int row = clipper.DisplayStart; row < clipper.DisplayEnd; ++row) {
          ImGui::TableNextRow();
          ImGui::PushID(row);
          ImGui::TableSetColumnIndex(0);
          const bool chosen = std::find(partners.begin(), partners.end(), row) != partners.end();
          if (ImGui::Selectable(std::to_string(row).c_str(), chosen)) selected_point_ = row;
          const glm::dvec3 current = doc().objects[std::size_t(index)].points[std::size_t(row)];
          for (int axis = 0; axis < dims; ++axis) {
            ImGui::TableSetColumnIndex(axis + 1);
            ImGui::PushID(axis);
            ImGui::SetNextItemWidth(-1.0f);
            double value = current[axis];
            const bool changed = ImGui::DragScalar("##v", ImGuiDataType_Double, &value, 0.005f, nullptr, nullptr,
                                                   "%.6g", ImGuiSliderFlags_NoRoundToFormat) &&
                                 value != current[axis];
            if (ImGui::IsItemActivated()) selected_point_ = row;
            glm::dvec3 moved = current;
            moved[axis] = value;
            continuous_item(changed, "move point",
                            [index, row, moved](Document& d) { return move_point(d, index, row, moved); });
            ImGui::PopID();
          }
          ImGui::PopID();
        }
      }
      ImGui::EndTable();
    }

    const int count = int(object.points.size());
    const bool has_point = selected_point_ >= 0 && selected_point_ < count;
    if (bezier) {
      const int pieces = int(piece_count(object.kind, count));
      const int piece = has_point ? std::clamp(selected_point_ / 3, 0, std::max(0, pieces - 1)) : 0;
      ImGui::SetNextItemWidth(120.0f);
      ImGui::SliderFloat("##t", &split_t_, 0.01f, 0.99f, "t = %.2f");
      ImGui::SameLine();
      const std::string split_label = "Split piece " + std::to_string(piece);
      if (ImGui::Button(split_label.c_str())) {
        const double t = double(split_t_);
        if (run_edit("split piece",
                     [index, piece, t](Document& d) { return split_bezier_piece(d, index, piece, t); })) {
          selected_point_ = 3 * piece + 3;  // the new joint
        }
      }
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("de Casteljau: the curve keeps its shape, the piece becomes two");
      const bool joint = has_point && selected_point_ % 3 == 0 && selected_point_ > 0 && selected_point_ < count - 1;
      ImGui::SameLine();
      if (!joint) ImGui::BeginDisabled();
      if (ImGui::Button("Join at joint")) {
        const int at = selected_point_;
        if (run_edit("join pieces", [index, at](Document& d) { return join_bezier_pieces(d, index, at); })) {
          selected_point_ = at - 1;
        }
      }
      if (!joint) ImGui::EndDisabled();
    } else {
      if (!has_point) ImGui::BeginDisabled();
      if (ImGui::Button("Insert after [i]")) insert_after_selected_point();
      ImGui::SameLine();
      if (ImGui::Button("Delete point [Del]")) delete_selected_point();
      if (!has_point) ImGui::EndDisabled();
    }
    if (bezier && has_point) {
      ImGui::SameLine();
      if (ImGui::Button("Delete [Del]")) delete_selected_point();
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("Deleting a joint joins its pieces");
    }
  }

  void draw_create_panel() {
    if (!ImGui::CollapsingHeader("Create")) return;
    ImGui::PushID("create");
    ImGui::Combo("curve", &template_choice_,
                 "open B-spline (2D)\0closed B-spline (2D)\0open B-spline (3D)\0Bezier (2D)\0Bezier (3D)\0circle\0");
    ImGui::SetNextItemWidth(-120.0f);
    ImGui::InputTextWithHint("##curve_name", "name (empty: automatic)", curve_name_.text.data(),
                             curve_name_.text.size());
    ImGui::SameLine();
    if (ImGui::Button("Add curve")) {
      static constexpr std::array<CurveTemplate, 6> kTemplates{
          CurveTemplate::OpenBSpline2, CurveTemplate::ClosedBSpline2, CurveTemplate::OpenBSpline3,
          CurveTemplate::Bezier2,      CurveTemplate::Bezier3,        CurveTemplate::Circle};
      const CurveTemplate shape = kTemplates[std::size_t(std::clamp(template_choice_, 0, 5))];
      std::string name = curve_name_.get();
      if (name.empty()) name = unique_name(doc(), shape == CurveTemplate::Circle ? "circle" : "curve");
      int added = -1;
      if (run_edit("add curve " + name, [shape, name, &added](Document& d) {
            added = add_curve(d, shape, name);
            return Change{{added}, true};
          })) {
        select_object(added);
        curve_name_.set("");
      }
    }
    ImGui::Separator();
    ImGui::Combo("surface", &surface_choice_, "surface of revolution\0generalized cylinder\0");
    // Curves to choose from: planar ones for the profile, any for the sweep.
    std::vector<int> planar_curves;
    std::vector<int> curves;
    for (std::size_t i = 0; i < doc().objects.size(); ++i) {
      if (is_planar_curve(doc().objects[i].kind)) planar_curves.push_back(int(i));
      if (is_curve(doc().objects[i].kind)) curves.push_back(int(i));
    }
    curve_combo("profile", planar_curves, profile_choice_);
    const bool cylinder = surface_choice_ == 1;
    if (cylinder) curve_combo("sweep", curves, sweep_choice_);
    if (!cylinder) ImGui::InputInt("copies (STEPS)", &surface_steps_);
    surface_steps_ = std::clamp(surface_steps_, 1, 100000);
    ImGui::SetNextItemWidth(-120.0f);
    ImGui::InputTextWithHint("##surface_name", "name (empty: automatic)", surface_name_.text.data(),
                             surface_name_.text.size());
    ImGui::SameLine();
    if (ImGui::Button("Add surface")) {
      const ObjectKind kind = cylinder ? ObjectKind::GeneralizedCylinder : ObjectKind::SurfaceOfRevolution;
      std::string name = surface_name_.get();
      if (name.empty()) name = unique_name(doc(), cylinder ? "cylinder" : "revolution");
      const int profile = profile_choice_;
      const int sweep = cylinder ? sweep_choice_ : -1;
      const int steps = surface_steps_;
      int added = -1;
      if (profile < 0 || (cylinder && sweep < 0)) {
        error_ = cylinder ? "choose a 2D profile curve and a sweep curve first" : "choose a 2D profile curve first";
      } else if (run_edit("add surface " + name, [kind, name, profile, sweep, steps, &added](Document& d) {
                   added = add_surface(d, kind, name, profile, sweep, steps);
                   return Change{{added}, true};
                 })) {
        select_object(added);
        surface_name_.set("");
      }
    }
    ImGui::PopID();
  }

  /// A combo box of curves by display name; `choice` is an object index or -1.
  void curve_combo(const char* label, const std::vector<int>& candidates, int& choice) {
    if (std::find(candidates.begin(), candidates.end(), choice) == candidates.end()) {
      choice = candidates.empty() ? -1 : candidates.front();
    }
    const std::string preview = choice >= 0 ? display_name(doc(), choice) : "(no curve)";
    if (ImGui::BeginCombo(label, preview.c_str())) {
      for (int i : candidates) {
        if (ImGui::Selectable(display_name(doc(), i).c_str(), i == choice)) choice = i;
      }
      ImGui::EndCombo();
    }
  }

  void draw_material_panel() {
    if (!ImGui::CollapsingHeader("Material and light")) return;
    render::Material& m = settings_.material;
    render::Lighting& l = settings_.lighting;
    ImGui::ColorEdit3("Colour", &m.color.x);
    ImGui::ColorEdit3("Specular", &m.specular.x);
    ImGui::SliderFloat("Shininess", &m.shininess, 1.0f, 256.0f, "%.0f", ImGuiSliderFlags_Logarithmic);
    ImGui::Checkbox("Two-sided lighting", &m.two_sided);
    ImGui::ColorEdit3("Key light", &l.key_color.x);
    ImGui::ColorEdit3("Fill light", &l.fill_color.x);
    ImGui::ColorEdit3("Ambient", &l.ambient.x);
    ImGui::ColorEdit3("Background", &settings_.background.x);
    ImGui::SliderFloat("Frame length", &settings_.frame_length, 0.005f, 0.5f, "%.3f", ImGuiSliderFlags_Logarithmic);
    ImGui::SliderFloat("Normal length", &settings_.normal_length, 0.005f, 0.5f, "%.3f", ImGuiSliderFlags_Logarithmic);
  }

  void draw_stats_panel() {
    if (!ImGui::CollapsingHeader("Stats", ImGuiTreeNodeFlags_DefaultOpen)) return;
    const render::RenderStats& stats = renderer_->stats();
    double mean = 0.0;
    for (double ms : frame_ms_) mean += ms;
    if (!frame_ms_.empty()) mean /= double(frame_ms_.size());
    ImGui::Text("vertices   %zu", stats.vertices);
    ImGui::Text("triangles  %zu", stats.triangles);
    ImGui::Text("curve samples %zu", stats.curve_samples);
    ImGui::Text("frame time %.2f ms (%.0f fps)", mean, mean > 0.0 ? 1000.0 / mean : 0.0);
    if (remesh_ms_.empty()) {
      ImGui::TextDisabled("re-mesh: no edit yet");
    } else {
      ImGui::Text("re-mesh %.2f ms (last edit, %zu object%s)", session_.last_remesh_ms(),
                  session_.last_remesh_objects(), session_.last_remesh_objects() == 1 ? "" : "s");
    }
    draw_sweep_diagnostics();
    ImGui::TextDisabled("%s", gl_description_.c_str());
  }

  /// Seam angle, twist and folds of every generalized cylinder.
  void draw_sweep_diagnostics() {
    const Scene& scene = session_.scene();
    for (std::size_t i = 0; i < doc().objects.size() && i < scene.objects.size(); ++i) {
      if (doc().objects[i].kind != ObjectKind::GeneralizedCylinder) continue;
      const SweepDiagnostics& d = scene.objects[i].diagnostics;
      const double degrees = 180.0 / 3.14159265358979323846;
      const std::string name = display_name(doc(), int(i));
      if (d.closed) {
        ImGui::Text("%s: seam %.1f deg, twist %.1f deg", name.c_str(), d.seam_angle * degrees, d.total_twist * degrees);
      } else {
        ImGui::Text("%s: open sweep, twist %.1f deg", name.c_str(), d.total_twist * degrees);
      }
      if (!d.folds.empty()) {
        ImGui::SameLine();
        ImGui::TextColored(ImVec4(kFold.r, kFold.g, kFold.b, 1.0f), "%zu fold%s", d.folds.size(),
                           d.folds.size() == 1 ? "" : "s");
        if (ImGui::IsItemHovered())
          ImGui::SetTooltip(
              "The tube folds over itself where the sweep bends tighter than the profile's radius\n(shown as magenta "
              "sweep samples when curves are on)");
      }
    }
  }

  void draw_error_panel() {
    if (error_.empty()) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    // Centred over the 3D view, right of the main panel.
    const float left = options_.show_ui ? panel_right_ : viewport->WorkPos.x;
    const float right = options_.show_ui && edit_left_ > left ? edit_left_ : viewport->WorkPos.x + viewport->WorkSize.x;
    const float width = std::max(200.0f, right - left - 24.0f);
    ImGui::SetNextWindowPos(ImVec2(left + 12.0f, viewport->WorkPos.y + 12.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSize(ImVec2(std::min(720.0f, width), 0.0f), ImGuiCond_Always);
    if (ImGui::Begin("Error", nullptr, ImGuiWindowFlags_NoCollapse)) {
      ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
      ImGui::TextWrapped("%s", error_.c_str());
      ImGui::PopStyleColor();
      if (ImGui::Button("Dismiss")) error_.clear();
    }
    ImGui::End();
  }

  /// The unsaved-changes question and the Save As dialog.
  void draw_modals() {
    if (confirm_requested_) {
      ImGui::OpenPopup("Unsaved changes");
      confirm_requested_ = false;
    }
    if (save_as_requested_) {
      ImGui::OpenPopup("Save as");
      save_as_field_.set(session_.file().empty() ? "untitled.swp" : session_.file());
      save_as_error_.clear();
      save_as_requested_ = false;
    }
    const ImVec2 centre = ImGui::GetMainViewport()->GetCenter();
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Unsaved changes", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
      const std::string& file = session_.file();
      ImGui::Text("%s has unsaved changes.",
                  file.empty() ? "The document" : std::filesystem::path(file).filename().string().c_str());
      ImGui::Text(pending_ == Pending::Quit ? "Save them before quitting?" : "Save them before opening another file?");
      if (!save_as_error_.empty()) ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", save_as_error_.c_str());
      if (ImGui::Button("Save")) {
        if (file.empty()) {
          ImGui::CloseCurrentPopup();
          save_as_requested_ = true;  // the pending action runs after Save As succeeds
        } else if (save_to(file)) {
          ImGui::CloseCurrentPopup();
          run_pending();
        } else {
          save_as_error_ = session_.error();
        }
      }
      ImGui::SameLine();
      if (ImGui::Button("Discard")) {
        ImGui::CloseCurrentPopup();
        save_as_error_.clear();
        if (pending_ == Pending::Quit) {
          glfwSetWindowShouldClose(window_, GLFW_TRUE);
          pending_ = Pending::None;
        } else {
          run_pending();
        }
      }
      ImGui::SameLine();
      // Not on the frame it appears: the Escape that asked the question is still down then.
      if (ImGui::Button("Cancel") ||
          (!ImGui::IsWindowAppearing() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))) {
        ImGui::CloseCurrentPopup();
        save_as_error_.clear();
        pending_ = Pending::None;
      }
      ImGui::EndPopup();
    }
    ImGui::SetNextWindowPos(centre, ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    if (ImGui::BeginPopupModal("Save as", nullptr, ImGuiWindowFlags_AlwaysAutoResize)) {
      ImGui::Text("Save the document as:");
      if (ImGui::IsWindowAppearing()) ImGui::SetKeyboardFocusHere();
      ImGui::SetNextItemWidth(480.0f * ImGui::GetIO().FontGlobalScale);
      const bool enter = ImGui::InputText("##path", save_as_field_.text.data(), save_as_field_.text.size(),
                                          ImGuiInputTextFlags_EnterReturnsTrue);
      if (!save_as_error_.empty()) {
        ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + 480.0f * ImGui::GetIO().FontGlobalScale);
        ImGui::TextColored(ImVec4(1.0f, 0.45f, 0.4f, 1.0f), "%s", save_as_error_.c_str());
        ImGui::PopTextWrapPos();
      }
      if (ImGui::Button("Save") || enter) {
        if (save_to(save_as_field_.get())) {
          save_as_error_.clear();
          ImGui::CloseCurrentPopup();
          if (pending_ != Pending::None) run_pending();
        } else {
          save_as_error_ = session_.error();
        }
      }
      ImGui::SameLine();
      // Not on the frame it appears: the Escape that asked the question is still down then.
      if (ImGui::Button("Cancel") ||
          (!ImGui::IsWindowAppearing() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))) {
        save_as_error_.clear();
        pending_ = Pending::None;
        ImGui::CloseCurrentPopup();
      }
      ImGui::EndPopup();
    }
  }

  ViewerOptions options_;
  std::unique_ptr<render::GlContext> context_;
  GLFWwindow* window_ = nullptr;
  std::unique_ptr<render::Renderer> renderer_;
  bool imgui_ready_ = false;
  float panel_right_ = 0.0f;  // right edge of the main panel, to keep the error panel beside it
  float edit_left_ = 0.0f;    // left edge of the edit panel (0 until drawn)
  float edit_bottom_ = 0.0f;  // its bottom edge
  std::string gl_description_;
  std::string title_;

  EditSession session_;
  render::Camera camera_;
  render::Camera camera_before_profile_;
  bool profile_view_ = false;
  render::DisplaySettings settings_;

  // Selection and editing.
  int selected_ = -1;        // object index
  int selected_point_ = -1;  // control point of the selected curve
  int hovered_point_ = -1;
  PointDrag point_drag_;
  bool snap_ = false;
  double snap_size_ = 0.25;
  float split_t_ = 0.5f;
  TextField rename_field_;
  int rename_for_ = -1;  // object whose name rename_field_ holds
  int template_choice_ = 0;
  TextField curve_name_;
  int surface_choice_ = 0;
  int profile_choice_ = -1;
  int sweep_choice_ = -1;
  int surface_steps_ = 24;
  TextField surface_name_;
  std::vector<double> remesh_ms_;  // every edit's re-mesh time, for --frame-time
  bool handles_printed_ = false;   // --select: printed once the layout is stable
  int stable_frames_ = 0;
  glm::dvec2 last_layout_{-1.0};

  // Saving and the questions before losing changes.
  Pending pending_ = Pending::None;
  std::string pending_path_;
  bool confirm_requested_ = false;
  bool save_as_requested_ = false;
  TextField save_as_field_;
  std::string save_as_error_;

  std::string error_;   // shown in the Error panel (file:line:column for parse errors)
  std::string status_;  // last thing done
  TextField open_field_;
  TextField export_field_;
  TextField screenshot_field_;
  std::deque<std::string> recent_;
  std::vector<std::string> dropped_;
  std::vector<KeyPress> pressed_keys_;  // since the last frame
  std::string pending_screenshot_;

  int drag_button_ = -1;
  bool drag_moved_ = false;
  glm::dvec2 drag_last_{0.0};
  std::deque<double> frame_ms_;
};

void print_no_display() {
  std::fprintf(stderr,
               "sweep: no display to open a window on (DISPLAY/WAYLAND_DISPLAY unset or unusable); "
               "use `sweep render FILE.swp -o OUT.png` to render headless\n");
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
      doc = load_swp_file(options.file);
    } catch (const ParseError& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 1;
    }
  }
  Viewer viewer(options);
  try {
    viewer.start_up();
  } catch (const NoDisplayError&) {
    print_no_display();
    return 1;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 1;
  }
  if (!options.file.empty() && !viewer.show_document(std::move(doc), options.file)) {
    std::fprintf(stderr, "%s\n", viewer.error().c_str());
    return 1;
  }
  if (!options.select.empty() && !viewer.select_by_name(options.select)) {
    std::fprintf(stderr, "sweep: no object named '%s'\n", options.select.c_str());
    return 1;
  }
  return viewer.run();
}

}  // namespace sweep::viewer
