#include "geometry/mesh/shell_contact.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace sweep {
namespace {

struct Box {
  glm::dvec3 low{std::numeric_limits<double>::max()};
  glm::dvec3 high{std::numeric_limits<double>::lowest()};
};

Box box_of(const Shell& shell) {
  Box box;
  for (const glm::dvec3& p : shell.positions) {
    box.low = glm::min(box.low, p);
    box.high = glm::max(box.high, p);
  }
  return box;
}

bool inside(const Box& inner, const Box& outer) {
  return glm::all(glm::greaterThanEqual(inner.low, outer.low)) && glm::all(glm::lessThanEqual(inner.high, outer.high));
}

/// Whether the ray from `origin` along `direction` crosses triangle (a, b, c) at a positive
/// distance (Moller and Trumbore's test).
bool crosses(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& a, const glm::dvec3& b,
             const glm::dvec3& c) {
  const glm::dvec3 e1 = b - a;
  const glm::dvec3 e2 = c - a;
  const glm::dvec3 p = glm::cross(direction, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-300) return false;
  const glm::dvec3 s = origin - a;
  const double u = glm::dot(s, p) / det;
  if (u < 0.0 || u > 1.0) return false;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(direction, q) / det;
  if (v < 0.0 || u + v > 1.0) return false;
  return glm::dot(e2, q) / det > 0.0;
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
    crossings += crosses(origin, direction, p[outer.indices[t]], p[outer.indices[t + 1]], p[outer.indices[t + 2]]);
  }
  return crossings % 2 == 1;
}

}  // namespace sweep
