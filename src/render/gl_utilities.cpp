// The renderer's small GL services (declared in renderer.hpp): loading the functions, reading
// the framebuffer back, errors and the driver's description.
#include "render/renderer.hpp"

#include <glad/gl.h>

#include <string>

namespace sweep::render {

bool load_gl_functions(void (*(*get_proc)(const char*))()) {
  const int version = gladLoadGL(get_proc);
  return version != 0 &&
         (GLAD_VERSION_MAJOR(version) > 3 || (GLAD_VERSION_MAJOR(version) == 3 && GLAD_VERSION_MINOR(version) >= 3));
}

Image read_framebuffer(glm::ivec2 size) {
  Image image;
  image.width = size.x;
  image.height = size.y;
  image.rgba.resize(static_cast<std::size_t>(size.x) * static_cast<std::size_t>(size.y) * 4);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, size.x, size.y, GL_RGBA, GL_UNSIGNED_BYTE, image.rgba.data());
  image.flip_rows();  // GL rows run bottom to top; images top to bottom
  return image;
}

unsigned int take_gl_error() {
  const GLenum first = glGetError();
  for (int i = 0; i < 16 && glGetError() != GL_NO_ERROR; ++i) {
  }
  return first;
}

std::string gl_description() {
  const auto text = [](GLenum name) {
    const auto* s = reinterpret_cast<const char*>(glGetString(name));
    return std::string(s ? s : "?");
  };
  return text(GL_RENDERER) + ", OpenGL " + text(GL_VERSION) + ", GLSL " + text(GL_SHADING_LANGUAGE_VERSION);
}

}  // namespace sweep::render
