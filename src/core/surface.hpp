#pragma once
// Swept surfaces built from evaluated curves.
#include "core/curve.hpp"
#include "core/mesh.hpp"

#include <cstdint>

namespace sweep {

/// Vertex count the surface will have; used to check caps before allocating.
std::int64_t revolution_vertex_count(std::int64_t profile_samples, bool profile_closed, std::int64_t steps);
std::int64_t cylinder_vertex_count(std::int64_t profile_samples, bool profile_closed,
                                   std::int64_t sweep_samples, bool sweep_closed);

/// Surface of revolution: `steps` copies of the planar profile turned counterclockwise about +y
/// (seen from above). A closed profile shares its seam vertices; so does the turn.
/// Normal rule: the profile is closed through the y axis if it is open (its ends are joined by
/// their projections onto the axis); normals point out of the region it then bounds. For the
/// usual profile traced top to bottom at x < 0 these are the reversed profile normals (-N), as in
/// the original tool; for a profile at x > 0, or a clockwise closed one, they are +N.
/// Preconditions: profile.planar, profile has >= 2 samples, steps >= 1.
Mesh build_surface_of_revolution(const CurveSamples& profile, int steps);

/// Generalized cylinder: every profile sample (x, y) placed by every sweep frame as
/// P = V + x N + y B. Closed profiles get normals out of the region they bound (-N for a
/// counterclockwise one); open profiles get the reversed profile normals (-N), as the original
/// tool. A closed profile or sweep closes its seam by sharing vertices.
/// Preconditions: profile.planar, both have >= 2 samples.
Mesh build_generalized_cylinder(const CurveSamples& profile, const CurveSamples& sweep);

}  // namespace sweep
