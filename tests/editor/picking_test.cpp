// Picking maths: world points to window pixels and back along the pointer ray, for perspective
// and orthographic cameras, and the plane, line, segment and grid helpers drags use.
#include "editor/picking.hpp"

#include "support/screen_mapping_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace sweep::editor {
namespace {

using test::distance_to_ray_line;
using test::kEye;
using test::kWindow;

const std::vector<glm::dvec3> kWorldPoints = {
    {0.0, 0.0, 0.0}, {1.0, 0.5, -0.5}, {-1.2, 0.8, 0.3}, {0.4, -1.1, 1.5}, {-0.7, -0.6, -2.0}, {1.5, 1.2, 0.9},
};

TEST(Picking, TheTargetLandsInTheWindowCentreAndUpIsUp) {
  const ScreenMapping mapping = test::perspective_mapping();
  const auto centre = to_screen(mapping, {0.0, 0.0, 0.0});
  ASSERT_TRUE(centre);
  EXPECT_NEAR(centre->x, 400.0, 1e-9);
  EXPECT_NEAR(centre->y, 300.0, 1e-9);
  const auto above = to_screen(mapping, {0.0, 1.0, 0.0});
  ASSERT_TRUE(above);
  EXPECT_LT(above->y, 300.0) << "window y grows downwards";
}

TEST(Picking, APointLandsOnAPixelWhoseRayPassesThroughIt) {
  for (const ScreenMapping& mapping : {test::perspective_mapping(), test::ortho_mapping()}) {
    for (const glm::dvec3& p : kWorldPoints) {
      const auto pixel = to_screen(mapping, p);
      ASSERT_TRUE(pixel);
      EXPECT_GT(pixel->x, 0.0);
      EXPECT_LT(pixel->x, kWindow.x);
      EXPECT_GT(pixel->y, 0.0);
      EXPECT_LT(pixel->y, kWindow.y);
      const Ray ray = pointer_ray(mapping, *pixel);
      EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-12);
      EXPECT_LT(distance_to_ray_line(ray, p), 1e-9) << p.x << " " << p.y << " " << p.z;
      EXPECT_GT(glm::dot(p - ray.origin, ray.direction), 0.0) << "the point is ahead of the ray's origin";
    }
  }
}

TEST(Picking, EveryPointOfAPixelsRayLandsOnThatPixel) {
  const ScreenMapping mapping = test::perspective_mapping();
  for (const glm::dvec2 pixel : {glm::dvec2(10.0, 20.0), glm::dvec2(400.0, 300.0), glm::dvec2(790.0, 580.0)}) {
    const Ray ray = pointer_ray(mapping, pixel);
    EXPECT_LT(distance_to_ray_line(ray, kEye), 1e-9) << "perspective rays come from the eye";
    for (double t : {0.5, 3.0, 20.0}) {
      const auto back = to_screen(mapping, ray.origin + t * ray.direction);
      ASSERT_TRUE(back);
      EXPECT_NEAR(back->x, pixel.x, 1e-7);
      EXPECT_NEAR(back->y, pixel.y, 1e-7);
    }
  }
}

TEST(Picking, OrthographicRaysAreParallelToTheViewDirection) {
  const ScreenMapping mapping = test::ortho_mapping();
  for (const glm::dvec2 pixel : {glm::dvec2(0.0, 0.0), glm::dvec2(400.0, 300.0), glm::dvec2(700.0, 100.0)}) {
    const Ray ray = pointer_ray(mapping, pixel);
    EXPECT_NEAR(ray.direction.x, 0.0, 1e-12);
    EXPECT_NEAR(ray.direction.y, 0.0, 1e-12);
    EXPECT_NEAR(ray.direction.z, -1.0, 1e-12);
  }
  // Depth does not move a point on the screen; 8 x 6 world units fill 800 x 600 pixels.
  const auto near_point = to_screen(mapping, {1.0, 1.0, 5.0});
  const auto far_point = to_screen(mapping, {1.0, 1.0, -50.0});
  ASSERT_TRUE(near_point && far_point);
  EXPECT_NEAR(near_point->x, 500.0, 1e-9);
  EXPECT_NEAR(near_point->y, 200.0, 1e-9);
  EXPECT_NEAR(far_point->x, 500.0, 1e-9);
  EXPECT_NEAR(far_point->y, 200.0, 1e-9);
}

TEST(Picking, PointsBehindTheEyeOrNotFiniteHaveNoPixel) {
  const ScreenMapping mapping = test::perspective_mapping();
  EXPECT_FALSE(to_screen(mapping, kEye + kEye)) << "straight behind the eye";
  EXPECT_FALSE(to_screen(mapping, kEye + glm::dvec3(0.5, 0.0, 3.0)));
  EXPECT_FALSE(to_screen(mapping, kEye)) << "at the eye";
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_FALSE(to_screen(mapping, {nan, 0.0, 0.0}));
  EXPECT_FALSE(to_screen(mapping, {0.0, inf, 0.0}));
}

TEST(Picking, AWindowOfNoSizeIsTreatedAsOnePixel) {
  const ScreenMapping mapping = screen_mapping(glm::dmat4(1.0), {0.0, -5.0});
  EXPECT_EQ(mapping.window_size, glm::dvec2(1.0, 1.0));
}

