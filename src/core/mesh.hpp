#pragma once
// A triangle mesh laid out for a vertex buffer: contiguous float3 positions and normals and
// uint32 triangle indices, counterclockwise seen from the side the normals point to.
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace sweep {

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;      // unit, one per position
  std::vector<std::uint32_t> indices;  // 3 per triangle

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return indices.size() / 3; }
};

}  // namespace sweep
