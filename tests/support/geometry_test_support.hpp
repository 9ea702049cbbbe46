#pragma once
// Helpers of the geometry tests, which link geometry alone: reference evaluations written from
// the textbook formulas (independent of src/geometry/curves/bezier_curves.cpp) and mesh topology counts.
#include "geometry/mesh/mesh.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <map>
#include <utility>
#include <vector>

namespace sweep::test {

/// Bernstein polynomials of degree 3 at t.
inline glm::dvec4 bernstein_weights(double t) {
  const double s = 1.0 - t;
  return {s * s * s, 3.0 * t * s * s, 3.0 * t * t * s, t * t * t};
}

/// Uniform cubic B-spline blending functions at t (Bartels, Beatty, Barsky, "An Introduction to
/// Splines for Use in Computer Graphics and Geometric Modeling", 1987).
inline glm::dvec4 bspline_weights(double t) {
  const double s = 1.0 - t;
  return {s * s * s / 6.0, (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0,
          (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0, t * t * t / 6.0};
}

/// Piece k of a piecewise Bezier curve at t, by de Casteljau's algorithm.
inline glm::dvec3 direct_bezier(const std::vector<glm::dvec3>& points, std::size_t piece, double t) {
  glm::dvec3 p[4] = {points[3 * piece], points[3 * piece + 1], points[3 * piece + 2], points[3 * piece + 3]};
  for (int level = 3; level > 0; --level) {
    for (int i = 0; i < level; ++i) p[i] = (1.0 - t) * p[i] + t * p[i + 1];
  }
  return p[0];
}

/// Piece k of a uniform cubic B-spline at t, straight from the blending functions.
inline glm::dvec3 direct_bspline(const std::vector<glm::dvec3>& points, std::size_t piece, double t) {
  const glm::dvec4 w = bspline_weights(t);
  return w[0] * points[piece] + w[1] * points[piece + 1] + w[2] * points[piece + 2] + w[3] * points[piece + 3];
}

/// Derivative of direct_bspline with respect to t.
inline glm::dvec3 direct_bspline_derivative(const std::vector<glm::dvec3>& points, std::size_t piece, double t) {
  const double s = 1.0 - t;
  const glm::dvec4 w{-s * s / 2.0, (3.0 * t * t - 4.0 * t) / 2.0, (-3.0 * t * t + 2.0 * t + 1.0) / 2.0, t * t / 2.0};
  return w[0] * points[piece] + w[1] * points[piece + 1] + w[2] * points[piece + 2] + w[3] * points[piece + 3];
}

/// How many triangles use each undirected edge (smaller index first).
inline std::map<std::pair<std::uint32_t, std::uint32_t>, int> edge_uses(const Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.indices[t + k];
      const std::uint32_t b = mesh.indices[t + (k + 1) % 3];
      ++uses[{std::min(a, b), std::max(a, b)}];
    }
  }
  return uses;
}

/// How many triangles traverse each directed edge a -> b.
inline std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed_edge_uses(const Mesh& mesh) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> uses;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    for (std::size_t k = 0; k < 3; ++k) ++uses[{mesh.indices[t + k], mesh.indices[t + (k + 1) % 3]}];
  }
  return uses;
}

inline double distance(const glm::dvec3& a, const glm::dvec3& b) {
  return glm::length(a - b);
}

}  // namespace sweep::test
