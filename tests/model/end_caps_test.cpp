// Caps: capped generalized cylinders and surfaces of revolution are closed, consistently
// oriented solids (no boundary edge once equal positions are welded, positive volume), and
// their volumes converge to the analytic ones.
#include "geometry/mesh/mesh_topology.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <string>

namespace {

sweep::Mesh surface_mesh(const std::string& text) {
  const sweep::Document doc = sweep::io::parse_swp(text, "test.swp");
  return sweep::evaluate_document(doc).objects.back().mesh;
}

void expect_closed_solid(const sweep::Mesh& mesh, const std::string& what) {
  const sweep::MeshTopology topology = sweep::mesh_topology(mesh);
  EXPECT_EQ(topology.boundary_edges, 0u) << what;
  EXPECT_EQ(topology.non_manifold_edges, 0u) << what;
  EXPECT_GT(sweep::signed_volume(mesh), 0.0) << what;
  // Cap normals point out too: away from the solid's centre along the cap's plane normal.
  for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f) << what;
}

TEST(Caps, CappedCylinderIsAClosedSolidWhoseVolumeConvergesToPiR2H) {
  const double pi = std::numbers::pi;
  double previous_error = 1e9;
  for (const int steps : {8, 32, 128, 512}) {
    const sweep::Mesh mesh = surface_mesh("circ c " + std::to_string(steps) +
                                          " 0.5\nbez3 up 4 4 [0 0 0] [0 1 0] [0 2 0] [0 3 0]\ngcyl g c up caps\n");
    expect_closed_solid(mesh, "steps " + std::to_string(steps));
    const double exact = pi * 0.25 * 3.0;
    // The inscribed polygon's area: (n / 2) r^2 sin(2 pi / n).
    const double polygon = 0.5 * steps * 0.25 * std::sin(2.0 * pi / steps) * 3.0;
    EXPECT_NEAR(sweep::signed_volume(mesh), polygon, 1e-5 * exact);
    const double error = std::abs(sweep::signed_volume(mesh) - exact);
    EXPECT_LT(error, previous_error);
    previous_error = error;
  }
  EXPECT_LT(previous_error, 1e-4 * pi * 0.75);
}

TEST(Caps, CappedLinearTaperConeConvergesToAThirdOfTheCylinder) {
  const double pi = std::numbers::pi;
  double previous_error = 1e9;
  for (const int steps : {16, 64, 256}) {
    const sweep::Mesh mesh =
        surface_mesh("circ c " + std::to_string(steps) +
                     " 1\nbez3 up 8 4 [0 0 0] [0 1 0] [0 2 0] [0 3 0]\ncr2 taper 2 2 [0 1] [1 1e-6]\n"
                     "gcyl cone c up scale taper caps\n");
    expect_closed_solid(mesh, "steps " + std::to_string(steps));
    const double error = std::abs(sweep::signed_volume(mesh) - pi * 3.0 / 3.0);
    EXPECT_LT(error, previous_error);
    previous_error = error;
  }
  EXPECT_LT(previous_error, 1e-3 * pi);
}

TEST(Caps, NonConvexProfilesAlongCurvedSweepsAreClosed) {
  // A star (both orientations) along a bending, twisting path.
  const std::string star_ccw =
      "cr2 star 2 11 [1 0] [0.31 0.22] [0.31 0.95] [-0.12 0.36] [-0.81 0.59] [-0.38 0] [-0.81 -0.59] "
      "[-0.12 -0.36] [0.31 -0.95] [0.31 -0.22] [1 0]\n";
  const std::string star_cw =
      "cr2 star 2 11 [1 0] [0.31 -0.22] [0.31 -0.95] [-0.12 -0.36] [-0.81 -0.59] [-0.38 0] [-0.81 0.59] "
      "[-0.12 0.36] [0.31 0.95] [0.31 0.22] [1 0]\n";
  for (const std::string& star : {star_ccw, star_cw}) {
    const sweep::Mesh mesh = surface_mesh(star +
                                          "bsp3 path 10 5 [0 0 0] [0 2 0] [1 4 1] [3 5 1] [5 5 0]\n"
                                          "gcyl g star path twist 120 caps\n");
    expect_closed_solid(mesh, star);
  }
}

TEST(Caps, SurfaceOfRevolutionIsClosedWithDisksAtEndsOffTheAxis) {
  const double pi = std::numbers::pi;
  // A straight wall at |x| = 1 from y = 1 to y = -1, traced both ways and on both sides: a
  // cylinder of volume 2 pi, with a disk at each end.
  for (const char* wall : {"[-1 1] [-1 0.3] [-1 -0.3] [-1 -1]", "[-1 -1] [-1 -0.3] [-1 0.3] [-1 1]",
                           "[1 1] [1 0.3] [1 -0.3] [1 -1]", "[1 -1] [1 -0.3] [1 0.3] [1 1]"}) {
    const sweep::Mesh mesh = surface_mesh(std::string("bez2 wall 1 4 ") + wall + "\nsrev s 512 wall caps\n");
    expect_closed_solid(mesh, wall);
    EXPECT_NEAR(sweep::signed_volume(mesh), 2.0 * pi, 1e-3) << wall;
  }
  // A cup: one end on the axis (no disk needed there), the rim closed by a disk.
  const sweep::Mesh cup = surface_mesh("bez2 cup 8 4 [0 -1] [-1.2 -1] [-1 0] [-1 1]\nsrev s 64 cup caps\n");
  expect_closed_solid(cup, "cup");
}

TEST(Caps, WithoutCapsTheEndsAreOpen) {
  const sweep::Mesh tube = surface_mesh("circ c 16 0.5\nbez3 up 4 4 [0 0 0] [0 1 0] [0 2 0] [0 3 0]\ngcyl g c up\n");
  EXPECT_EQ(sweep::mesh_topology(tube).boundary_edges, 32u);
  const sweep::Mesh wall = surface_mesh("bez2 wall 1 4 [-1 1] [-1 0.3] [-1 -0.3] [-1 -1]\nsrev s 20 wall\n");
  EXPECT_EQ(sweep::mesh_topology(wall).boundary_edges, 40u);
}

}  // namespace
