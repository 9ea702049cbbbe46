#pragma once
// Helpers shared by the tests of the interpolating splines, helices and torus knots.
#include "geometry/curves/curve.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

namespace sweep::test {

inline bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Diagonal of the bounding box of some points, for relative tolerances.
inline double extent_of(const std::vector<glm::dvec3>& points) {
  glm::dvec3 lo = points.front(), hi = lo;
  for (const auto& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

/// Empty if the frame is finite, unit, orthonormal and right-handed (B = T x N), else why not.
inline std::string frame_problem(const Frame& f, double tolerance = 1e-9) {
  if (!finite(f.V) || !finite(f.T) || !finite(f.N) || !finite(f.B)) return "not finite";
  if (std::abs(glm::length(f.T) - 1.0) > tolerance || std::abs(glm::length(f.N) - 1.0) > tolerance ||
      std::abs(glm::length(f.B) - 1.0) > tolerance) {
    return "not unit";
  }
  if (std::abs(glm::dot(f.T, f.N)) > tolerance || std::abs(glm::dot(f.T, f.B)) > tolerance ||
      std::abs(glm::dot(f.N, f.B)) > tolerance) {
    return "not orthogonal";
  }
  if (glm::length(f.B - glm::cross(f.T, f.N)) > tolerance) return "not right-handed";
  return "";
}

/// Distance from p to the line segment a-b.
inline double distance_to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

/// Points in the xy-plane (z = 0) from (x, y) pairs.
inline std::vector<glm::dvec3> planar_points(std::initializer_list<std::pair<double, double>> xy) {
  std::vector<glm::dvec3> points;
  for (const auto& [x, y] : xy) points.emplace_back(x, y, 0.0);
  return points;
}

}  // namespace sweep::test
