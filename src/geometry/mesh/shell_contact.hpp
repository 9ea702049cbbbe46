#pragma once
// Where shells stand: their lowest points, and whether one holds another inside it. The print
// checks tell parts that float from parts resting in or on others with these.
#include "geometry/mesh/shell.hpp"

#include <glm/vec3.hpp>

namespace sweep {

/// A part whose lowest point is at most this high stands on the plate.
inline constexpr double kOnPlateMillimetres = 1e-3;

/// The vertex of `shell` with the least z (the first of equals); (0, 0, +huge) for an empty one.
glm::dvec3 lowest_point(const Shell& shell);

/// Whether `inner`'s first vertex is inside the closed shell `outer`: a ray from it crosses
/// outer an odd number of times (in a direction off the axes, so it meets no seam of a surface
/// of revolution edge-on). False at once when inner's box is not inside outer's. O(triangles).
bool holds(const Shell& outer, const Shell& inner);

}  // namespace sweep
