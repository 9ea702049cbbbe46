#include "geometry/mesh/curvature.hpp"

#include "geometry/mesh/mesh_topology.hpp"

// The discrete operators are those of
//   Mark Meyer, Mathieu Desbrun, Peter Schroeder and Alan H. Barr, "Discrete Differential-Geometry
//   Operators for Triangulated 2-Manifolds", in Visualization and Mathematics III (Hege and
//   Polthier, eds.), Springer, 2003, pp. 35-57:
// the mixed area A_mixed (their section 3.4: the Voronoi region of the vertex inside a non-obtuse
// triangle, (|PR|^2 cot Q + |PQ|^2 cot R) / 8; half the area of an obtuse triangle at its obtuse
// corner, a quarter at the others), the mean curvature normal from the cotangent formula
//   K(x_i) = 1 / (2 A_mixed) * sum_j (cot alpha_ij + cot beta_ij) (x_i - x_j)       (their eq. 8)
// which is 2 H n, and the Gaussian curvature from the angle deficit
//   K_G(x_i) = (2 pi - sum_j theta_j) / A_mixed                                     (their eq. 9).

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <unordered_map>
#include <vector>

namespace sweep {
namespace {

/// A triangle is degenerate (no area, no cotangents) when twice its area is at most this much of
/// its longest edge squared: its smallest angle is below about 1e-12 radians.
constexpr double kDegenerate = 1e-12;

/// What the welded mesh adds up per vertex.
struct Accumulated {
  std::vector<std::uint32_t> welded;  // welded index of every mesh vertex
  std::vector<glm::dvec3> position;   // per welded vertex
  std::vector<double> angle_sum;      // corner angles
  std::vector<double> area;           // mixed area
  std::vector<glm::dvec3> laplacian;  // sum of cot weights times (x_i - x_j)
  std::vector<int> boundary_edges;    // welded edges used by one triangle, at this vertex
};

/// The corner angle at a between a->b and a->c, in [0, pi], accurate also near 0 and pi.
double corner_angle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 u = b - a, v = c - a;
  return std::atan2(glm::length(glm::cross(u, v)), glm::dot(u, v));
}

Accumulated accumulate(const Mesh& mesh) {
  Accumulated acc;
  std::size_t n = 0;
  acc.welded = weld_equal_positions(mesh, n);
  acc.position.resize(n);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) acc.position[acc.welded[i]] = glm::dvec3(mesh.positions[i]);
  acc.angle_sum.assign(n, 0.0);
  acc.area.assign(n, 0.0);
  acc.laplacian.assign(n, glm::dvec3(0.0));
  acc.boundary_edges.assign(n, 0);

  std::unordered_map<std::uint64_t, std::uint32_t> edge_uses;
  edge_uses.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::array<std::uint32_t, 3> v{acc.welded[mesh.indices[t]], acc.welded[mesh.indices[t + 1]],
                                         acc.welded[mesh.indices[t + 2]]};
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;  // collapsed once welded
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = v[k], b = v[(k + 1) % 3];
      ++edge_uses[(std::uint64_t{std::min(a, b)} << 32) | std::max(a, b)];
    }
    const std::array<glm::dvec3, 3> p{acc.position[v[0]], acc.position[v[1]], acc.position[v[2]]};
    std::array<double, 3> angle{};
    for (std::size_t k = 0; k < 3; ++k) {
      angle[k] = corner_angle(p[k], p[(k + 1) % 3], p[(k + 2) % 3]);
      acc.angle_sum[v[k]] += angle[k];
    }
    // Edge k runs from corner k+1 to corner k+2, opposite corner k.
    std::array<double, 3> length2{};
    for (std::size_t k = 0; k < 3; ++k) {
      const glm::dvec3 e = p[(k + 2) % 3] - p[(k + 1) % 3];
      length2[k] = glm::dot(e, e);
    }
    const double twice_area = glm::length(glm::cross(p[1] - p[0], p[2] - p[0]));
    if (!(twice_area > kDegenerate * std::max({length2[0], length2[1], length2[2]}))) continue;
    std::array<double, 3> cot{};
    for (std::size_t k = 0; k < 3; ++k) {
      cot[k] = glm::dot(p[(k + 1) % 3] - p[k], p[(k + 2) % 3] - p[k]) / twice_area;
    }
    // Cotangent Laplacian: edge (j, l) opposite corner k, weight cot(theta_k).
    for (std::size_t k = 0; k < 3; ++k) {
      const std::size_t j = (k + 1) % 3, l = (k + 2) % 3;
      const glm::dvec3 w = cot[k] * (p[j] - p[l]);
      acc.laplacian[v[j]] += w;
      acc.laplacian[v[l]] -= w;
    }
    // Mixed area.
    const double area = 0.5 * twice_area;
    const bool obtuse = cot[0] < 0.0 || cot[1] < 0.0 || cot[2] < 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      if (obtuse) {
        acc.area[v[k]] += cot[k] < 0.0 ? 0.5 * area : 0.25 * area;
      } else {
        // The two edges at corner k: edge j (opposite corner j) and edge l, weighted by the
        // cotangents of the angles opposite them.
        const std::size_t j = (k + 1) % 3, l = (k + 2) % 3;
        acc.area[v[k]] += (length2[j] * cot[j] + length2[l] * cot[l]) / 8.0;
      }
    }
  }
  for (const auto& [key, uses] : edge_uses) {
    if (uses != 1) continue;
    ++acc.boundary_edges[static_cast<std::uint32_t>(key >> 32)];
    ++acc.boundary_edges[static_cast<std::uint32_t>(key & 0xffffffffu)];
  }
  return acc;
}

