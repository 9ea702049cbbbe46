#pragma once
// Screen-space picking and drag maths for the editor: projecting world points to window
// pixels, rays through the pointer, and the planes and lines handles are dragged along.
// Plain GLM, no GL, so it is unit-tested without a context.

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <optional>

namespace sweep::editor {

/// How world points land on a window: the camera's view and projection for the framebuffer's
/// aspect, and the window's size in the units pointer positions come in (origin top left).
struct ScreenMapping {
  glm::dmat4 view_projection{1.0};
  glm::dvec2 window_size{1.0};
};

/// The mapping of a camera whose projection * view matrix is `view_projection` (for the
/// framebuffer's aspect, as the renderer uses it) drawn over a whole window of `window_size`.
ScreenMapping screen_mapping(const glm::dmat4& view_projection, const glm::dvec2& window_size);

/// Window position of a world point; nullopt when it is behind the eye or not finite.
std::optional<glm::dvec2> to_screen(const ScreenMapping& mapping, const glm::dvec3& world);

/// A ray in world space; direction is unit length.
struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};
};

/// The ray of world points that land on window position `pixel` (from the near plane away
/// from the eye). Works for perspective and orthographic cameras.
Ray pointer_ray(const ScreenMapping& mapping, const glm::dvec2& pixel);

/// Where the ray meets the plane through `point` with normal `normal`; nullopt when it runs
/// (nearly) parallel to the plane, which would throw the hit towards infinity, or when the
/// plane lies behind the ray's origin (a pointer above the horizon of the xy-plane).
std::optional<glm::dvec3> intersect_plane(const Ray& ray, const glm::dvec3& point, const glm::dvec3& normal);

/// The point of the line through `point` along `axis` (unit) closest to the ray; nullopt when
/// the ray runs (nearly) along the line.
std::optional<glm::dvec3> closest_on_line(const Ray& ray, const glm::dvec3& point, const glm::dvec3& axis);

/// Distance in the plane from `p` to the segment from `a` to `b`.
double distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b);

/// Rounds each coordinate whose `mask` entry is true to the nearest multiple of `grid` (> 0).
glm::dvec3 snap_to_grid(const glm::dvec3& p, double grid, const glm::bvec3& mask = glm::bvec3(true));

}  // namespace sweep::editor
