#pragma once
// Cameras for the picking and drag tests, made straight from GLM (the editor tests do not link
// the renderer, so render::Camera is not used): a perspective camera looking at the origin from
// an oblique eye, and an orthographic one looking down -z.
#include "editor/picking.hpp"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace sweep::editor::test {

inline const glm::dvec2 kWindow{800.0, 600.0};
inline const glm::dvec3 kEye{3.0, 2.0, 5.0};
inline const glm::dvec3 kTarget{0.0, 0.0, 0.0};

inline ScreenMapping perspective_mapping() {
  const glm::dmat4 view = glm::lookAt(kEye, kTarget, glm::dvec3(0.0, 1.0, 0.0));
  const glm::dmat4 projection = glm::perspective(glm::radians(45.0), kWindow.x / kWindow.y, 0.1, 100.0);
  return screen_mapping(projection * view, kWindow);
}

/// Looks down -z from (0, 0, 10) at an 8 x 6 box around the origin.
inline ScreenMapping ortho_mapping() {
  const glm::dmat4 view = glm::lookAt(glm::dvec3(0.0, 0.0, 10.0), kTarget, glm::dvec3(0.0, 1.0, 0.0));
  const glm::dmat4 projection = glm::ortho(-4.0, 4.0, -3.0, 3.0, 0.1, 100.0);
  return screen_mapping(projection * view, kWindow);
}

/// Distance from `p` to the (infinite) line of `ray`.
inline double distance_to_ray_line(const Ray& ray, const glm::dvec3& p) {
  return glm::length(glm::cross(p - ray.origin, ray.direction));
}

}  // namespace sweep::editor::test
