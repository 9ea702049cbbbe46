#pragma once
// Flat caps that close a swept surface into a solid: the ends of a tube (a closed profile along
// an open sweep) and the open ends of a surface of revolution. A cap's rim vertices are copies
// of the surface's boundary vertices, at exactly the same positions, with the cap's own flat
// normal; so the surface is watertight once equal positions are welded (as STL readers do).
#include "geometry/curves/curve.hpp"
#include "geometry/mesh/mesh.hpp"

#include <glm/vec2.hpp>

#include <cstddef>
#include <span>

namespace sweep {

/// Appends caps to a tube of `rings` rings of ring.size() vertices (ring j at j * ring.size()):
/// the polygon of the profile's ring samples `ring` (profile coordinates) is triangulated once
/// (non-convex profiles too) and placed on the first ring facing `start_out` and on the last
/// ring facing `end_out`. The profile is placed with x along N, y along B and N x B = T, so a
/// counterclockwise profile is counterclockwise seen from +T. Preconditions: ring.size() >= 3,
/// rings >= 2, the mesh holds the tube's vertices first.
void add_tube_caps(Mesh& mesh, std::span<const glm::dvec2> ring, std::size_t rings, const glm::dvec3& start_out,
                   const glm::dvec3& end_out);

/// Appends disks that close a surface of revolution's open profile at each end that is off the
/// axis (|x| > `on_axis`): a fan from the axis to that end's circle of `copies` vertices (the
/// end's copies, profile sample 0 or the last at j * profile samples). Each disk faces out of
/// the solid the profile bounds when closed through the axis (its ends joined by their
/// projections onto the axis), whichever way the profile runs. Closed profiles get nothing.
void add_revolution_caps(Mesh& mesh, const CurveSamples& profile, std::size_t copies, double on_axis);

}  // namespace sweep
