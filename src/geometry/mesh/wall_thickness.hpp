#pragma once
// Walls too thin to print: the thickness of a closed shell measured by a ray from each
// triangle's centroid along its inward normal to the opposite wall.
//
// The measure. A ray along the inward normal crosses the material and leaves it through the
// opposite wall; it measures the wall where the two sides are (nearly) parallel, as in a plate
// or a tube, and a wall slanted to the ray reads thicker than it is. So that the measure is the
// opposite wall's and not the start's own neighbourhood:
//  - triangles that share a vertex with the start triangle are passed through: on a strongly
//    curved or coarse surface the ray can graze them at tiny distances, and they are the same
//    wall, not the opposite one (the cost: a thin sharp edge is measured from triangles one
//    ring away from it);
//  - the first triangle the ray meets counts only when it faces along the ray (its outward
//    normal points the way the ray goes): the ray leaves the material through the back of the
//    opposite wall. A first hit that faces the ray means the ray left the material somewhere
//    else (a surface that passes through itself, an open or badly wound shell): no measure.
// Triangles of zero area have no normal and are not measured.
#include "geometry/mesh/shell.hpp"
#include "geometry/mesh/triangle_bvh.hpp"

#include <glm/vec3.hpp>

#include <cstddef>

namespace sweep {

struct ThinWalls {
  /// Triangles whose wall is thinner than asked.
  std::size_t triangles = 0;
  /// The smallest thickness found (mm); 0 when no wall is thin.
  double thinnest = 0.0;
  /// The centroid of the triangle with the thinnest wall (the lowest-numbered of equals); 0 when
  /// no wall is thin.
  glm::dvec3 where{0.0};
};

/// Walls of the closed shell `shell` thinner than `min_wall`, measured as the header describes:
/// from each triangle's centroid along -(b - a) x (c - a), normalized. The result does not depend
/// on the thread count. Cost: one ray per triangle through a bounding volume hierarchy, each
/// looking no further than min_wall, on every core (1.6 million triangles: about 1 s on 2).
/// Preconditions: min_wall > 0; the shell's indices in threes and below its position count.
ThinWalls thin_walls(const Shell& shell, double min_wall);

/// The same on the shell's hierarchy, built already (shared with the intersection checks).
ThinWalls thin_walls(const TriangleBvh& bvh, double min_wall);

}  // namespace sweep
