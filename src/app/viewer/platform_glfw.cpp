// Every GLFW call of the viewer: the "glfw" context provider and the Platform window.
#include "app/viewer/platform.hpp"

#include "editor/commands.hpp"
#include "render/renderer.hpp"

// glad before GLFW, so GLFW does not pull in the system GL header (its own block: clang-format
// sorts includes within a block).
#include <glad/gl.h>

#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cstdlib>

namespace sweep::viewer {
namespace {

// The command table's keys are GLFW's codes, so presses pass through unchanged.
static_assert(int(editor::Key::Space) == GLFW_KEY_SPACE && int(editor::Key::A) == GLFW_KEY_A &&
              int(editor::Key::B) == GLFW_KEY_B && int(editor::Key::Z) == GLFW_KEY_Z &&
              int(editor::Key::N) == GLFW_KEY_N && int(editor::Key::Q) == GLFW_KEY_Q &&
              int(editor::Key::Escape) == GLFW_KEY_ESCAPE && int(editor::Key::Backspace) == GLFW_KEY_BACKSPACE &&
              int(editor::Key::Insert) == GLFW_KEY_INSERT && int(editor::Key::Delete) == GLFW_KEY_DELETE &&
              int(editor::Key::Home) == GLFW_KEY_HOME && int(editor::Key::F1) == GLFW_KEY_F1 &&
              int(editor::Key::Digit1) == GLFW_KEY_1 && int(editor::Key::Digit3) == GLFW_KEY_3 &&
              int(editor::Key::Digit7) == GLFW_KEY_7 && int(editor::Key::Keypad1) == GLFW_KEY_KP_1 &&
              int(editor::Key::Keypad3) == GLFW_KEY_KP_3 && int(editor::Key::Keypad7) == GLFW_KEY_KP_7 &&
              int(editor::Key::F) == GLFW_KEY_F && int(editor::Key::G) == GLFW_KEY_G &&
              int(editor::Key::Enter) == GLFW_KEY_ENTER && int(editor::Key::KeypadEnter) == GLFW_KEY_KP_ENTER &&
              int(editor::Key::X) == GLFW_KEY_X);

/// GLFW's last error, kept instead of printed so failures become one clear message.
std::string& last_glfw_error() {
  static std::string message;
  return message;
}

void remember_glfw_error(int /*code*/, const char* description) {
  last_glfw_error() = description ? description : "?";
}

GLFWwindow* create_window(const render::ContextRequest& request) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
#ifdef __APPLE__
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
#endif
  glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);  // HiDPI: window size follows the content scale
  glfwWindowHint(GLFW_VISIBLE, request.visible ? GLFW_TRUE : GLFW_FALSE);
  glfwWindowHint(GLFW_SAMPLES, request.samples);
  GLFWwindow* window = glfwCreateWindow(request.size.x, request.size.y, request.title.c_str(), nullptr, nullptr);
  if (window == nullptr && request.samples > 0) {
    glfwWindowHint(GLFW_SAMPLES, 0);  // no multisampled visual: plain is better than nothing
    window = glfwCreateWindow(request.size.x, request.size.y, request.title.c_str(), nullptr, nullptr);
  }
  return window;
}

/// The "glfw" provider: a window with an OpenGL 3.3 core context.
class GlfwContext final : public render::GlContext {
 public:
  explicit GlfwContext(const render::ContextRequest& request) {
    glfwSetErrorCallback(remember_glfw_error);
    if (glfwInit() != GLFW_TRUE) throw NoDisplayError("GLFW cannot start: " + last_glfw_error());
    window_ = create_window(request);
    if (window_ == nullptr) {
      const std::string reason = last_glfw_error();
      glfwTerminate();
      throw std::runtime_error("cannot open an OpenGL 3.3 core window: " + reason);
    }
    make_current();
    if (!render::load_gl_functions(glfwGetProcAddress)) {
      glfwDestroyWindow(window_);
      glfwTerminate();
      throw std::runtime_error("cannot load the OpenGL 3.3 core functions");
    }
  }
  ~GlfwContext() override {
    glfwDestroyWindow(window_);
    glfwTerminate();
  }
  GlfwContext(const GlfwContext&) = delete;
  GlfwContext& operator=(const GlfwContext&) = delete;

