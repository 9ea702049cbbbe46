#pragma once
// Welding: one index for points closer than a tolerance, so seams built twice (patch edges, a
// surface's grid seam) become shared vertices.
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace sweep {

/// For every point, the index of the earliest point within `tolerance` of it that is itself
/// kept (itself if none): a welded point is never another's representative. Indices refer to
/// `points`. Expected linear time: the kept points are filed by cells 8 tolerances wide
/// (one flat open-addressing table), and a point is compared with those in the one to eight
/// cells its tolerance reaches. Precondition: tolerance > 0.
std::vector<std::uint32_t> weld_points(std::span<const glm::dvec3> points, double tolerance);

/// The diagonal of the box around `points` (0 for none).
double points_extent(std::span<const glm::dvec3> points);

}  // namespace sweep
