#pragma once
// Where a surface passes through itself or through another, for the printability checks: the
// pairs of triangles that intersect (that cross or touch, as triangle_intersection.hpp defines
// it), found through bounding volume hierarchies (triangle_bvh.hpp) on every core, so
// only triangles whose boxes overlap are tested.
#include "geometry/mesh/shell.hpp"
#include "geometry/mesh/triangle_bvh.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace sweep {

/// How many intersecting pairs IntersectingPairs::sample keeps.
inline constexpr std::size_t kIntersectionSample = 8;

struct IntersectingPairs {
  /// Intersecting pairs found: all of them, or the limit asked when there are at least as many.
  std::size_t count = 0;
  /// A point on both triangles of sample[0] (the viewer shows where); 0 when count is 0.
  glm::dvec3 first_point{0.0};
  /// Up to kIntersectionSample of the pairs found, in increasing order (the lowest pairs when
  /// count is below the limit; when the search stopped at the limit, which pairs it had found
  /// depends on the threads' timing).
  std::vector<std::pair<std::uint32_t, std::uint32_t>> sample;
};

/// Pairs of triangles of `shell` that share no vertex index and intersect: the surface passes
/// through itself, or touches itself (a pinch, a doubled wall, a seam that is not welded). Pairs are
/// (lower triangle, higher triangle). Stops counting at `limit`. Triangles that share a vertex
/// are not tested, so a fold whose triangles all share one vertex is not found.
/// Cost: O(n log n) for a surface (1.6 million triangles: about 0.6 s on 2 cores).
/// Preconditions: the shell's indices in threes and below its position count; limit > 0.
IntersectingPairs self_intersections(const Shell& shell, std::size_t limit = 1000);

/// Pairs (a triangle of a, a triangle of b) that intersect; otherwise as above. Constant time
/// after a pass over the positions when the shells' boxes are apart.
IntersectingPairs mutual_intersections(const Shell& a, const Shell& b, std::size_t limit = 1000);

/// The same on hierarchies built already (one per shell, shared by every check that needs it:
/// printability.cpp builds each part's once). The triangles are the hierarchies' own numbers.
IntersectingPairs self_intersections(const TriangleBvh& bvh, std::size_t limit = 1000);
IntersectingPairs mutual_intersections(const TriangleBvh& a, const TriangleBvh& b, std::size_t limit = 1000);

}  // namespace sweep
