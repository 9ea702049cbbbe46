// The editor's picking maths with the viewer's camera: projecting to the window and back
// through a turned, shifted, perspective or orthographic Camera.
#include "editor/picking.hpp"
#include "render/camera.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace sweep::render {
namespace {

using editor::closest_on_line;
using editor::distance_to_segment;
using editor::intersect_plane;
using editor::pointer_ray;
using editor::Ray;
using editor::ScreenMapping;
using editor::snap_to_grid;
using editor::to_screen;

/// The mapping of `camera` over a window of `size` whose framebuffer has aspect `aspect`.
ScreenMapping screen_mapping(const Camera& camera, const glm::dvec2& size, double aspect) {
  return editor::screen_mapping(camera.projection_matrix(aspect) * camera.view_matrix(), size);
}

constexpr double kTolerance = 1e-9;

void expect_near(const glm::dvec3& a, const glm::dvec3& b, double tolerance = kTolerance) {
  EXPECT_NEAR(a.x, b.x, tolerance);
  EXPECT_NEAR(a.y, b.y, tolerance);
  EXPECT_NEAR(a.z, b.z, tolerance);
}

Camera turned_camera(Projection projection) {
  Camera camera;
  camera.projection = projection;
  camera.set_yaw_pitch(35.0, 25.0);
  camera.target = {0.5, -0.25, 0.75};
  camera.distance = 6.0;
  camera.scene_radius = 2.0;
  camera.lens_shift = {0.2, 0.0};
  return camera;
}

TEST(Picking, TheTargetLandsAtTheShiftedCentre) {
  for (Projection projection : {Projection::Perspective, Projection::Orthographic}) {
    const Camera camera = turned_camera(projection);
    const ScreenMapping mapping = screen_mapping(camera, {1000.0, 500.0}, 2.0);
    const auto pixel = to_screen(mapping, camera.target);
    ASSERT_TRUE(pixel.has_value());
    EXPECT_NEAR(pixel->x, 500.0 + 0.2 * 500.0, 1e-6);  // a lens shift of 0.2 NDC is a tenth of the width
    EXPECT_NEAR(pixel->y, 250.0, 1e-6);
  }
}

TEST(Picking, ThePointerRayPassesThroughThePointUnderIt) {
  for (Projection projection : {Projection::Perspective, Projection::Orthographic}) {
    const Camera camera = turned_camera(projection);
    const ScreenMapping mapping = screen_mapping(camera, {800.0, 600.0}, 800.0 / 600.0);
    const glm::dvec3 world{1.0, 0.3, -0.4};
    const auto pixel = to_screen(mapping, world);
    ASSERT_TRUE(pixel.has_value());
    const Ray ray = pointer_ray(mapping, *pixel);
    EXPECT_NEAR(glm::length(ray.direction), 1.0, 1e-12);
    // Distance from the point to the ray.
    const glm::dvec3 w = world - ray.origin;
    const glm::dvec3 off = w - glm::dot(w, ray.direction) * ray.direction;
    EXPECT_LT(glm::length(off), 1e-7);
    EXPECT_GT(glm::dot(w, ray.direction), 0.0) << "the ray runs away from the eye, towards the point";
  }
}

TEST(Picking, PointsBehindTheEyeHaveNoScreenPosition) {
  const Camera camera = turned_camera(Projection::Perspective);
  const ScreenMapping mapping = screen_mapping(camera, {800.0, 600.0}, 800.0 / 600.0);
  EXPECT_FALSE(to_screen(mapping, camera.eye() - 3.0 * camera.forward()).has_value());
  EXPECT_FALSE(to_screen(mapping, glm::dvec3(std::nan(""), 0.0, 0.0)).has_value());
}

TEST(Picking, DraggingInTheXyPlaneKeepsZAtZero) {
  const Camera camera = turned_camera(Projection::Perspective);
  const ScreenMapping mapping = screen_mapping(camera, {800.0, 600.0}, 800.0 / 600.0);
  const glm::dvec3 handle{0.7, -0.2, 0.0};
  const auto pixel = to_screen(mapping, handle);
  ASSERT_TRUE(pixel.has_value());
  const auto hit = intersect_plane(pointer_ray(mapping, *pixel), glm::dvec3(0.0), {0.0, 0.0, 1.0});
  ASSERT_TRUE(hit.has_value());
  expect_near(*hit, handle, 1e-7);
  // A plane seen edge-on gives no hit rather than a point at infinity.
  Ray grazing;
  grazing.origin = {0.0, 0.0, 1.0};
  grazing.direction = {1.0, 0.0, 0.0};
  EXPECT_FALSE(intersect_plane(grazing, glm::dvec3(0.0), {0.0, 0.0, 1.0}).has_value());
}

TEST(Picking, ClosestPointOnAnAxis) {
  Ray ray;
  ray.origin = {2.0, 5.0, 3.0};
  ray.direction = {0.0, -1.0, 0.0};
  // The x axis through (0, 0, 3): the ray crosses it at x = 2.
  const auto p = closest_on_line(ray, {0.0, 0.0, 3.0}, {1.0, 0.0, 0.0});
  ASSERT_TRUE(p.has_value());
  expect_near(*p, {2.0, 0.0, 3.0});
  // Skew lines: the axis point is the foot of the common perpendicular.
  const auto q = closest_on_line(ray, {0.0, 0.0, 0.0}, {1.0, 0.0, 0.0});
  ASSERT_TRUE(q.has_value());
  expect_near(*q, {2.0, 0.0, 0.0});
  // Looking along the axis: no single closest point.
  EXPECT_FALSE(closest_on_line(ray, {0.0, 0.0, 0.0}, {0.0, 1.0, 0.0}).has_value());
}

TEST(Picking, DistanceToASegment) {
  EXPECT_NEAR(distance_to_segment({5.0, 3.0}, {0.0, 0.0}, {10.0, 0.0}), 3.0, kTolerance);
  EXPECT_NEAR(distance_to_segment({-3.0, 4.0}, {0.0, 0.0}, {10.0, 0.0}), 5.0, kTolerance);  // past the end
  EXPECT_NEAR(distance_to_segment({1.0, 1.0}, {0.0, 0.0}, {0.0, 0.0}), std::sqrt(2.0), kTolerance);
}

TEST(Picking, SnappingRoundsOnlyTheMaskedCoordinates) {
  expect_near(snap_to_grid({0.26, -0.74, 1.12}, 0.25), {0.25, -0.75, 1.0});
  expect_near(snap_to_grid({0.26, -0.74, 1.12}, 0.25, {true, false, false}), {0.25, -0.74, 1.12});
  const glm::dvec3 small = snap_to_grid({-0.1, 0.0, 0.0}, 0.5);
  EXPECT_FALSE(std::signbit(small.x)) << "no -0 written to the file";
  expect_near(snap_to_grid({0.3, 0.3, 0.3}, 0.0), {0.3, 0.3, 0.3});  // no grid: unchanged
}

}  // namespace
}  // namespace sweep::render
