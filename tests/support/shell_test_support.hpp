#pragma once
// Shells the geometry tests build: a UV sphere and a torus (welded, counterclockwise from
// outside), and whether a point lies on a triangle.
#include "geometry/mesh/shell.hpp"
#include "geometry/mesh/triangle_intersection.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <numbers>

namespace sweep::test {

/// A UV sphere, welded (one vertex per pole), counterclockwise from outside.
inline Shell sphere(const glm::dvec3& centre, double radius, std::uint32_t segments, std::uint32_t rings) {
  Shell s;
  s.positions.push_back(centre + glm::dvec3(0, 0, radius));
  for (std::uint32_t i = 1; i < rings; ++i) {
    const double theta = std::numbers::pi * i / rings;
    for (std::uint32_t j = 0; j < segments; ++j) {
      const double phi = 2.0 * std::numbers::pi * j / segments;
      s.positions.push_back(centre + radius * glm::dvec3(std::sin(theta) * std::cos(phi),
                                                         std::sin(theta) * std::sin(phi), std::cos(theta)));
    }
  }
  const auto south = static_cast<std::uint32_t>(s.positions.size());
  s.positions.push_back(centre - glm::dvec3(0, 0, radius));
  const auto at = [&](std::uint32_t i, std::uint32_t j) { return 1 + (i - 1) * segments + j % segments; };
  for (std::uint32_t j = 0; j < segments; ++j) {
    s.indices.insert(s.indices.end(), {0, at(1, j), at(1, j + 1)});
    for (std::uint32_t i = 1; i + 1 < rings; ++i) {
      s.indices.insert(s.indices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1)});
      s.indices.insert(s.indices.end(), {at(i, j), at(i + 1, j + 1), at(i, j + 1)});
    }
    s.indices.insert(s.indices.end(), {at(rings - 1, j), south, at(rings - 1, j + 1)});
  }
  return s;
}

/// A torus around z: ring radius `ring`, tube radius `tube`, welded on both seams.
inline Shell torus(double ring, double tube, std::uint32_t around, std::uint32_t across) {
  Shell s;
  for (std::uint32_t j = 0; j < around; ++j) {
    const double phi = 2.0 * std::numbers::pi * j / around;
    for (std::uint32_t k = 0; k < across; ++k) {
      const double theta = 2.0 * std::numbers::pi * k / across;
      const double rho = ring + tube * std::cos(theta);
      s.positions.push_back({rho * std::cos(phi), rho * std::sin(phi), tube * std::sin(theta)});
    }
  }
  const auto at = [&](std::uint32_t j, std::uint32_t k) { return (j % around) * across + k % across; };
  for (std::uint32_t j = 0; j < around; ++j) {
    for (std::uint32_t k = 0; k < across; ++k) {
      s.indices.insert(s.indices.end(), {at(j, k), at(j + 1, k), at(j + 1, k + 1)});
      s.indices.insert(s.indices.end(), {at(j, k), at(j + 1, k + 1), at(j, k + 1)});
    }
  }
  return s;
}

/// Whether `p` lies on triangle `t`: on its plane and inside its edges, to `tolerance`.
inline bool on_triangle(const glm::dvec3& p, const TriangleCorners& t, double tolerance) {
  const glm::dvec3 n = glm::normalize(glm::cross(t[1] - t[0], t[2] - t[0]));
  if (std::abs(glm::dot(n, p - t[0])) > tolerance) return false;
  for (int i = 0; i < 3; ++i) {
    const glm::dvec3 inward = glm::normalize(glm::cross(n, t[(i + 1) % 3] - t[i]));
    if (glm::dot(inward, p - t[i]) < -tolerance) return false;
  }
  return true;
}

}  // namespace sweep::test
