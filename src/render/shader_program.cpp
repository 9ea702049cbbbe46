#include "render/shader_program.hpp"

#include "render/shader_sources.hpp"

#include <array>
#include <stdexcept>

namespace sweep::render {
namespace {

GLuint compile_shader(GLenum type, const std::string& name) {
  const auto source = shader_source(name);
  if (!source) throw std::runtime_error("shader " + name + " was not embedded");
  const GLuint shader = glCreateShader(type);
  const char* text = source->data();
  const GLint length = static_cast<GLint>(source->size());
  glShaderSource(shader, 1, &text, &length);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::array<char, 4096> log{};
    glGetShaderInfoLog(shader, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteShader(shader);
    throw std::runtime_error("shader " + name + " does not compile: " + log.data());
  }
  return shader;
}

}  // namespace

Program::Program(const std::string& name) {
  const GLuint vertex = compile_shader(GL_VERTEX_SHADER, name + ".vert");
  const GLuint fragment = compile_shader(GL_FRAGMENT_SHADER, name + ".frag");
  id_ = glCreateProgram();
  glAttachShader(id_, vertex);
  glAttachShader(id_, fragment);
  glLinkProgram(id_);
  glDeleteShader(vertex);
  glDeleteShader(fragment);
  GLint ok = GL_FALSE;
  glGetProgramiv(id_, GL_LINK_STATUS, &ok);
  if (ok != GL_TRUE) {
    std::array<char, 4096> log{};
    glGetProgramInfoLog(id_, static_cast<GLsizei>(log.size()), nullptr, log.data());
    glDeleteProgram(id_);
    throw std::runtime_error("shader program " + name + " does not link: " + log.data());
  }
}

}  // namespace sweep::render
