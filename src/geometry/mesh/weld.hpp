#pragma once
// Welding: one index for points closer than a tolerance, so seams built twice (patch edges, a
// surface's grid seam) become shared vertices.
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace sweep {

/// For every point, the index of the first earlier point within `tolerance` of it (itself if
/// none); indices refer to `points`. Expected linear time: points are hashed into cells of the
/// tolerance's size and compared with the 27 cells around them. Precondition: tolerance > 0.
std::vector<std::uint32_t> weld_points(std::span<const glm::dvec3> points, double tolerance);

/// The diagonal of the box around `points` (0 for none).
double points_extent(std::span<const glm::dvec3> points);

}  // namespace sweep
