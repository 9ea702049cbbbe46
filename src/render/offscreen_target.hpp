#pragma once
// A framebuffer object to render pictures into: multisampled colour and depth, resolved into a
// plain colour buffer for reading back. Used by the headless renderer, where the OSMesa default
// framebuffer has no multisampling, and by the viewer for its still (multisampled) frames while
// moving frames go straight to a plain window.
#include "render/image.hpp"

#include <glm/vec2.hpp>

namespace sweep::render {

class OffscreenTarget {
 public:
  /// Precondition: a current GL 3.3 context with loaded functions. samples is clamped to what
  /// the implementation supports (0 or 1: no multisampling). Throws std::runtime_error if the
  /// framebuffer is incomplete.
  OffscreenTarget(glm::ivec2 size, int samples);
  ~OffscreenTarget();
  OffscreenTarget(const OffscreenTarget&) = delete;
  OffscreenTarget& operator=(const OffscreenTarget&) = delete;

  glm::ivec2 size() const { return size_; }
  /// Binds the multisampled framebuffer for drawing.
  void bind() const;
  /// Resolves the samples and reads the picture back (top row first).
  Image resolve_and_read() const;
  /// Resolves the samples into the window's (default, single-sampled) framebuffer of the same
  /// size, and leaves that bound.
  void resolve_to_window() const;

 private:
  glm::ivec2 size_;
  unsigned int draw_fbo_ = 0;
  unsigned int draw_color_ = 0;
  unsigned int draw_depth_ = 0;
  unsigned int resolve_fbo_ = 0;
  unsigned int resolve_color_ = 0;
};

/// Binds the window's default framebuffer for drawing and reading.
void bind_window_framebuffer();
/// Reads the window's back buffer (what the next present shows), top row first.
Image read_window_framebuffer(glm::ivec2 size);

}  // namespace sweep::render
