#include "headless/osmesa_context.hpp"

#include "render/gl_context.hpp"
#include "render/renderer.hpp"

#include <GL/osmesa.h>

#include <stdexcept>
#include <vector>

namespace sweep::headless {
namespace {

class OsmesaContext final : public render::GlContext {
 public:
  explicit OsmesaContext(const render::ContextRequest& request) : size_(request.size) {
    if (size_.x <= 0 || size_.y <= 0) throw std::runtime_error("OSMesa: the buffer size must be positive");
    const int attributes[] = {OSMESA_FORMAT,
                              OSMESA_RGBA,
                              OSMESA_DEPTH_BITS,
                              24,
                              OSMESA_STENCIL_BITS,
                              8,
                              OSMESA_PROFILE,
                              OSMESA_CORE_PROFILE,
                              OSMESA_CONTEXT_MAJOR_VERSION,
                              3,
                              OSMESA_CONTEXT_MINOR_VERSION,
                              3,
                              0};
    context_ = OSMesaCreateContextAttribs(attributes, nullptr);
    if (context_ == nullptr) throw std::runtime_error("OSMesa could not create an OpenGL 3.3 core context");
    buffer_.resize(static_cast<std::size_t>(size_.x) * static_cast<std::size_t>(size_.y) * 4);
    make_current();
    if (!render::load_gl_functions(OSMesaGetProcAddress)) {
      OSMesaDestroyContext(context_);
      throw std::runtime_error("OSMesa: could not load the OpenGL 3.3 core functions");
    }
  }
  ~OsmesaContext() override { OSMesaDestroyContext(context_); }
  OsmesaContext(const OsmesaContext&) = delete;
  OsmesaContext& operator=(const OsmesaContext&) = delete;

  std::string_view provider() const override { return "osmesa"; }
  void make_current() override {
    if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, size_.x, size_.y)) {
      throw std::runtime_error("OSMesa could not make its context current");
    }
  }
  glm::ivec2 framebuffer_size() const override { return size_; }
  glm::ivec2 window_size() const override { return size_; }
  void present() override { /* pictures are read back from a framebuffer object */
  }
  void* native_window() const override { return nullptr; }

 private:
  glm::ivec2 size_;
  OSMesaContext context_ = nullptr;
  std::vector<unsigned char> buffer_;
};

}  // namespace

void register_osmesa_provider() {
  render::register_context_provider("osmesa", [](const render::ContextRequest& request) {
    return std::unique_ptr<render::GlContext>(std::make_unique<OsmesaContext>(request));
  });
}

}  // namespace sweep::headless
