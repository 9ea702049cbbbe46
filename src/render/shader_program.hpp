#pragma once
// A linked GLSL program of the renderer (internal to src/render): shaders/NAME.vert and
// shaders/NAME.frag (or any vertex, geometry and fragment shader of shaders/) from the sources
// embedded at build time, with uniform setters.
#include <glad/gl.h>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <string>

namespace sweep::render {

/// A linked program from shaders/NAME.vert and shaders/NAME.frag.
class Program {
 public:
  /// Compiles and links; throws std::runtime_error with the GLSL log if either fails.
  /// Precondition: a current GL 3.3 context with loaded functions.
  explicit Program(const std::string& name);
  /// From the files named (e.g. "mesh.vert", "wire.geom", "wire.frag"); `geometry` may be empty.
  Program(const std::string& vertex, const std::string& geometry, const std::string& fragment);
  ~Program() { glDeleteProgram(id_); }
  Program(const Program&) = delete;
  Program& operator=(const Program&) = delete;

  void use() const { glUseProgram(id_); }
  GLint location(const char* uniform) const { return glGetUniformLocation(id_, uniform); }
  void set(const char* uniform, const glm::mat4& m) const {
    glUniformMatrix4fv(location(uniform), 1, GL_FALSE, glm::value_ptr(m));
  }
  void set(const char* uniform, const glm::vec3& v) const { glUniform3fv(location(uniform), 1, glm::value_ptr(v)); }
  void set(const char* uniform, float f) const { glUniform1f(location(uniform), f); }
  void set(const char* uniform, bool b) const { glUniform1i(location(uniform), b ? 1 : 0); }
  void set(const char* uniform, int i) const { glUniform1i(location(uniform), i); }
  void set(const char* uniform, const glm::vec2& v) const { glUniform2fv(location(uniform), 1, glm::value_ptr(v)); }

 private:
  GLuint id_ = 0;
};

}  // namespace sweep::render