  std::string_view provider() const override { return "glfw"; }
  void make_current() override { glfwMakeContextCurrent(window_); }
  glm::ivec2 framebuffer_size() const override {
    glm::ivec2 size;
    glfwGetFramebufferSize(window_, &size.x, &size.y);
    return size;
  }
  glm::ivec2 window_size() const override {
    glm::ivec2 size;
    glfwGetWindowSize(window_, &size.x, &size.y);
    return size;
  }
  void present() override { glfwSwapBuffers(window_); }
  void* native_window() const override { return window_; }

 private:
  GLFWwindow* window_ = nullptr;
};

GLFWwindow* glfw(void* window) {
  return static_cast<GLFWwindow*>(window);
}

}  // namespace

struct Platform::Queue {
  std::vector<KeyPress> keys;
  std::vector<std::string> dropped;
  bool close_requested = false;
  bool event = true;  // the first frame is drawn

  static Queue& of(GLFWwindow* window) { return *static_cast<Queue*>(glfwGetWindowUserPointer(window)); }
  static void any(GLFWwindow* window) { of(window).event = true; }
};

bool display_variable_set() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 != nullptr && *x11 != '\0') || (wayland != nullptr && *wayland != '\0');
}

namespace {

/// Our callbacks, set before ImGui's backend, which chains to them: each one marks that
/// something happened (so the viewer redraws); keys, drops and close requests are queued.
void install_callbacks(GLFWwindow* window) {
  glfwSetKeyCallback(window, [](GLFWwindow* w, int key, int /*scancode*/, int action, int mods) {
    Platform::Queue::any(w);
    if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
    // Queued rather than polled through ImGui: ImGui 1.86 only sees the key state at each
    // frame, so a tap shorter than a (slow) frame would be lost.
    Platform::Queue::of(w).keys.push_back(
        {key, (mods & (GLFW_MOD_CONTROL | GLFW_MOD_SUPER)) != 0, (mods & GLFW_MOD_SHIFT) != 0});
  });
  glfwSetDropCallback(window, [](GLFWwindow* w, int count, const char** paths) {
    Platform::Queue::any(w);
    for (int i = 0; i < count; ++i) Platform::Queue::of(w).dropped.emplace_back(paths[i]);
  });
  glfwSetWindowCloseCallback(window, [](GLFWwindow* w) {
    Platform::Queue::any(w);
    Platform::Queue::of(w).close_requested = true;
    glfwSetWindowShouldClose(w, GLFW_FALSE);  // the viewer decides (it may ask about unsaved changes)
  });
  glfwSetCharCallback(window, [](GLFWwindow* w, unsigned int) { Platform::Queue::any(w); });
  glfwSetCursorPosCallback(window, [](GLFWwindow* w, double, double) { Platform::Queue::any(w); });
  glfwSetCursorEnterCallback(window, [](GLFWwindow* w, int) { Platform::Queue::any(w); });
  glfwSetMouseButtonCallback(window, [](GLFWwindow* w, int, int, int) { Platform::Queue::any(w); });
  glfwSetScrollCallback(window, [](GLFWwindow* w, double, double) { Platform::Queue::any(w); });
  glfwSetWindowFocusCallback(window, [](GLFWwindow* w, int) { Platform::Queue::any(w); });
  glfwSetFramebufferSizeCallback(window, [](GLFWwindow* w, int, int) { Platform::Queue::any(w); });
  glfwSetWindowRefreshCallback(window, [](GLFWwindow* w) { Platform::Queue::any(w); });
}

}  // namespace

