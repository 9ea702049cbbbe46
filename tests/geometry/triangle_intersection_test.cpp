// Triangle-triangle and ray-triangle tests (triangle_intersection.hpp) on cases drawn by hand,
// each triangle pair both ways round: crossing, apart, touching at a point or along an edge,
// almost touching, coplanar (overlapping, meeting at an edge or a corner, apart), zero area.
#include "geometry/mesh/triangle_intersection.hpp"
#include "support/shell_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace sweep {
namespace {

using test::on_triangle;

const TriangleCorners kBase{glm::dvec3{0, 0, 0}, glm::dvec3{2, 0, 0}, glm::dvec3{0, 2, 0}};

TriangleCorners moved(const TriangleCorners& t, const glm::dvec3& by) {
  return {t[0] + by, t[1] + by, t[2] + by};
}

/// The test both ways round, which must agree.
bool intersect(const TriangleCorners& a, const TriangleCorners& b) {
  const bool ab = triangles_intersect(a, b), ba = triangles_intersect(b, a);
  EXPECT_EQ(ab, ba);
  return ab;
}

TEST(TriangleIntersection, CrossingTrianglesMeetInAPointOnBoth) {
  const TriangleCorners b{glm::dvec3{0.5, 0.5, -1}, glm::dvec3{0.5, 0.5, 1}, glm::dvec3{0.5, -1, 0}};
  ASSERT_TRUE(intersect(kBase, b));
  const glm::dvec3 p = *triangle_intersection_point(kBase, b);
  EXPECT_NEAR(glm::distance(p, glm::dvec3(0.5, 0.25, 0)), 0.0, 1e-12);  // the common segment's middle
  EXPECT_TRUE(on_triangle(p, kBase, 1e-12));
  EXPECT_TRUE(on_triangle(p, b, 1e-12));
}

TEST(TriangleIntersection, DisjointTrianglesDoNotIntersect) {
  const TriangleCorners b{glm::dvec3{0.5, 0.5, -1}, glm::dvec3{0.5, 0.5, 1}, glm::dvec3{0.5, -1, 0}};
  EXPECT_FALSE(intersect(kBase, moved(b, {0, 0, 3})));         // all above the plane
  EXPECT_FALSE(intersect(kBase, moved(b, {5, 5, 0})));         // through the plane, beside the triangle
  EXPECT_FALSE(intersect(kBase, moved(kBase, {0, 0, 1e-3})));  // parallel, just above
}

/// Whether the two intersect at `expected` (to 1e-9: the tolerance of 1e-10 of their size), both ways round.
void expect_touch_at(const TriangleCorners& a, const TriangleCorners& b, const glm::dvec3& expected) {
  ASSERT_TRUE(intersect(a, b));
  EXPECT_NEAR(glm::distance(*triangle_intersection_point(a, b), expected), 0.0, 1e-9);
  EXPECT_NEAR(glm::distance(*triangle_intersection_point(b, a), expected), 0.0, 1e-9);
}

TEST(TriangleIntersection, TouchingAtOnePointCounts) {
  // A corner on the face, a corner on a corner, and an edge across an edge at (1, 0, 0).
  expect_touch_at(kBase, {glm::dvec3{0.5, 0.5, 0}, glm::dvec3{1, 1, 1}, glm::dvec3{0, 1, 1}}, {0.5, 0.5, 0});
  expect_touch_at(kBase, {glm::dvec3{2, 0, 0}, glm::dvec3{3, 0, 1}, glm::dvec3{3, 1, 1}}, {2, 0, 0});
  expect_touch_at(kBase, {glm::dvec3{1, -0.5, 0.5}, glm::dvec3{1, 0.5, -0.5}, glm::dvec3{1, -2, -2}}, {1, 0, 0});
}

TEST(TriangleIntersection, AlmostTouchingDoesNotCount) {
  EXPECT_FALSE(intersect(kBase, {glm::dvec3{0.5, 0.5, 1e-6}, glm::dvec3{1, 1, 1}, glm::dvec3{0, 1, 1}}));
  EXPECT_FALSE(intersect(kBase, {glm::dvec3{2 + 1e-6, 0, 0}, glm::dvec3{3, 0, 1}, glm::dvec3{3, 1, 1}}));
  // Lowered by 1e-6, the edge across the base's edge crosses z = 0 just outside it.
  EXPECT_FALSE(intersect(
      kBase, {glm::dvec3{1, -0.5, 0.5 - 1e-6}, glm::dvec3{1, 0.5, -0.5 - 1e-6}, glm::dvec3{1, -2, -2 - 1e-6}}));
}

TEST(TriangleIntersection, AnEdgeLyingOnTheOtherCounts) {
  expect_touch_at(kBase, {glm::dvec3{0.5, 0.5, 0}, glm::dvec3{1, 0.5, 0}, glm::dvec3{0.75, 0.5, 1}}, {0.75, 0.5, 0});
}

TEST(TriangleIntersection, CoplanarTrianglesCountWhenTheirAreasOverlap) {
  ASSERT_TRUE(intersect(kBase, moved(kBase, {0.5, 0.5, 0})));
  const glm::dvec3 p = *triangle_intersection_point(kBase, moved(kBase, {0.5, 0.5, 0}));
  EXPECT_TRUE(on_triangle(p, kBase, 1e-12));
  EXPECT_TRUE(on_triangle(p, moved(kBase, {0.5, 0.5, 0}), 1e-12));
  EXPECT_TRUE(intersect(kBase, {glm::dvec3{0.2, 0.2, 0}, glm::dvec3{0.3, 0.2, 0}, glm::dvec3{0.2, 0.3, 0}}));  // inside
  EXPECT_TRUE(
      intersect(kBase, {glm::dvec3{0.2, 0.2, 0}, glm::dvec3{0.2, 0.3, 0}, glm::dvec3{0.3, 0.2, 0}}));     // facing down
  EXPECT_FALSE(intersect(kBase, moved(kBase, {3, 3, 0})));                                                // apart
  EXPECT_FALSE(intersect(kBase, {glm::dvec3{2, 1e-6, 0}, glm::dvec3{2, 2, 0}, glm::dvec3{1e-6, 2, 0}}));  // nearly
}

TEST(TriangleIntersection, CoplanarTrianglesMeetingAtAnEdgeOrCornerCount) {
  const TriangleCorners across_edge{glm::dvec3{2, 0, 0}, glm::dvec3{2, 2, 0}, glm::dvec3{0, 2, 0}};
  ASSERT_TRUE(intersect(kBase, across_edge));
  const glm::dvec3 p = *triangle_intersection_point(kBase, across_edge);
  EXPECT_NEAR(p.x + p.y, 2.0, 1e-9);  // on the common edge
  expect_touch_at(kBase, {glm::dvec3{2, 0, 0}, glm::dvec3{3, 0, 0}, glm::dvec3{3, 1, 0}}, {2, 0, 0});
}

TEST(TriangleIntersection, ZeroAreaTrianglesIntersectNothing) {
  EXPECT_FALSE(intersect(kBase, {glm::dvec3{0.5, 0.5, -1}, glm::dvec3{0.5, 0.5, 0}, glm::dvec3{0.5, 0.5, 1}}));
}

TEST(RayTriangle, HitsFromEitherSideAndMissesBesideOrAlong) {
  EXPECT_DOUBLE_EQ(*ray_triangle_distance({0.5, 0.5, 3}, {0, 0, -1}, kBase), 3.0);
  EXPECT_DOUBLE_EQ(*ray_triangle_distance({0.5, 0.5, -2}, {0, 0, 1}, kBase), 2.0);
  EXPECT_FALSE(ray_triangle_distance({0.5, 0.5, 3}, {0, 0, 1}, kBase));   // pointing away
  EXPECT_FALSE(ray_triangle_distance({1.5, 1.5, 3}, {0, 0, -1}, kBase));  // beside
  EXPECT_FALSE(ray_triangle_distance({-1, 0.5, 0}, {1, 0, 0}, kBase));    // along its plane
}

TEST(RayTriangle, ARayThroughASharedEdgeHitsBothTriangles) {
  const TriangleCorners other{glm::dvec3{2, 0, 0}, glm::dvec3{2, 2, 0}, glm::dvec3{0, 2, 0}};
  const glm::dvec3 origin{2.0 / 3.0, 4.0 / 3.0, 1.0};  // above the diagonal x + y = 2
  EXPECT_TRUE(ray_triangle_distance(origin, {0, 0, -1}, kBase));
  EXPECT_TRUE(ray_triangle_distance(origin, {0, 0, -1}, other));
}

}  // namespace
}  // namespace sweep