/// 2 pi - sum of angles at an interior vertex, pi - sum at a boundary vertex: in general
/// (2 - b / 2) pi for b boundary edges at the vertex (a vertex where two boundary loops touch has
/// 4), so that the deficits add up to 2 pi chi.
double angle_deficit(const Accumulated& acc, std::size_t i) {
  return (2.0 - 0.5 * acc.boundary_edges[i]) * std::numbers::pi - acc.angle_sum[i];
}

}  // namespace

Curvatures vertex_curvatures(const Mesh& mesh) {
  const Accumulated acc = accumulate(mesh);
  const std::size_t n = acc.position.size();

  // The side the surface faces at every welded vertex: the sum of its copies' normals (a seam's
  // copies agree; a cap's rim averages the side and the cap), else of its triangles' normals.
  std::vector<glm::dvec3> side(n, glm::dvec3(0.0));
  if (mesh.normals.size() == mesh.positions.size()) {
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) side[acc.welded[i]] += glm::dvec3(mesh.normals[i]);
  }
  std::vector<glm::dvec3> face_side(n, glm::dvec3(0.0));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = acc.welded[mesh.indices[t]], b = acc.welded[mesh.indices[t + 1]],
                        c = acc.welded[mesh.indices[t + 2]];
    const glm::dvec3 area_normal = glm::cross(acc.position[b] - acc.position[a], acc.position[c] - acc.position[a]);
    face_side[a] += area_normal;
    face_side[b] += area_normal;
    face_side[c] += area_normal;
  }

  std::vector<double> gaussian(n, 0.0), mean(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double area = acc.area[i];
    if (!(area > 0.0)) continue;  // no area: 0
    gaussian[i] = angle_deficit(acc, i) / area;
    // Mean curvature normal K = 2 H n. On a sphere (x_i - x_j) leans outward, so K points along
    // the outward normal: H = |K| / 2 where K agrees with the vertex normal, -|K| / 2 otherwise.
    const glm::dvec3 k = acc.laplacian[i] / (2.0 * area);
    const glm::dvec3 up = glm::dot(side[i], side[i]) > 1e-12 ? side[i] : face_side[i];
    const double magnitude = 0.5 * glm::length(k);
    mean[i] = glm::dot(k, up) < 0.0 ? -magnitude : magnitude;
  }

  Curvatures out;
  out.gaussian.resize(mesh.positions.size());
  out.mean.resize(mesh.positions.size());
  // Finite floats only (a sliver's huge value is clamped to the largest float).
  const auto finite = [](double v) {
    constexpr double kMax = std::numeric_limits<float>::max();
    return std::isfinite(v) ? static_cast<float>(std::clamp(v, -kMax, kMax)) : 0.0f;
  };
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    out.gaussian[i] = finite(gaussian[acc.welded[i]]);
    out.mean[i] = finite(mean[acc.welded[i]]);
  }
  return out;
}

double total_angle_deficit(const Mesh& mesh) {
  const Accumulated acc = accumulate(mesh);
  // Vertices no triangle uses add nothing (as if they were not there).
  std::vector<bool> used(acc.position.size(), false);
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = acc.welded[mesh.indices[t]], b = acc.welded[mesh.indices[t + 1]],
                        c = acc.welded[mesh.indices[t + 2]];
    if (a == b || b == c || c == a) continue;
    used[a] = used[b] = used[c] = true;
  }
  double total = 0.0;
  for (std::size_t i = 0; i < acc.position.size(); ++i) {
    if (used[i]) total += angle_deficit(acc, i);
  }
  return total;
}

}  // namespace sweep
