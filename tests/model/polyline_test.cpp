// Polylines (poly2, poly3): straight segments through their points, one sample per point, every
// interior point a corner (mitred in sweeps), closed when the last point equals the first; read,
// written back, evaluated, swept and edited like the other control-point curves.
#include "geometry/mesh/mesh_topology.hpp"
#include "io/swp/write.hpp"
#include "model/edit/edit.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/scene.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <string>

namespace {

using sweep::Document;
using sweep::io::parse_swp;
using sweep::test::expect_error;

const char* const kSquare = "poly2 square 5 [-1 -1] [1 -1] [1 1] [-1 1] [-1 -1]\n";
const char* const kZigzag = "poly3 zig 4 [0 0 0] [1 0 0] [1 1 0] [1 1 2]\n";

}  // namespace

TEST(Polyline, OneSamplePerPointOnTheSegmentsWithUnitTangentsAlongThem) {
  const Document doc = parse_swp(kZigzag, "zig.swp");
  const sweep::CurveSamples c = sweep::evaluate_curve(doc.objects[0]);
  ASSERT_EQ(c.frames.size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) EXPECT_EQ(c.frames[i].V, doc.objects[0].as<sweep::PointsPart>().points[i]);
  // Each sample's tangent leaves along the next segment; the last arrives along the last one.
  EXPECT_LT(glm::length(c.frames[0].T - glm::dvec3(1, 0, 0)), 1e-12);
  EXPECT_LT(glm::length(c.frames[1].T - glm::dvec3(0, 1, 0)), 1e-12);
  EXPECT_LT(glm::length(c.frames[3].T - glm::dvec3(0, 0, 1)), 1e-12);
  for (const sweep::Frame& f : c.frames) {
    EXPECT_NEAR(glm::dot(f.T, f.N), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(f.N), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(f.B), 1.0, 1e-12);
  }
  EXPECT_FALSE(c.closed);
}

TEST(Polyline, EveryInteriorPointIsACornerAndAClosedOneHasOneAtItsSeamToo) {
  const sweep::CurveSamples open = sweep::evaluate_curve(parse_swp(kZigzag, "zig.swp").objects[0]);
  ASSERT_EQ(open.corners.size(), 2u);
  EXPECT_EQ(open.corners[0].sample, 1u);
  EXPECT_EQ(open.corners[1].sample, 2u);
  const sweep::CurveSamples square = sweep::evaluate_curve(parse_swp(kSquare, "square.swp").objects[0]);
  EXPECT_TRUE(square.closed);
  EXPECT_TRUE(square.planar);
  EXPECT_EQ(square.frames.size(), 5u);
  ASSERT_EQ(square.corners.size(), 4u);  // the three interior points and the seam
  EXPECT_EQ(square.corners[0].sample, 0u);
  EXPECT_LT(glm::length(square.corners[0].incoming - glm::dvec3(0, -1, 0)), 1e-12);  // arriving down
  // 2D convention: B = +z, N = B x T (left of travel).
  EXPECT_LT(glm::length(square.frames[0].B - glm::dvec3(0, 0, 1)), 1e-12);
  EXPECT_LT(glm::length(square.frames[0].N - glm::dvec3(0, 1, 0)), 1e-12);
}

TEST(Polyline, ASquareTubeAlongASquarePolylineIsWatertightWithMitredCorners) {
  const Document doc = parse_swp(std::string(kSquare) + "circ ring 12 0.2\ngcyl tube ring square\n", "t.swp");
  const sweep::Scene scene = sweep::evaluate_document(doc);
  const sweep::Mesh& mesh = scene.objects[2].mesh;
  EXPECT_TRUE(sweep::mesh_topology(mesh).closed_manifold());
  // Mitred: at a corner the profile lies in the plane bisecting the turn, stretched by
  // 1/cos(45 degrees), so the outer side reaches (1.2, 1.2); placed square to the leaving
  // segment it would reach only |x| + |y| = 2.2.
  double farthest = 0.0;
  for (const glm::vec3& p : mesh.positions) farthest = std::max(farthest, double(std::abs(p.x) + std::abs(p.y)));
  EXPECT_NEAR(farthest, 2.4, 1e-6);
}

TEST(Polyline, STEPSAndTheToleranceDoNotApply) {
  const Document doc = parse_swp("poly2 p 3 tolerance 0.001 [0 0] [1 0] [1 1]\n", "p.swp");
  EXPECT_EQ(sweep::evaluate_curve(doc.objects[0]).frames.size(), 3u);
  EXPECT_EQ(sweep::evaluate_curve(doc.objects[0], {}, {1e-4, 0.0}).frames.size(), 3u);
  EXPECT_EQ(sweep::curve_sample_count(doc.objects[0]), 3);
}

TEST(Polyline, WritesBackAsItWasRead) {
  const std::string text =
      "poly2 square 5\n[-1 -1]\n[1 -1]\n[1 1]\n[-1 1]\n[-1 -1]\n\npoly3 zig 2\n[0 0 0]\n[1 2 3]\n\n";
  EXPECT_EQ(sweep::io::write_swp(parse_swp(text, "p.swp")), text);
}

TEST(Polyline, BadCountsAndPointsAreLocated) {
  expect_error("poly2 p 1 [0 0]\n", 1, 9, "expected at least 2 polyline control points, found '1'");
  expect_error("poly2 p 2 [0 0] [1 0 0]\n", 1, 22,
               "expected ']' to end point 2 of 2 (2D points have 2 coordinates), found '0'");
  expect_error("poly3 p 2 [0 0 0]\n", 2, 1, "expected '[' to start point 2 of 2, found end of file");
}

TEST(Polyline, PointsAreInsertedDeletedAndAClosedOneStaysClosed) {
  Document doc = parse_swp(kSquare, "square.swp");
  sweep::insert_bspline_point(doc, 0, 1, glm::dvec3(0, -1.5, 0));
  ASSERT_EQ(doc.objects[0].as<sweep::PointsPart>().points.size(), 6u);
  EXPECT_EQ(doc.objects[0].as<sweep::PointsPart>().points[1], glm::dvec3(0, -1.5, 0));
  sweep::move_point(doc, 0, 0, glm::dvec3(-2, -2, 0));
  EXPECT_EQ(doc.objects[0].as<sweep::PointsPart>().points.back(), glm::dvec3(-2, -2, 0));  // the seam moves as one
  sweep::delete_point(doc, 0, 1);
  sweep::delete_point(doc, 0, 1);
  EXPECT_EQ(doc.objects[0].as<sweep::PointsPart>().points.size(), 4u);
  EXPECT_EQ(sweep::test::edit_error(doc, [&] { sweep::delete_point(doc, 0, 1); }),
            "a closed polyline needs at least 3 distinct points (besides the first, repeated)");
}

TEST(Polyline, TheCreatePanelsStarIsAClosedPolylineThatWritesBack) {
  Document doc;
  const int star = sweep::add_curve(doc, "star polyline (2D)", "star");
  EXPECT_EQ(doc.objects[std::size_t(star)].kind(), sweep::ObjectKind::Polyline2);
  EXPECT_TRUE(sweep::evaluate_curve(doc.objects[0]).closed);
  EXPECT_EQ(parse_swp(sweep::io::write_swp(doc), "star.swp"), doc);
}
