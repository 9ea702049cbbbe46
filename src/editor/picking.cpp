#include "editor/picking.hpp"

#include <glm/geometric.hpp>
#include <glm/mat4x4.hpp>

#include <cmath>

namespace sweep::editor {
namespace {

bool finite(const glm::dvec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

/// Window pixel to normalized device coordinates (x right, y up, -1..1).
glm::dvec2 to_ndc(const ScreenMapping& mapping, const glm::dvec2& pixel) {
  return {2.0 * pixel.x / mapping.window_size.x - 1.0, 1.0 - 2.0 * pixel.y / mapping.window_size.y};
}

glm::dvec3 unproject(const glm::dmat4& inverse, const glm::dvec3& ndc) {
  const glm::dvec4 p = inverse * glm::dvec4(ndc, 1.0);
  return glm::dvec3(p) / p.w;
}

}  // namespace

ScreenMapping screen_mapping(const glm::dmat4& view_projection, const glm::dvec2& window_size) {
  ScreenMapping mapping;
  mapping.view_projection = view_projection;
  mapping.window_size = glm::max(window_size, glm::dvec2(1.0));
  return mapping;
}

std::optional<glm::dvec2> to_screen(const ScreenMapping& mapping, const glm::dvec3& world) {
  if (!finite(world)) return std::nullopt;
  const glm::dvec4 clip = mapping.view_projection * glm::dvec4(world, 1.0);
  if (!(clip.w > 0.0)) return std::nullopt;  // behind the eye (perspective); orthographic w is 1
  const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
  return glm::dvec2((ndc.x + 1.0) * 0.5 * mapping.window_size.x, (1.0 - ndc.y) * 0.5 * mapping.window_size.y);
}

Ray pointer_ray(const ScreenMapping& mapping, const glm::dvec2& pixel) {
  const glm::dmat4 inverse = glm::inverse(mapping.view_projection);
  const glm::dvec2 ndc = to_ndc(mapping, pixel);
  const glm::dvec3 near_point = unproject(inverse, {ndc, -1.0});
  const glm::dvec3 far_point = unproject(inverse, {ndc, 1.0});
  Ray ray;
  ray.origin = near_point;
  const glm::dvec3 d = far_point - near_point;
  const double length = glm::length(d);
  if (length > 0.0 && std::isfinite(length)) ray.direction = d / length;
  return ray;
}

std::optional<glm::dvec3> intersect_plane(const Ray& ray, const glm::dvec3& point, const glm::dvec3& normal) {
  const double n_length = glm::length(normal);
  if (!(n_length > 0.0)) return std::nullopt;
  const glm::dvec3 n = normal / n_length;
  const double facing = glm::dot(ray.direction, n);
  constexpr double kGrazing = 1e-4;  // cosine below which the hit is too far to be useful
  if (std::abs(facing) < kGrazing) return std::nullopt;
  const double t = glm::dot(point - ray.origin, n) / facing;
  if (!(t >= 0.0)) return std::nullopt;  // the plane is behind the ray: nothing under the pointer
  const glm::dvec3 hit = ray.origin + t * ray.direction;
  if (!finite(hit)) return std::nullopt;
  return hit;
}

std::optional<glm::dvec3> closest_on_line(const Ray& ray, const glm::dvec3& point, const glm::dvec3& axis) {
  // Closest points of two lines: solve for s on the axis (point + s axis) and t on the ray.
  const glm::dvec3 w = point - ray.origin;
  const double b = glm::dot(axis, ray.direction);
  const double denominator = 1.0 - b * b;  // both unit: |axis x direction|^2
  if (denominator < 1e-8) return std::nullopt;
  const double s = (b * glm::dot(ray.direction, w) - glm::dot(axis, w)) / denominator;
  const glm::dvec3 result = point + s * axis;
  if (!finite(result)) return std::nullopt;
  return result;
}

double distance_to_segment(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b) {
  const glm::dvec2 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  const double t = length2 > 0.0 ? glm::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

glm::dvec3 snap_to_grid(const glm::dvec3& p, double grid, const glm::bvec3& mask) {
  glm::dvec3 out = p;
  if (!(grid > 0.0)) return out;
  for (int i = 0; i < 3; ++i) {
    if (mask[i]) out[i] = std::round(p[i] / grid) * grid + 0.0;  // + 0.0 turns -0 into 0 for the file
  }
  return out;
}

}  // namespace sweep::editor
