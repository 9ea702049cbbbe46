// circ NAME STEPS 0: a point with the circle's turning frames, which students sweep along to turn
// a profile about z (issue 26). The reader accepts it, evaluation gives finite frames, and a
// generalized cylinder along it is the closed, outward solid of revolution about z.
#include "geometry/mesh/mesh_topology.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/scene.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace {

using sweep::test::expect_error;

// A closed B-spline loop around (1, 0) in the profile plane, swept along a point.
const std::string kTorus =
    "circ point 24 0\n"
    "bsp2 loop 8 7 [1.3 0] [1 0.3] [0.7 0] [1 -0.3] [1.3 0] [1 0.3] [0.7 0]\n"
    "gcyl torus loop point\n";

TEST(ZeroRadiusCircle, IsThePointWithTheCirclesTurningFrames) {
  const sweep::Document doc = sweep::io::parse_swp("circ point 24 0\n", "point.swp");
  const sweep::CurveSamples samples = sweep::evaluate_curve(doc.objects[0]);
  ASSERT_EQ(samples.frames.size(), 25u);
  EXPECT_TRUE(samples.closed);
  for (std::size_t i = 0; i < samples.frames.size(); ++i) {
    const sweep::Frame& f = samples.frames[i];
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(i % 24) / 24.0;
    EXPECT_EQ(f.V, glm::dvec3(0.0)) << i;
    EXPECT_NEAR(glm::distance(f.T, glm::dvec3(-std::sin(angle), std::cos(angle), 0.0)), 0.0, 1e-12) << i;
    EXPECT_NEAR(glm::distance(f.B, glm::dvec3(0.0, 0.0, 1.0)), 0.0, 1e-12) << i;
    EXPECT_NEAR(glm::distance(f.N, glm::cross(f.B, f.T)), 0.0, 1e-12) << i;
    EXPECT_EQ(samples.curvature[i], 0.0) << "nothing divides by the radius";
  }
  EXPECT_EQ(sweep::curve_extent(doc.objects[0]), 0.0);
}

TEST(ZeroRadiusCircle, AGeneralizedCylinderAlongItIsTheProfileTurnedAboutZ) {
  const sweep::Document doc = sweep::io::parse_swp(kTorus, "torus.swp");
  const sweep::Scene scene = sweep::evaluate_document(doc);
  const sweep::Mesh& mesh = scene.objects[2].mesh;
  ASSERT_GT(mesh.vertex_count(), 0u);
  const sweep::CurveSamples profile = sweep::evaluate_curve(doc.objects[1]);
  // Every vertex lies on the circle the profile's sample turns on: at |x| from z, at height y.
  for (std::size_t v = 0; v < mesh.vertex_count(); ++v) {
    const glm::dvec3 p(mesh.positions[v]);
    const auto& sample = profile.frames[v % (profile.frames.size() - 1)].V;
    EXPECT_NEAR(std::hypot(p.x, p.y), std::abs(sample.x), 1e-6) << v;
    EXPECT_NEAR(p.z, sample.y, 1e-6) << v;
    ASSERT_TRUE(std::isfinite(mesh.normals[v].x) && std::isfinite(mesh.normals[v].y) &&
                std::isfinite(mesh.normals[v].z));
  }
  EXPECT_TRUE(sweep::mesh_topology(mesh).closed_manifold());
  // The same solid as the surface of revolution of the profile, about z instead of y.
  const sweep::Document srev = sweep::io::parse_swp(kTorus + "srev ref 24 loop\n", "torus.swp");
  const sweep::Scene revolved = sweep::evaluate_document(srev);
  EXPECT_NEAR(sweep::signed_volume(mesh), sweep::signed_volume(revolved.objects[3].mesh),
              1e-4 * std::abs(sweep::signed_volume(mesh)));
  EXPECT_GT(sweep::signed_volume(mesh), 0.0) << "normals out, triangles counterclockwise from outside";
}

TEST(ZeroRadiusCircle, AdaptiveSamplingTakesItsSteps) {
  const sweep::Document doc = sweep::io::parse_swp("circ point 24 0 tolerance 0.001\n", "point.swp");
  EXPECT_EQ(sweep::evaluate_curve(doc.objects[0]).frames.size(), 25u);
  const sweep::Document plain = sweep::io::parse_swp("circ point 24 0\n", "point.swp");
  EXPECT_EQ(sweep::evaluate_curve(plain.objects[0], {}, {0.001, 0.0}).frames.size(), 25u);
}

TEST(ZeroRadiusCircle, ANegativeRadiusIsStillAnError) {
  expect_error("circ c 8 -1\n", 1, 10, "expected a radius of 0 or more, found '-1'");
  expect_error("circ c 8 1e-13\n", 1, 10, "expected a radius of 0 or of at least 1e-12, found '1e-13'");
}

}  // namespace
