#include "editor/point_drag.hpp"

namespace sweep::editor {
namespace {

/// A 2D point: on the xy-plane, along x or y only (keeping the other coordinate).
std::optional<glm::dvec3> planar_target(const Ray& ray, const PointDragInput& input, glm::bvec3& snap_mask) {
  if (input.axis == 2) return std::nullopt;  // a 2D point has no z to move along
  std::optional<glm::dvec3> hit = intersect_plane(ray, glm::dvec3(0.0), {0.0, 0.0, 1.0});
  if (!hit) return std::nullopt;
  hit->z = 0.0;
  if (input.axis == 0) hit->y = input.start.y;
  if (input.axis == 1) hit->x = input.start.x;
  snap_mask = {input.axis != 1, input.axis != 0, false};
  return hit;
}

}  // namespace

std::optional<glm::dvec3> drag_target(const Ray& ray, const PointDragInput& input) {
  glm::bvec3 snap_mask(true);
  std::optional<glm::dvec3> hit;
  if (input.planar) {
    hit = planar_target(ray, input, snap_mask);
  } else if (input.axis >= 0 && input.axis < 3) {
    glm::dvec3 direction(0.0);
    direction[input.axis] = 1.0;
    hit = closest_on_line(ray, input.start, direction);
    snap_mask = {input.axis == 0, input.axis == 1, input.axis == 2};
  } else {
    hit = intersect_plane(ray, input.start, input.view_forward);
  }
  if (hit && input.snap > 0.0) hit = snap_to_grid(*hit, input.snap, snap_mask);
  return hit;
}

std::optional<glm::dvec3> grip_target(const ScreenMapping& mapping, const HandleGrip& grip, const glm::dvec2& pointer,
                                      const PointDragInput& input) {
  // The ray through the handle's centre meets the drag plane at the point only up to rounding,
  // so a press and release in place would write that rounding into the point.
  if (pointer == grip.pressed) return input.start;
  return drag_target(pointer_ray(mapping, pointer + grip.offset), input);
}

}  // namespace sweep::editor
