#include "app/viewer/viewer.hpp"

#include "app/viewer/glfw_context.hpp"
#include "core/obj_writer.hpp"
#include "core/scene.hpp"
#include "core/swp_parser.hpp"
#include "headless/png_file.hpp"
#include "render/camera.hpp"
#include "render/gl_context.hpp"
#include "render/renderer.hpp"

#include <glad/gl.h>  // before GLFW, so GLFW does not pull in the system GL header
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

class Viewer {
 public:
  explicit Viewer(const ViewerOptions& options) : options_(options) { settings_ = options.display; }
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
    glfwSetKeyCallback(window_, [](GLFWwindow* window, int key, int /*scancode*/, int action, int /*mods*/) {
      if (action == GLFW_PRESS) static_cast<Viewer*>(glfwGetWindowUserPointer(window))->pressed_keys_.push_back(key);
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
    panel_right_ = 8.0f + 340.0f * std::max(scale_x, 1.0f);  // until the panel is first drawn
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
      Scene scene = evaluate_document(doc);
      doc_ = std::move(doc);
      scene_ = std::move(scene);
      file_ = path;
      settings_.visible.assign(doc_.objects.size(), true);
      reset_camera();
      error_.clear();
      status_ = "opened " + path;
      remember_recent(path);
      open_field_.set(path);
      const std::string stem = std::filesystem::path(path).stem().string();
      export_field_.set(stem);
      screenshot_field_.set(stem + ".png");
      if (window_) glfwSetWindowTitle(window_, ("Sweep - " + path).c_str());
      return true;
    } catch (const std::exception& e) {  // e.g. out of memory while evaluating
      error_ = path + ": " + e.what();
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
      ImGui::NewFrame();
      handle_input();
      if (options_.show_ui) draw_ui();
      ImGui::Render();

      const glm::ivec2 framebuffer = context_->framebuffer_size();
      const glm::ivec2 window = context_->window_size();
      if (framebuffer.x <= 0 || framebuffer.y <= 0) {  // minimised: nothing to draw
        glfwWaitEventsTimeout(0.1);
        continue;
      }
      settings_.pixel_ratio = window.x > 0 ? float(framebuffer.x) / float(window.x) : 1.0f;
      camera_.lens_shift = {panel_share(), 0.0};  // centre the scene right of the panel
      glBindFramebuffer(GL_FRAMEBUFFER, 0);
      renderer_->draw(doc_, scene_, camera_, framebuffer, settings_);
      ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

      ++frame;
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
    }
    return 0;
  }

 private:
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

  /// Share of the window's width covered by the main panel (0 without the UI).
  double panel_share() const {
    const glm::ivec2 window = context_ ? context_->window_size() : options_.window_size;
    if (!options_.show_ui || window.x <= 0) return 0.0;
    return std::clamp(double(panel_right_) / double(window.x), 0.0, 0.6);
  }

  /// Aspect ratio of the part of the window the panel leaves free, which framing fills.
  double aspect() const {
    const glm::ivec2 size = context_ ? context_->framebuffer_size() : options_.window_size;
    return size.y > 0 ? (1.0 - panel_share()) * double(size.x) / double(size.y) : 1.0;
  }

  void reset_camera() {
    const render::Projection projection = camera_.projection;
    camera_.reset(render::scene_bounds(scene_), aspect());
    camera_.projection = projection;
  }

  void set_view(render::ViewPreset preset) {
    camera_.set_view(preset);
    camera_.frame(render::scene_bounds(scene_), aspect());
  }

  void remember_recent(const std::string& path) {
    std::error_code ec;
    std::string absolute = std::filesystem::absolute(path, ec).lexically_normal().string();
    if (ec) absolute = path;
    recent_.erase(std::remove(recent_.begin(), recent_.end(), absolute), recent_.end());
    recent_.push_front(absolute);
    if (recent_.size() > kMaxRecentFiles) recent_.pop_back();
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
    if (!chosen.empty()) open_file(chosen);
  }

