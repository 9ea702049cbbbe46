#include "geometry/mesh/shell_contact.hpp"

#include "geometry/mesh/triangle_bvh.hpp"
#include "geometry/mesh/triangle_intersection.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <limits>
#include <optional>

namespace sweep {
namespace {

/// Whether `inner` lies within `outer`.
bool inside(const BvhBox& inner, const BvhBox& outer) {
  return glm::all(glm::greaterThanEqual(inner.low, outer.low)) && glm::all(glm::lessThanEqual(inner.high, outer.high));
}

}  // namespace

glm::dvec3 lowest_point(const Shell& shell) {
  glm::dvec3 low(0.0, 0.0, std::numeric_limits<double>::max());
  for (const glm::dvec3& p : shell.positions) {
    if (p.z < low.z) low = p;
  }
  return low;
}

bool holds(const Shell& outer, const Shell& inner) {
  if (inner.positions.empty() || !inside(box_of(inner), box_of(outer))) return false;
  const glm::dvec3 origin = inner.positions.front();
  const glm::dvec3 direction = glm::normalize(glm::dvec3(0.0123, 0.0371, 1.0));
  std::size_t crossings = 0;
  for (std::size_t t = 0; t + 2 < outer.indices.size(); t += 3) {
    const auto& p = outer.positions;
    const std::optional<double> hit = ray_triangle_distance(
        origin, direction, {p[outer.indices[t]], p[outer.indices[t + 1]], p[outer.indices[t + 2]]});
    crossings += hit && *hit > 0.0;
  }
  return crossings % 2 == 1;
}

}  // namespace sweep
