#pragma once
// Triangle-triangle and ray-triangle tests in double, for the printability checks
// (intersections.hpp: a surface passing through itself or another; wall_thickness.hpp: rays
// across a wall).
//
// When two triangles count as intersecting: when they have a point in common, as closed sets.
// Distances below kIntersectionTolerance times the longer of the two triangles' longest edges
// count as zero (from a plane, between the pieces), so rounding does not decide. That is:
//  - crossing triangles count, and so do triangles that only touch: a corner on the other
//    triangle, an edge on it or across one of its edges. For printing a surface that touches
//    itself without sharing a vertex there (a pinch, as where a spindle torus meets its axis) is
//    as wrong as one passing through itself; triangles that do share a vertex are the caller's
//    to leave out (intersections.hpp does);
//  - coplanar triangles count when their closed areas meet (an overlap is a doubled,
//    zero-thickness wall; a common edge or corner without a common vertex index, a seam that is
//    not welded);
//  - triangles of (nearly) zero area have no plane and intersect nothing.
#include <glm/vec3.hpp>

#include <array>
#include <optional>

namespace sweep {

/// A triangle's three corners, counterclockwise seen from its front.
using TriangleCorners = std::array<glm::dvec3, 3>;

/// Lengths (and distances from a plane) below this times the triangles' size count as zero.
inline constexpr double kIntersectionTolerance = 1e-10;

/// A point that `a` and `b` have in common (to the tolerance) when they intersect as the header
/// describes (the middle of their common segment; when coplanar, the mean of the corners of
/// their common polygon), else nullopt. Constant time: Moeller's interval overlap along the planes' common line (T.
/// Moeller, "A Fast Triangle-Triangle Intersection Test", 1997) with exact segment ends, and convex clipping for
/// coplanar triangles.
std::optional<glm::dvec3> triangle_intersection_point(const TriangleCorners& a, const TriangleCorners& b);

/// Whether `a` and `b` intersect as the header describes. Constant time.
bool triangles_intersect(const TriangleCorners& a, const TriangleCorners& b);

/// The t >= 0 at which the ray origin + t * direction meets triangle `t` (from either side), or
/// nullopt: Moeller and Trumbore, "Fast, Minimum Storage Ray/Triangle Intersection" (1997).
/// Barycentric coordinates may be out by 1e-9, so a ray through a shared edge hits both
/// triangles rather than neither; a ray (nearly) parallel to the triangle's plane misses it, as
/// does a triangle of zero area. t is a distance when `direction` has unit length.
/// Constant time.
std::optional<double> ray_triangle_distance(const glm::dvec3& origin, const glm::dvec3& direction,
                                            const TriangleCorners& t);

}  // namespace sweep
