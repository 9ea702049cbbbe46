// The mitre limit: a corner whose mitre would stretch the profile by more than the limit is
// bevelled (the tube cut square on both sides of the corner, joined by a flat strip), as SVG's
// stroke-miterlimit. The tube stays within its radius of the path (no spike), stays watertight,
// and has the documented counts; a higher limit mitres the same corner.
#include "geometry/curves/polyline.hpp"
#include "geometry/mesh/mesh_topology.hpp"
#include "geometry/surfaces/surface.hpp"

#include "support/geometry_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace {

using sweep::test::distance;

constexpr double kRadius = 0.1;
constexpr std::size_t kRing = 12;  // the circle profile's distinct samples

double distance_to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return distance(p, a + t * ab);
}

double distance_to_path(const glm::dvec3& p, const std::vector<glm::dvec3>& path) {
  double nearest = 1e300;
  for (std::size_t k = 0; k + 1 < path.size(); ++k)
    nearest = std::min(nearest, distance_to_segment(p, path[k], path[k + 1]));
  return nearest;
}

/// A hairpin turning by `turn_degrees` at (1, 0, 0): in along +x, out back towards -x.
std::vector<glm::dvec3> hairpin(double turn_degrees) {
  const double a = (180.0 - turn_degrees) * std::numbers::pi / 180.0;
  return {{0, 0, 0}, {1, 0, 0}, {1 - std::cos(a), std::sin(a), 0}};
}

sweep::Mesh tube(const std::vector<glm::dvec3>& path, double limit, bool caps = false, bool planar = true) {
  sweep::SweepControls controls;
  controls.mitre_limit = limit;
  controls.caps = caps;
  return sweep::build_generalized_cylinder(sweep::evaluate_circle(kRadius, kRing),
                                           sweep::evaluate_polyline(path, planar), sweep::SeamMode::Full, nullptr,
                                           controls);
}

double farthest_from_path(const sweep::Mesh& mesh, const std::vector<glm::dvec3>& path) {
  double farthest = 0.0;
  for (const glm::vec3& v : mesh.positions) farthest = std::max(farthest, distance_to_path(glm::dvec3(v), path));
  return farthest;
}

TEST(MitreLimit, TheRuleIsSvgsStrokeMiterlimit) {
  const glm::dvec3 in(1, 0, 0);
  const auto out = [](double turn_degrees) {
    const double t = turn_degrees * std::numbers::pi / 180.0;
    return glm::dvec3(std::cos(t), std::sin(t), 0.0);
  };
  // The stretch 1 / cos(turn / 2) passes 4 at a turn of 2 acos(1/4) = 151.04 degrees.
  EXPECT_FALSE(sweep::bevels_corner(in, out(151.0), 4.0));
  EXPECT_TRUE(sweep::bevels_corner(in, out(151.1), 4.0));
  EXPECT_FALSE(sweep::bevels_corner(in, out(90.0), 4.0));
  EXPECT_FALSE(sweep::bevels_corner(in, out(89.0), std::sqrt(2.0)));
  EXPECT_TRUE(sweep::bevels_corner(in, out(91.0), std::sqrt(2.0)));
  EXPECT_TRUE(sweep::bevels_corner(in, out(1.0), 1.0));  // 1 bevels every corner
  EXPECT_TRUE(sweep::bevels_corner(in, -in, 1e6));       // a reversal has no mitre
}

TEST(MitreLimit, ASharpCornerIsBevelledWithinTheRadius) {
  for (const double turn : {155.0, 170.0, 179.0, 180.0}) {
    const std::vector<glm::dvec3> path = hairpin(turn);
    const sweep::Mesh bevelled = tube(path, sweep::kMitreLimit);
    // Every vertex at the tube's radius from the path (float rounding aside): no spike.
    EXPECT_LE(farthest_from_path(bevelled, path), kRadius * (1 + 1e-5)) << turn;
    for (const glm::vec3& n : bevelled.normals) EXPECT_NEAR(glm::length(glm::dvec3(n)), 1.0, 1e-5) << turn;
  }
  // The same corner mitred under a higher limit reaches r / cos(turn / 2).
  const double turn = 155.0;
  const double stretch = 1.0 / std::cos(0.5 * turn * std::numbers::pi / 180.0);
  const sweep::Mesh mitred = tube(hairpin(turn), 10.0);
  EXPECT_NEAR(farthest_from_path(mitred, hairpin(turn)), kRadius * stretch, 1e-3 * kRadius);
  EXPECT_GT(stretch, 4.0);
}

