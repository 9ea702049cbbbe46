#pragma once
// Triangulating a simple polygon by ear clipping, for the flat end caps of swept solids: the
// profiles are closed planar polylines that may be non-convex (stars, letter-like outlines) and
// may contain collinear runs and repeated consecutive points.
#include <glm/vec2.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace sweep {

/// Triangles of a simple polygon as index triples into `polygon`, each with the polygon's own
/// orientation (counterclockwise for a counterclockwise polygon): n - 2 of them for n >= 3
/// vertices, none for n < 3. Every vertex is used; collinear and repeated points give zero-area
/// triangles, so the cap's boundary edges are exactly the polygon's edges. O(n^2) at worst for a
/// simple polygon, O(n) for a convex one.
/// A self-intersecting or otherwise broken polygon still gets n - 2 triangles (they may overlap
/// or turn the wrong way) and the call always ends, in O(n^3) at worst: where no ear exists, the
/// sharpest convex corner is clipped (polygon_triangulation.cpp says why).
/// Preconditions: vertices in order, either orientation, fewer than 2^32 of them. The first is
/// best not repeated at the end: a repeat (there or anywhere) only adds a zero-area triangle.
std::vector<std::array<std::uint32_t, 3>> triangulate_polygon(std::span<const glm::dvec2> polygon);

/// Twice the signed area of a polygon: positive if its vertices run counterclockwise, zero for
/// fewer than 3 vertices. Preconditions: as for triangulate_polygon (self-intersecting polygons
/// get the sum of their loops' signed areas).
double polygon_twice_signed_area(std::span<const glm::dvec2> polygon);

}  // namespace sweep