Platform::Platform(glm::ivec2 size, bool vsync) : queue_(std::make_unique<Queue>()) {
  render::register_context_provider("glfw", [](const render::ContextRequest& request) {
    return std::unique_ptr<render::GlContext>(std::make_unique<GlfwContext>(request));
  });
  render::ContextRequest request;
  request.size = size;
  request.samples = 0;
  request.title = "Sweep";
  context_ = render::create_context("glfw", request);
  window_ = context_->native_window();
  glfwSetWindowUserPointer(glfw(window_), queue_.get());
  install_callbacks(glfw(window_));
  glfwSwapInterval(vsync ? 1 : 0);
  float scale_y = 1.0f;
  glfwGetWindowContentScale(glfw(window_), &content_scale_, &scale_y);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // no imgui.ini dropped into the working directory
  ImGui::StyleColorsDark();
  if (content_scale_ > 1.0f) {
    ImGui::GetStyle().ScaleAllSizes(content_scale_);
    ImGui::GetIO().FontGlobalScale = content_scale_;
  }
  ImGui_ImplGlfw_InitForOpenGL(glfw(window_), true);  // chains to the callbacks above
  ImGui_ImplOpenGL3_Init("#version 330 core");
  imgui_ready_ = true;
}

Platform::~Platform() {
  if (imgui_ready_) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
}

bool Platform::wait(double timeout) {
  if (timeout < 0.0) {
    glfwWaitEvents();
  } else if (timeout > 0.0) {
    glfwWaitEventsTimeout(timeout);
  } else {
    glfwPollEvents();
  }
  const bool event = queue_->event;
  queue_->event = false;
  return event;
}

void Platform::wake() {
  glfwPostEmptyEvent();
}

double Platform::now() const {
  return glfwGetTime();
}

void Platform::begin_ui_frame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  // ImGui 1.86 sees keys as up/down at each frame, so a tap shorter than a frame (a quick Enter
  // in a field, Escape in a dialog, or synthetic input) would be lost: keys pressed since the
  // last frame are held down for this frame, with their modifiers.
  ImGuiIO& io = ImGui::GetIO();
  held_taps_.clear();
  for (const KeyPress& press : queue_->keys) {
    if (press.key < 0 || press.key >= int(IM_ARRAYSIZE(io.KeysDown)) || io.KeysDown[press.key]) continue;
    io.KeysDown[press.key] = true;
    io.KeyCtrl = io.KeyCtrl || press.ctrl;
    io.KeyShift = io.KeyShift || press.shift;
    held_taps_.push_back(press.key);
  }
  ImGui::NewFrame();
}

void Platform::end_ui_frame() {
  ImGui::Render();
  if (held_taps_.empty()) return;
  // The held keys (and modifiers) go back to their real state.
  ImGuiIO& io = ImGui::GetIO();
  const auto down = [this](int key) { return glfwGetKey(glfw(window_), key) == GLFW_PRESS; };
  for (int key : held_taps_) io.KeysDown[key] = down(key);
  io.KeyCtrl = down(GLFW_KEY_LEFT_CONTROL) || down(GLFW_KEY_RIGHT_CONTROL) || down(GLFW_KEY_LEFT_SUPER) ||
               down(GLFW_KEY_RIGHT_SUPER);
  io.KeyShift = down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT);
  held_taps_.clear();
}

void Platform::draw_ui() {
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

std::vector<KeyPress> Platform::take_key_presses() {
  std::vector<KeyPress> keys;
  keys.swap(queue_->keys);
  return keys;
}

std::vector<std::string> Platform::take_dropped_files() {
  std::vector<std::string> dropped;
  dropped.swap(queue_->dropped);
  return dropped;
}

bool Platform::take_close_request() {
  const bool requested = queue_->close_requested;
  queue_->close_requested = false;
  return requested;
}

void Platform::close() {
  glfwSetWindowShouldClose(glfw(window_), GLFW_TRUE);
}

bool Platform::closing() const {
  return glfwWindowShouldClose(glfw(window_)) == GLFW_TRUE;
}

int Platform::held_axis() const {
  if (glfwGetKey(glfw(window_), GLFW_KEY_X) == GLFW_PRESS) return 0;
  if (glfwGetKey(glfw(window_), GLFW_KEY_Y) == GLFW_PRESS) return 1;
  if (glfwGetKey(glfw(window_), GLFW_KEY_Z) == GLFW_PRESS) return 2;
  return -1;
}

void Platform::set_title(const std::string& title) {
  if (title == title_) return;
  glfwSetWindowTitle(glfw(window_), title.c_str());
  title_ = title;
}

}  // namespace sweep::viewer
