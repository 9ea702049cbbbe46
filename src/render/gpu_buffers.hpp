#pragma once
// The renderer's GPU buffers (internal to src/render): vertex arrays for meshes and for lines,
// and the line vertices of curves, frames, normals and control polygons.
#include "geometry/curves/curve.hpp"
#include "geometry/mesh/mesh.hpp"

#include <glad/gl.h>
#include <glm/vec3.hpp>

#include <span>
#include <vector>

namespace sweep::render {

/// Vertex of lines.vert: drawn at position + u_direction_length * direction.
struct LineVertex {
  glm::vec3 position;
  glm::vec3 direction;
  glm::vec3 color;
};

inline const glm::vec3 kWhite{1.0f};
inline const glm::vec3 kRed{1.0f, 0.15f, 0.15f};
inline const glm::vec3 kGreen{0.2f, 1.0f, 0.2f};
inline const glm::vec3 kBlue{0.25f, 0.45f, 1.0f};

/// A vertex array with one vertex buffer (and an index buffer for meshes).
struct GpuArray {
  GLuint vao = 0;
  GLuint vbo = 0;
  GLuint ebo = 0;
  GLsizei count = 0;  // vertices, or indices when ebo != 0

  void release() {
    if (ebo) glDeleteBuffers(1, &ebo);
    if (vbo) glDeleteBuffers(1, &vbo);
    if (vao) glDeleteVertexArrays(1, &vao);
    *this = {};
  }
  bool empty() const { return count == 0; }
};

/// Uploads line vertices (attributes 0 position, 1 direction, 2 colour). Precondition: a current context.
GpuArray upload_lines(const std::vector<LineVertex>& vertices);
/// Uploads a mesh's positions, normals, texture coordinates (attribute 2, when it has them) and
/// triangle indices. Precondition: a current context.
GpuArray upload_mesh(const Mesh& mesh);
/// One colour per vertex of `mesh` as attribute 3, into `buffer` (created when 0).
void upload_vertex_colors(GpuArray& mesh, GLuint& buffer, const std::vector<glm::vec3>& colors);
/// A curve's samples as one strip.
std::vector<LineVertex> curve_strip(const CurveSamples& curve);
/// N (red), B (green) and T (blue) at every sample, as segments scaled by u_direction_length.
std::vector<LineVertex> frame_segments(const CurveSamples& curve);
/// Every vertex normal as a segment.
std::vector<LineVertex> normal_segments(const Mesh& mesh);
/// Control points in order (drawn as a strip and as points).
std::vector<LineVertex> control_polygon(std::span<const glm::dvec3> points);
/// Line pairs (a control net or a cage, EvaluatedObject::net) as line vertices.
std::vector<LineVertex> net_segments(const std::vector<glm::vec3>& lines);

}  // namespace sweep::render
