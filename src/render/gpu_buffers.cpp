#include "render/gpu_buffers.hpp"

#include <cstddef>
#include <utility>

namespace sweep::render {
namespace {

glm::vec3 to_float(const glm::dvec3& v) {
  return glm::vec3(v);
}

}  // namespace

GpuArray upload_lines(const std::vector<LineVertex>& vertices) {
  GpuArray array;
  glGenVertexArrays(1, &array.vao);
  glGenBuffers(1, &array.vbo);
  glBindVertexArray(array.vao);
  glBindBuffer(GL_ARRAY_BUFFER, array.vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(LineVertex)), vertices.data(),
               GL_STATIC_DRAW);
  const auto stride = static_cast<GLsizei>(sizeof(LineVertex));
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(offsetof(LineVertex, position)));
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                        reinterpret_cast<const void*>(offsetof(LineVertex, direction)));
  glEnableVertexAttribArray(2);
  glVertexAttribPointer(2, 3, GL_FLOAT, GL_FALSE, stride, reinterpret_cast<const void*>(offsetof(LineVertex, color)));
  glBindVertexArray(0);
  array.count = static_cast<GLsizei>(vertices.size());
  return array;
}

GpuArray upload_mesh(const Mesh& mesh) {
  GpuArray array;
  glGenVertexArrays(1, &array.vao);
  glGenBuffers(1, &array.vbo);
  glGenBuffers(1, &array.ebo);
  glBindVertexArray(array.vao);
  // Positions, normals, then texture coordinates in one buffer: contiguous arrays in the Mesh.
  const std::size_t block = mesh.positions.size() * sizeof(glm::vec3);
  const bool has_uvs = mesh.uvs.size() == mesh.positions.size();
  const std::size_t uv_block = has_uvs ? mesh.uvs.size() * sizeof(glm::vec2) : 0;
  glBindBuffer(GL_ARRAY_BUFFER, array.vbo);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(2 * block + uv_block), nullptr, GL_STATIC_DRAW);
  glBufferSubData(GL_ARRAY_BUFFER, 0, static_cast<GLsizeiptr>(block), mesh.positions.data());
  glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(block), static_cast<GLsizeiptr>(block), mesh.normals.data());
  glEnableVertexAttribArray(0);
  glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glEnableVertexAttribArray(1);
  glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, 0, reinterpret_cast<const void*>(block));
  if (has_uvs) {
    glBufferSubData(GL_ARRAY_BUFFER, static_cast<GLintptr>(2 * block), static_cast<GLsizeiptr>(uv_block),
                    mesh.uvs.data());
    glEnableVertexAttribArray(2);
    glVertexAttribPointer(2, 2, GL_FLOAT, GL_FALSE, 0, reinterpret_cast<const void*>(2 * block));
  }
  glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, array.ebo);
  glBufferData(GL_ELEMENT_ARRAY_BUFFER, static_cast<GLsizeiptr>(mesh.indices.size() * sizeof(std::uint32_t)),
               mesh.indices.data(), GL_STATIC_DRAW);
  glBindVertexArray(0);
  array.count = static_cast<GLsizei>(mesh.indices.size());
  return array;
}

void upload_vertex_colors(GpuArray& mesh, GLuint& buffer, const std::vector<glm::vec3>& colors) {
  if (buffer == 0) glGenBuffers(1, &buffer);
  glBindVertexArray(mesh.vao);
  glBindBuffer(GL_ARRAY_BUFFER, buffer);
  glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(colors.size() * sizeof(glm::vec3)), colors.data(),
               GL_STATIC_DRAW);
  glEnableVertexAttribArray(3);
  glVertexAttribPointer(3, 3, GL_FLOAT, GL_FALSE, 0, nullptr);
  glBindVertexArray(0);
}

std::vector<LineVertex> curve_strip(const CurveSamples& curve) {
  std::vector<LineVertex> vertices;
  vertices.reserve(curve.frames.size());
  for (const Frame& f : curve.frames) vertices.push_back({to_float(f.V), glm::vec3(0.0f), kWhite});
  return vertices;
}

std::vector<LineVertex> frame_segments(const CurveSamples& curve) {
  std::vector<LineVertex> vertices;
  vertices.reserve(curve.frames.size() * 6);
  for (const Frame& f : curve.frames) {
    const glm::vec3 v = to_float(f.V);
    for (const auto& [axis, color] : {std::pair{f.N, kRed}, std::pair{f.B, kGreen}, std::pair{f.T, kBlue}}) {
      vertices.push_back({v, glm::vec3(0.0f), color});
      vertices.push_back({v, to_float(axis), color});
    }
  }
  return vertices;
}

std::vector<LineVertex> normal_segments(const Mesh& mesh) {
  std::vector<LineVertex> vertices;
  vertices.reserve(mesh.positions.size() * 2);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    vertices.push_back({mesh.positions[i], glm::vec3(0.0f), kWhite});
    vertices.push_back({mesh.positions[i], mesh.normals[i], kWhite});
  }
  return vertices;
}

std::vector<LineVertex> control_polygon(std::span<const glm::dvec3> points) {
  std::vector<LineVertex> vertices;
  vertices.reserve(points.size());
  for (const glm::dvec3& p : points) vertices.push_back({to_float(p), glm::vec3(0.0f), kWhite});
  return vertices;
}

std::vector<LineVertex> net_segments(const std::vector<glm::vec3>& lines) {
  std::vector<LineVertex> vertices;
  vertices.reserve(lines.size());
  for (const glm::vec3& p : lines) vertices.push_back({p, glm::vec3(0.0f), kWhite});
  return vertices;
}

}  // namespace sweep::render