  /// Keyboard and mouse for the 3D view; whatever ImGui is using is left to ImGui.
  void handle_input() {
    ImGuiIO& io = ImGui::GetIO();
    std::vector<int> keys;
    keys.swap(pressed_keys_);
    // Keys typed into an ImGui field belong to the field.
    for (int key : io.WantCaptureKeyboard ? std::vector<int>{} : keys) {
      switch (key) {
        case GLFW_KEY_S: settings_.surface = render::next(settings_.surface); break;
        case GLFW_KEY_C: settings_.curves = render::next(settings_.curves); break;
        case GLFW_KEY_P: settings_.control_points = !settings_.control_points; break;
        case GLFW_KEY_SPACE: reset_camera(); break;
        case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(window_, GLFW_TRUE); break;
        default: break;
      }
    }

    // Arcball coordinates are centred on the free part of the window, where the scene is.
    const double panel = panel_share() * double(io.DisplaySize.x);
    const glm::dvec2 window_size(double(io.DisplaySize.x) - panel, io.DisplaySize.y);
    const glm::dvec2 pointer(double(io.MousePos.x) - panel, io.MousePos.y);
    if (!io.WantCaptureMouse) {
      for (int button = 0; button < 3; ++button) {
        if (ImGui::IsMouseClicked(button) && drag_button_ < 0) {
          drag_button_ = button;
          drag_last_ = pointer;
        }
      }
      if (io.MouseWheel != 0.0f) camera_.zoom(std::pow(0.88, double(io.MouseWheel)));
    }
    if (drag_button_ >= 0) {
      if (!ImGui::IsMouseDown(drag_button_) || !ImGui::IsMousePosValid()) {
        drag_button_ = -1;
        return;
      }
      if (pointer == drag_last_) return;
      const glm::dvec2 from = render::arcball_point(drag_last_, window_size);
      const glm::dvec2 to = render::arcball_point(pointer, window_size);
      switch (drag_button_) {
        case ImGuiMouseButton_Left: camera_.arcball_rotate(from, to); break;
        case ImGuiMouseButton_Right: camera_.zoom(std::exp(2.0 * (from.y - to.y))); break;  // drag up: closer
        case ImGuiMouseButton_Middle: camera_.pan(to - from); break;
        default: break;
      }
      drag_last_ = pointer;
    }
  }

  /// Validates an edited STEPS and re-evaluates what depends on it; keeps the old value when
  /// the new one breaks a rule (e.g. a cap), showing why.
  void apply_steps(int index, int steps) {
    Document candidate = doc_;
    candidate.objects[static_cast<std::size_t>(index)].steps = steps;
    try {
      validate_document(candidate, file_.empty() ? "<document>" : file_);
    } catch (const ParseError& e) {
      error_ = e.what();
      return;
    }
    doc_ = std::move(candidate);
    reevaluate(scene_, doc_, index);
    error_.clear();
  }

  void export_obj(const std::string& prefix) {
    int written = 0;
    try {
      for (std::size_t i = 0; i < doc_.objects.size(); ++i) {
        if (!is_surface(doc_.objects[i].kind)) continue;
        const std::string name = display_name(doc_, static_cast<int>(i));
        const std::string path = prefix + "_" + file_safe(name) + ".obj";
        save_obj_file(path, scene_.objects[i].mesh, "sweep: " + name + " from " + file_);
        ++written;
      }
      status_ = written == 0 ? "no surfaces to export" : "wrote " + std::to_string(written) + " OBJ file(s) " + prefix + "_*.obj";
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

  void draw_ui() {
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    const float margin = 8.0f * ImGui::GetStyle().FramePadding.y / 3.0f;
    ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + margin, viewport->WorkPos.y + margin), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(340.0f * ImGui::GetIO().FontGlobalScale, viewport->WorkSize.y - 2.0f * margin),
                             ImGuiCond_FirstUseEver);
    // Never taller than the window, also after it shrinks: the panel scrolls instead.
    ImGui::SetNextWindowSizeConstraints(ImVec2(160.0f, 120.0f),
                                        ImVec2(viewport->WorkSize.x, std::max(120.0f, viewport->WorkSize.y - 2.0f * margin)));
    ImGui::SetNextWindowBgAlpha(0.88f);
    if (ImGui::Begin("Sweep")) {
      draw_file_panel();
      draw_display_panel();
      draw_objects_panel();
      draw_material_panel();
      draw_stats_panel();
    }
    panel_right_ = ImGui::GetWindowPos().x + ImGui::GetWindowSize().x;
    ImGui::End();
    draw_error_panel();
  }

