#include "app/viewer/glfw_context.hpp"

#include "render/gl_context.hpp"
#include "render/renderer.hpp"

// glad before GLFW, so GLFW does not pull in the system GL header (its own block: clang-format
// sorts includes within a block).
#include <glad/gl.h>

#include <GLFW/glfw3.h>

#include <cstdlib>
#include <string>

namespace sweep::viewer {
namespace {

/// GLFW's last error, kept instead of printed so failures become one clear message.
std::string& last_glfw_error() {
  static std::string message;
  return message;
}

void remember_glfw_error(int /*code*/, const char* description) {
  last_glfw_error() = description ? description : "?";
}

class GlfwContext final : public render::GlContext {
 public:
  explicit GlfwContext(const render::ContextRequest& request) {
    glfwSetErrorCallback(remember_glfw_error);
    if (glfwInit() != GLFW_TRUE) throw NoDisplayError("GLFW cannot start: " + last_glfw_error());
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
#ifdef __APPLE__
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
#endif
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);  // HiDPI: window size follows the content scale
    glfwWindowHint(GLFW_VISIBLE, request.visible ? GLFW_TRUE : GLFW_FALSE);
    glfwWindowHint(GLFW_SAMPLES, request.samples);
    window_ = glfwCreateWindow(request.size.x, request.size.y, request.title.c_str(), nullptr, nullptr);
    if (window_ == nullptr && request.samples > 0) {
      glfwWindowHint(GLFW_SAMPLES, 0);  // no multisampled visual: plain is better than nothing
      window_ = glfwCreateWindow(request.size.x, request.size.y, request.title.c_str(), nullptr, nullptr);
    }
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

  std::string_view provider() const override {
    return "glfw";
  }
  void make_current() override {
    glfwMakeContextCurrent(window_);
  }
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
  void present() override {
    glfwSwapBuffers(window_);
  }
  void* native_window() const override {
    return window_;
  }

 private:
  GLFWwindow* window_ = nullptr;
};

}  // namespace

void register_glfw_provider() {
  render::register_context_provider("glfw", [](const render::ContextRequest& request) {
    return std::unique_ptr<render::GlContext>(std::make_unique<GlfwContext>(request));
  });
}

bool display_variable_set() {
  const char* x11 = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x11 != nullptr && *x11 != '\0') || (wayland != nullptr && *wayland != '\0');
}

}  // namespace sweep::viewer