TEST(Picking, IntersectPlaneHitsThePlaneOnTheRay) {
  const Ray ray{{1.0, 2.0, 3.0}, glm::normalize(glm::dvec3(0.2, -0.3, -1.0))};
  const glm::dvec3 point{0.5, 0.5, -1.0};
  const glm::dvec3 normal{0.1, 0.2, 3.0};  // not unit: it is normalised
  const auto hit = intersect_plane(ray, point, normal);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(glm::dot(*hit - point, glm::normalize(normal)), 0.0, 1e-12);
  EXPECT_LT(distance_to_ray_line(ray, *hit), 1e-12);

  const Ray along{{0.0, 0.0, 1.0}, {1.0, 0.0, 0.0}};
  EXPECT_FALSE(intersect_plane(along, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0})) << "parallel: no hit";
  EXPECT_FALSE(intersect_plane(ray, point, {0.0, 0.0, 0.0})) << "no normal, no plane";
}

TEST(Picking, IntersectPlaneIgnoresAPlaneBehindTheRay) {
  // Hits behind the ray's origin (t < 0) are not on the ray: a pointer ray never reaches them.
  const Ray away{{0.0, 0.0, 1.0}, glm::normalize(glm::dvec3(0.3, 0.0, 1.0))};
  EXPECT_FALSE(intersect_plane(away, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0})) << "the plane is behind the ray";
  const Ray towards{{0.0, 0.0, 1.0}, -away.direction};
  EXPECT_TRUE(intersect_plane(towards, {0.0, 0.0, 0.0}, {0.0, 0.0, 1.0})) << "the same plane ahead is hit";
}

TEST(Picking, ClosestOnLineIsWhereTheCommonPerpendicularMeetsTheLine) {
  const Ray ray{{0.0, 3.0, 4.0}, glm::normalize(glm::dvec3(0.3, -1.0, -0.5))};
  const glm::dvec3 point{1.0, 0.5, -0.25};
  const glm::dvec3 axis{0.0, 0.0, 1.0};
  const auto closest = closest_on_line(ray, point, axis);
  ASSERT_TRUE(closest);
  EXPECT_EQ(closest->x, point.x) << "on the line: only z moves";
  EXPECT_EQ(closest->y, point.y);
  // The nearest point of the ray to it makes a segment perpendicular to both lines.
  const double t = glm::dot(*closest - ray.origin, ray.direction);
  const glm::dvec3 on_ray = ray.origin + t * ray.direction;
  EXPECT_NEAR(glm::dot(*closest - on_ray, axis), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(*closest - on_ray, ray.direction), 0.0, 1e-12);

  const Ray along{{1.0, 0.5, 9.0}, {0.0, 0.0, -1.0}};
  EXPECT_FALSE(closest_on_line(along, point, axis)) << "a ray along the line has no closest point";
}

TEST(Picking, DistanceToSegment) {
  const glm::dvec2 a{0.0, 0.0};
  const glm::dvec2 b{4.0, 0.0};
  EXPECT_DOUBLE_EQ(distance_to_segment({2.0, 3.0}, a, b), 3.0) << "above the middle";
  EXPECT_DOUBLE_EQ(distance_to_segment({2.0, -1.5}, a, b), 1.5);
  EXPECT_DOUBLE_EQ(distance_to_segment({7.0, 4.0}, a, b), 5.0) << "past b: the distance to b";
  EXPECT_DOUBLE_EQ(distance_to_segment({-3.0, -4.0}, a, b), 5.0) << "before a: the distance to a";
  EXPECT_DOUBLE_EQ(distance_to_segment({1.0, 0.0}, a, b), 0.0);
  EXPECT_DOUBLE_EQ(distance_to_segment({4.0, 4.0}, {1.0, 1.0}, {1.0, 1.0}), std::sqrt(18.0)) << "a point segment";
}

TEST(Picking, SnapToGridRoundsTheMaskedCoordinates) {
  const glm::dvec3 p{0.26, -0.74, 1.12};
  const glm::dvec3 all = snap_to_grid(p, 0.5);
  EXPECT_DOUBLE_EQ(all.x, 0.5);
  EXPECT_DOUBLE_EQ(all.y, -0.5);
  EXPECT_DOUBLE_EQ(all.z, 1.0);
  const glm::dvec3 some = snap_to_grid(p, 0.25, glm::bvec3(true, false, true));
  EXPECT_DOUBLE_EQ(some.x, 0.25);
  EXPECT_EQ(some.y, p.y) << "unmasked coordinates stay exactly";
  EXPECT_DOUBLE_EQ(some.z, 1.0);
  EXPECT_EQ(snap_to_grid(p, 0.0), p) << "no grid, no snapping";
  EXPECT_EQ(snap_to_grid(p, -1.0), p);
  const glm::dvec3 zero = snap_to_grid({-0.1, 0.0, 0.0}, 1.0);
  EXPECT_EQ(zero.x, 0.0);
  EXPECT_FALSE(std::signbit(zero.x)) << "-0 would be written to the file as -0";
}

}  // namespace
}  // namespace sweep::editor