TEST(MitreLimit, CountsAreTheGridPlusARingAndAStripPerBevel) {
  // Two corners: 160 degrees (bevelled at 4, mitred at 10) and 90 degrees (mitred at both).
  const std::vector<glm::dvec3> path{{0, 0, 0}, {1, 0, 0}, {1 - 0.94, 0.342, 0}, {1 - 0.94, 1.342, 0}};
  const std::size_t samples = path.size();
  const sweep::Mesh mitred = tube(path, 10.0);
  EXPECT_EQ(mitred.vertex_count(), kRing * samples);
  EXPECT_EQ(mitred.triangle_count(), 2 * kRing * (samples - 1));
  const sweep::Mesh bevelled = tube(path, 4.0);
  EXPECT_EQ(bevelled.vertex_count(), kRing * samples + kRing + 4 * kRing);
  EXPECT_EQ(bevelled.triangle_count(), 2 * kRing * (samples - 1) + 2 * kRing);
  EXPECT_EQ(static_cast<std::int64_t>(bevelled.vertex_count()),
            sweep::cylinder_vertex_count(kRing + 1, true, static_cast<std::int64_t>(samples), false, 1));
  EXPECT_EQ(sweep::bevel_count(sweep::evaluate_polyline(path, true), 4.0), 1u);
  EXPECT_EQ(sweep::bevel_count(sweep::evaluate_polyline(path, true), 10.0), 0u);
}

TEST(MitreLimit, BevelledTubesAreWatertightWithOutwardFlatStrips) {
  // A capped zigzag (2D and 3D frames) and a closed triangle-like loop, every corner bevelled.
  const std::vector<glm::dvec3> zigzag{{0, 0, 0}, {0.4, 2, 0}, {0.8, 0, 0}, {1.2, 2, 0}, {2.2, 2, 0}};
  const std::vector<glm::dvec3> loop{{0, 0, 0}, {3, 0.3, 0}, {0, 0.6, 0}, {0.2, 0.3, 0}, {0, 0, 0}};
  for (const bool planar : {true, false}) {
    for (const auto* path : {&zigzag, &loop}) {
      const bool closed = path == &loop;
      const sweep::Mesh mesh = tube(*path, 1.0, !closed, planar);
      const sweep::MeshTopology topology = sweep::mesh_topology(mesh);
      EXPECT_TRUE(topology.closed_manifold()) << planar << closed << " boundary " << topology.boundary_edges
                                              << " non-manifold " << topology.non_manifold_edges;
      EXPECT_GT(sweep::signed_volume(mesh), 0.0);
      EXPECT_LE(farthest_from_path(mesh, *path), kRadius * (1 + 1e-5));
      // The strips (after the grid and before any cap): one flat normal per quad, the quad's own,
      // pointing away from the path on the outside of each bend.
      const std::size_t corners = closed ? path->size() - 1 : path->size() - 2;
      const std::size_t grid = kRing * ((closed ? path->size() - 1 : path->size()) + corners);
      const std::size_t strips_end = grid + 4 * kRing * corners;
      std::size_t strip_triangles = 0;
      for (std::size_t t = 0; t < mesh.triangle_count(); ++t) {
        const std::uint32_t* v = &mesh.indices[3 * t];
        if (*std::min_element(v, v + 3) < grid || *std::max_element(v, v + 3) >= strips_end) continue;
        ++strip_triangles;
        const glm::dvec3 a(mesh.positions[v[0]]), b(mesh.positions[v[1]]), c(mesh.positions[v[2]]);
        const glm::dvec3 area = glm::cross(b - a, c - a);
        if (glm::length(area) < 1e-6 * kRadius * kRadius) continue;  // folded to nothing on the bend's axis
        for (int k = 0; k < 3; ++k) {
          EXPECT_GT(glm::dot(glm::normalize(area), glm::dvec3(mesh.normals[v[k]])), 0.999) << "flat, same side";
        }
      }
      // Two a strip quad, less those folded to nothing on the bend's axis (none of zero area).
      EXPECT_GT(strip_triangles, kRing * corners);
      EXPECT_LE(strip_triangles, 2 * kRing * corners);
    }
  }
}

TEST(MitreLimit, TheBevelFacesAwayFromTheBend) {
  // The strip joins the arriving segment's end ring to the leaving one's start ring, so its area
  // vector is that of the two ring polygons, along T_in - T_out: out of the bend, as a 2D stroke's
  // bevel faces. Its triangles are the last ones (no caps here).
  for (const double turn : {120.0, 155.0, 170.0, 180.0}) {
    const std::vector<glm::dvec3> path = hairpin(turn);
    const sweep::Mesh mesh = tube(path, 1.0);
    const glm::dvec3 in = glm::normalize(path[1] - path[0]), out = glm::normalize(path[2] - path[1]);
    glm::dvec3 area(0.0);
    for (std::size_t t = 2 * kRing * 2; t < mesh.triangle_count(); ++t) {
      const std::uint32_t* v = &mesh.indices[3 * t];
      const glm::dvec3 a(mesh.positions[v[0]]), b(mesh.positions[v[1]]), c(mesh.positions[v[2]]);
      area += 0.5 * glm::cross(b - a, c - a);
    }
    EXPECT_GT(glm::dot(glm::normalize(area), glm::normalize(in - out)), 0.999) << turn;
    // Each ring is a regular 12-gon of circumradius r: area 12 / 2 sin(30 degrees) r^2 = 3 r^2.
    EXPECT_NEAR(glm::length(area), glm::length(in - out) * 3.0 * kRadius * kRadius, 1e-5) << turn;
  }
}

}  // namespace