  void draw_file_panel() {
    if (!ImGui::CollapsingHeader("File", ImGuiTreeNodeFlags_DefaultOpen)) return;
    ImGui::TextDisabled("%s", file_.empty() ? "(no file)" : file_.c_str());
    bool open = ImGui::InputText("##open", open_field_.text.data(), open_field_.text.size(),
                                 ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    open |= ImGui::Button("Open");
    if (open) open_file(open_field_.get());
    if (!recent_.empty() && ImGui::TreeNode("Recent files")) {
      std::string chosen;
      for (const std::string& path : recent_) {
        if (ImGui::Selectable(path.c_str())) chosen = path;
      }
      ImGui::TreePop();
      if (!chosen.empty()) open_file(chosen);
    }
    ImGui::TextDisabled("or drop a .swp file onto the window");
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
    bool ortho = camera_.projection == render::Projection::Orthographic;
    if (ImGui::Checkbox("Orthographic", &ortho)) {
      camera_.projection = ortho ? render::Projection::Orthographic : render::Projection::Perspective;
    }
    if (ImGui::Button("Front")) set_view(render::ViewPreset::Front);
    ImGui::SameLine();
    if (ImGui::Button("Top")) set_view(render::ViewPreset::Top);
    ImGui::SameLine();
    if (ImGui::Button("Side")) set_view(render::ViewPreset::Side);
    ImGui::SameLine();
    if (ImGui::Button("Reset [space]")) reset_camera();
    ImGui::TextDisabled("drag: left rotate, right zoom, middle pan");
  }

  void draw_object_row(std::size_t i) {
    const Object& object = doc_.objects[i];
    ImGui::PushID(static_cast<int>(i));
    bool visible = settings_.is_visible(i);
    const std::string label = display_name(doc_, static_cast<int>(i)) + "  (" + std::string(keyword(object.kind)) + ")";
    if (ImGui::Checkbox(label.c_str(), &visible)) {
      settings_.visible.resize(doc_.objects.size(), true);
      settings_.visible[i] = visible;
    }
    if (is_curve(object.kind) || object.kind == ObjectKind::SurfaceOfRevolution) {
      int steps = object.steps;
      ImGui::Indent();
      ImGui::SetNextItemWidth(-60.0f);
      // Logarithmic so both 5 and 500 are reachable; Ctrl+click types any value.
      if (ImGui::SliderInt("STEPS", &steps, 1, std::max(1000, object.steps), "%d", ImGuiSliderFlags_Logarithmic) &&
          steps != object.steps && steps >= 1) {
        apply_steps(static_cast<int>(i), steps);
      }
      ImGui::Unindent();
    } else if (object.kind == ObjectKind::GeneralizedCylinder) {
      ImGui::Indent();
      ImGui::TextDisabled("profile %s, sweep %s", display_name(doc_, object.profile).c_str(),
                          display_name(doc_, object.sweep).c_str());
      ImGui::Unindent();
    }
    ImGui::PopID();
  }

  void draw_objects_panel() {
    if (!ImGui::CollapsingHeader("Objects", ImGuiTreeNodeFlags_DefaultOpen)) return;
    if (doc_.objects.empty()) ImGui::TextDisabled("(empty scene)");
    for (bool surfaces : {false, true}) {
      bool any = false;
      for (const Object& o : doc_.objects) any |= is_surface(o.kind) == surfaces;
      if (!any) continue;
      if (ImGui::TreeNodeEx(surfaces ? "Surfaces" : "Curves", ImGuiTreeNodeFlags_DefaultOpen)) {
        for (std::size_t i = 0; i < doc_.objects.size(); ++i) {
          if (is_surface(doc_.objects[i].kind) == surfaces) draw_object_row(i);
        }
        ImGui::TreePop();
      }
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
    ImGui::TextDisabled("%s", gl_description_.c_str());
  }

  void draw_error_panel() {
    if (error_.empty()) return;
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    // Centred over the 3D view, right of the main panel.
    const float left = options_.show_ui ? panel_right_ : viewport->WorkPos.x;
    const float width = std::max(200.0f, viewport->WorkPos.x + viewport->WorkSize.x - left - 24.0f);
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

  ViewerOptions options_;
  std::unique_ptr<render::GlContext> context_;
  GLFWwindow* window_ = nullptr;
  std::unique_ptr<render::Renderer> renderer_;
  bool imgui_ready_ = false;
  float panel_right_ = 0.0f;  // right edge of the main panel, to keep the error panel beside it
  std::string gl_description_;

  Document doc_;
  Scene scene_;
  std::string file_;
  render::Camera camera_;
  render::DisplaySettings settings_;

  std::string error_;   // shown in the Error panel (file:line:column for parse errors)
  std::string status_;  // last thing done
  TextField open_field_;
  TextField export_field_;
  TextField screenshot_field_;
  std::deque<std::string> recent_;
  std::vector<std::string> dropped_;
  std::vector<int> pressed_keys_;  // GLFW key codes pressed since the last frame
  std::string pending_screenshot_;

  int drag_button_ = -1;
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
  return viewer.run();
}

}  // namespace sweep::viewer
