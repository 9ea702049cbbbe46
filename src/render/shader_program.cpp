#include "render/shader_program.hpp"

#include "render/shader_sources.hpp"

#include <array>
#include <stdexcept>
#include <vector>

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

Program::Program(const std::string& name) : Program(name + ".vert", "", name + ".frag") {}

Program::Program(const std::string& vertex_name, const std::string& geometry_name, const std::string& fragment_name) {
  const std::string name = vertex_name + "+" + fragment_name;
  std::vector<GLuint> shaders{compile_shader(GL_VERTEX_SHADER, vertex_name)};
  if (!geometry_name.empty()) shaders.push_back(compile_shader(GL_GEOMETRY_SHADER, geometry_name));
  shaders.push_back(compile_shader(GL_FRAGMENT_SHADER, fragment_name));
  id_ = glCreateProgram();
  for (const GLuint shader : shaders) glAttachShader(id_, shader);
  glLinkProgram(id_);
  for (const GLuint shader : shaders) glDeleteShader(shader);
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
