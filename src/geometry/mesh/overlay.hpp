#pragma once
// Marks drawn over a scene (editor handles, highlights, grids, fold markers): plain data that the
// editor builds and the renderer draws, so neither needs the other.
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace sweep {

/// One colour and primitive per batch, positions in world space.
struct OverlayBatch {
  enum class Primitive : std::uint8_t { Points, Lines, LineStrip };
  Primitive primitive = Primitive::Points;
  std::vector<glm::vec3> positions;
  glm::vec3 color{1.0f};
  float point_size = 8.0f;  // points: diameter in screen units (times the pixel ratio)
  bool round = true;        // points: discs; false: squares (a Bezier or Hermite curve's joints)
  bool on_top = true;       // drawn over everything (handles); false: hidden by nearer surfaces (grids)
};

}  // namespace sweep
