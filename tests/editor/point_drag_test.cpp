// Where a dragged control point goes: 2D points stay on z = 0 under the pointer, 3D points move
// in the plane facing the camera, an axis constraint moves one coordinate only, and snapping
// rounds only what moved.
#include "editor/point_drag.hpp"

#include "support/screen_mapping_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace sweep::editor {
namespace {

using test::distance_to_ray_line;

const glm::dvec3 kForward = glm::normalize(test::kTarget - test::kEye);
const std::vector<glm::dvec2> kPixels = {{400.0, 300.0}, {250.0, 180.0}, {610.0, 420.0}, {90.0, 500.0}};

/// True when `value` is a whole multiple of `step` (up to rounding).
bool on_grid(double value, double step) {
  return std::abs(value / step - std::round(value / step)) < 1e-9;
}

TEST(PointDrag, APlanarPointLandsOnTheXyPlaneUnderThePointer) {
  const ScreenMapping mapping = test::perspective_mapping();
  PointDragInput input;
  input.start = {0.3, -0.2, 0.0};
  input.planar = true;
  for (const glm::dvec2& pixel : kPixels) {
    const Ray ray = pointer_ray(mapping, pixel);
    const auto target = drag_target(ray, input);
    ASSERT_TRUE(target);
    EXPECT_EQ(target->z, 0.0);
    const auto back = to_screen(mapping, *target);
    ASSERT_TRUE(back);
    EXPECT_NEAR(back->x, pixel.x, 1e-6);
    EXPECT_NEAR(back->y, pixel.y, 1e-6);
  }
}

TEST(PointDrag, APlanarPointAlongAnAxisKeepsTheOtherCoordinate) {
  const ScreenMapping mapping = test::perspective_mapping();
  const Ray ray = pointer_ray(mapping, {250.0, 180.0});
  PointDragInput input;
  input.start = {0.3, -0.2, 0.0};
  input.planar = true;
  const auto free = drag_target(ray, input);
  ASSERT_TRUE(free);

  input.axis = 0;
  const auto along_x = drag_target(ray, input);
  ASSERT_TRUE(along_x);
  EXPECT_EQ(along_x->x, free->x) << "x follows the pointer on the plane";
  EXPECT_EQ(along_x->y, input.start.y);
  EXPECT_EQ(along_x->z, 0.0);

  input.axis = 1;
  const auto along_y = drag_target(ray, input);
  ASSERT_TRUE(along_y);
  EXPECT_EQ(along_y->x, input.start.x);
  EXPECT_EQ(along_y->y, free->y);
  EXPECT_EQ(along_y->z, 0.0);

  input.axis = 2;
  EXPECT_FALSE(drag_target(ray, input)) << "a 2D point has no z to move along";
}

TEST(PointDrag, APlanarPointSeenEdgeOnHasNoTarget) {
  // Looking along +y at the xy-plane: every ray runs in the plane.
  const Ray ray{{0.0, -5.0, 0.0}, {0.0, 1.0, 0.0}};
  PointDragInput input;
  input.planar = true;
  EXPECT_FALSE(drag_target(ray, input));
}

TEST(PointDrag, APlanarPointDraggedAboveTheHorizonHasNoTarget) {
  // A low camera looking along +y at the xy-plane's edge: near the top of the window the pointer
  // ray rises, so it meets the plane z = 0 only behind the eye.
  const glm::dmat4 view = glm::lookAt(glm::dvec3(0.0, -6.0, 1.0), test::kTarget, glm::dvec3(0.0, 0.0, 1.0));
  const glm::dmat4 projection = glm::perspective(glm::radians(45.0), test::kWindow.x / test::kWindow.y, 0.1, 100.0);
  const ScreenMapping mapping = screen_mapping(projection * view, test::kWindow);
  const Ray ray = pointer_ray(mapping, {400.0, 5.0});
  ASSERT_GT(ray.direction.z, 0.0) << "the ray rises away from the plane";
  PointDragInput input;
  input.planar = true;
  const auto target = drag_target(ray, input);
  // The plane is behind the ray: the point stays put rather than jumping behind the camera
  // (to a mirrored place no pixel shows).
  if (target) {
    ADD_FAILURE() << "target " << target->x << " " << target->y << " " << target->z << " is behind the eye ("
                  << (to_screen(mapping, *target) ? "on screen" : "no pixel shows it") << ")";
  }
}

TEST(PointDrag, AFreeDragOfA3dPointStaysInThePlaneFacingTheCamera) {
  const ScreenMapping mapping = test::perspective_mapping();
  PointDragInput input;
  input.start = {0.4, 0.7, -0.3};
  input.view_forward = kForward;
  for (const glm::dvec2& pixel : kPixels) {
    const Ray ray = pointer_ray(mapping, pixel);
    const auto target = drag_target(ray, input);
    ASSERT_TRUE(target);
    EXPECT_NEAR(glm::dot(*target - input.start, kForward), 0.0, 1e-9) << "in the plane through the start";
    EXPECT_LT(distance_to_ray_line(ray, *target), 1e-9) << "under the pointer";
  }
  // The start's own pixel gives the start back.
  const auto pixel = to_screen(mapping, input.start);
  ASSERT_TRUE(pixel);
  const auto same = drag_target(pointer_ray(mapping, *pixel), input);
  ASSERT_TRUE(same);
  EXPECT_LT(glm::length(*same - input.start), 1e-9);
}

TEST(PointDrag, AnAxisDragOfA3dPointMovesAlongThatAxisOnly) {
  const ScreenMapping mapping = test::perspective_mapping();
  PointDragInput input;
  input.start = {0.4, 0.7, -0.3};
  input.view_forward = kForward;
  const Ray ray = pointer_ray(mapping, {610.0, 420.0});
  for (int axis = 0; axis < 3; ++axis) {
    input.axis = axis;
    const auto target = drag_target(ray, input);
    ASSERT_TRUE(target) << "axis " << axis;
    for (int other = 0; other < 3; ++other) {
      if (other != axis) {
        EXPECT_EQ((*target)[other], input.start[other]) << "axis " << axis;
      }
    }
    EXPECT_NE((*target)[axis], input.start[axis]) << "the pointer moved off the start";
  }
  // A ray straight along the axis gives no target.
  input.axis = 2;
  EXPECT_FALSE(drag_target(Ray{{0.4, 0.7, 5.0}, {0.0, 0.0, -1.0}}, input));
}

TEST(PointDrag, SnappingRoundsOnlyTheMovedCoordinates) {
  const ScreenMapping mapping = test::perspective_mapping();
  const Ray ray = pointer_ray(mapping, {250.0, 180.0});
  PointDragInput input;
  input.start = {0.13, -0.27, 0.0};  // off the grid
  input.planar = true;
  input.snap = 0.25;

  const auto planar = drag_target(ray, input);
  ASSERT_TRUE(planar);
  EXPECT_TRUE(on_grid(planar->x, 0.25)) << planar->x;
  EXPECT_TRUE(on_grid(planar->y, 0.25)) << planar->y;
  EXPECT_EQ(planar->z, 0.0);

  input.axis = 0;
  const auto along_x = drag_target(ray, input);
  ASSERT_TRUE(along_x);
  EXPECT_TRUE(on_grid(along_x->x, 0.25)) << along_x->x;
  EXPECT_EQ(along_x->y, input.start.y) << "the kept coordinate is not snapped";

  input.start = {0.13, -0.27, 0.41};
  input.planar = false;
  input.view_forward = kForward;
  input.axis = 2;
  const auto along_z = drag_target(ray, input);
  ASSERT_TRUE(along_z);
  EXPECT_EQ(along_z->x, input.start.x);
  EXPECT_EQ(along_z->y, input.start.y);
  EXPECT_TRUE(on_grid(along_z->z, 0.25)) << along_z->z;

  input.axis = -1;
  const auto free = drag_target(ray, input);
  ASSERT_TRUE(free);
  for (int i = 0; i < 3; ++i) EXPECT_TRUE(on_grid((*free)[i], 0.25)) << i << ": " << (*free)[i];
}

/// A grip on the handle of `start`, pressed `off` window units from its centre.
HandleGrip grip_at(const ScreenMapping& mapping, const glm::dvec3& start, const glm::dvec2& off) {
  const auto centre = to_screen(mapping, start);
  EXPECT_TRUE(centre);
  return {*centre + off, -off};
}

TEST(PointDrag, APressAndReleaseInPlaceKeepsThePointToTheBit) {
  // -0.351882 is the coordinate a click turned into -0.3518820000000016 through the ray.
  const ScreenMapping mapping = test::perspective_mapping();
  PointDragInput input;
  input.start = {-0.351882, 0.716137, 0.243019};
  input.view_forward = kForward;
  for (const double snap : {0.0, 0.25}) {  // not even onto the grid: nothing moved
    input.snap = snap;
    for (int axis = -1; axis < 3; ++axis) {
      input.axis = axis;
      const HandleGrip grip = grip_at(mapping, input.start, {2.5, -1.25});
      const auto target = grip_target(mapping, grip, grip.pressed, input);
      ASSERT_TRUE(target);
      EXPECT_EQ(*target, input.start) << "axis " << axis << ", snap " << snap;
    }
  }
  input.start.z = 0.0;
  input.planar = true;
  input.axis = -1;
  const HandleGrip grip = grip_at(mapping, input.start, {-3.0, 4.0});
  EXPECT_EQ(grip_target(mapping, grip, grip.pressed, input), std::optional<glm::dvec3>(input.start));
}

TEST(PointDrag, AGripThatMovesFollowsThePointerAndComesBackExactly) {
  const ScreenMapping mapping = test::perspective_mapping();
  PointDragInput input;
  input.start = {0.3, -0.2, 0.0};
  input.planar = true;
  const HandleGrip grip = grip_at(mapping, input.start, {1.5, 0.5});
  const glm::dvec2 moved = grip.pressed + glm::dvec2(40.0, -25.0);
  EXPECT_EQ(grip_target(mapping, grip, moved, input), drag_target(pointer_ray(mapping, moved + grip.offset), input));
  EXPECT_NE(grip_target(mapping, grip, moved, input), std::optional<glm::dvec3>(input.start));
  EXPECT_EQ(grip_target(mapping, grip, grip.pressed, input), std::optional<glm::dvec3>(input.start));
}

}  // namespace
}  // namespace sweep::editor
