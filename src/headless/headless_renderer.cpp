#include "headless/headless_renderer.hpp"

#include "headless/osmesa_context.hpp"
#include "render/offscreen_target.hpp"

#include <glad/gl.h>

#include <algorithm>

namespace sweep::headless {

HeadlessRenderer::HeadlessRenderer(const std::string& provider) {
  register_osmesa_provider();
  render::ContextRequest request;
  request.size = {64, 64};  // the default framebuffer is unused: pictures go to target_
  request.visible = false;
  context_ = render::create_context(provider, request);
  renderer_ = std::make_unique<render::Renderer>();
}

HeadlessRenderer::~HeadlessRenderer() {
  // GL objects go before their context.
  context_->make_current();
  target_.reset();
  renderer_.reset();
}

render::Image HeadlessRenderer::render(const render::DrawList& list, const render::Camera& camera, glm::ivec2 size,
                                       const render::DisplaySettings& settings) {
  context_->make_current();
  if (!target_ || target_->size() != size) {
    target_.reset();
    target_ = std::make_unique<render::OffscreenTarget>(size, 4);
  }
  target_->bind();
  renderer_->draw(list, camera, render::RenderTarget{size, 1.0f}, settings);
  return target_->resolve_and_read();
}

render::Image HeadlessRenderer::render(const Document& doc, const Scene& scene, const render::Camera& camera,
                                       glm::ivec2 size, const render::DisplaySettings& settings,
                                       const std::filesystem::path& image_folder) {
  return render(render::draw_list(doc, scene, image_folder), camera, size, settings);
}

int HeadlessRenderer::max_picture_side() const {
  context_->make_current();
  GLint renderbuffer = 0;
  GLint viewport[2] = {0, 0};
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &renderbuffer);
  glGetIntegerv(GL_MAX_VIEWPORT_DIMS, viewport);
  return std::min({renderbuffer, viewport[0], viewport[1]});
}

std::string HeadlessRenderer::description() const {
  context_->make_current();
  return render::gl_description();
}

}  // namespace sweep::headless
