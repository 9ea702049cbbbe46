#include "render/camera.hpp"

#include "base/precondition.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace sweep::render {
namespace {

bool is_finite(const glm::dvec3& p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

/// A point in arcball coordinates lifted onto the unit sphere (or the rim outside it).
glm::dvec3 on_sphere(const glm::dvec2& p) {
  const double r2 = glm::dot(p, p);
  if (r2 <= 1.0) return {p.x, p.y, std::sqrt(1.0 - r2)};
  return glm::dvec3(p / std::sqrt(r2), 0.0);
}

}  // namespace

void Bounds::add(const glm::dvec3& point) {
  min = glm::min(min, point);
  max = glm::max(max, point);
}

void Bounds::add(const Bounds& other) {
  if (other.empty()) return;
  add(other.min);
  add(other.max);
}

glm::dvec3 Bounds::center() const {
  return empty() ? glm::dvec3(0.0) : 0.5 * (min + max);
}

double Bounds::radius() const {
  return empty() ? 0.0 : 0.5 * glm::length(max - min);
}

Bounds scene_bounds(const Scene& scene, const std::vector<bool>& visible) {
  Bounds bounds;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (!visible.empty() && (i >= visible.size() || !visible[i])) continue;
    const EvaluatedObject& object = scene.objects[i];
    for (const Frame& frame : object.curve.frames) {
      if (is_finite(frame.V)) bounds.add(frame.V);
    }
    for (const glm::vec3& p : object.mesh.positions) {
      const glm::dvec3 point(p);
      if (is_finite(point)) bounds.add(point);
    }
  }
  return bounds;
}

void Camera::set_yaw_pitch(double yaw_degrees, double pitch_degrees) {
  orientation = glm::angleAxis(glm::radians(yaw_degrees), glm::dvec3(0.0, 1.0, 0.0)) *
                glm::angleAxis(glm::radians(-pitch_degrees), glm::dvec3(1.0, 0.0, 0.0));
}

void Camera::set_view(ViewPreset preset) {
  switch (preset) {
    case ViewPreset::Front:
      set_yaw_pitch(0.0, 0.0);
      break;
    case ViewPreset::Top:
      set_yaw_pitch(0.0, 90.0);
      break;
    case ViewPreset::Side:
      set_yaw_pitch(90.0, 0.0);
      break;
  }
}

void Camera::frame(const Bounds& bounds, double aspect, double height_share) {
  SWEEP_EXPECTS(height_share > 0.0 && height_share <= 1.0, "height_share is in (0, 1]");
  double radius = bounds.radius();
  if (!(radius > 0.0) || !std::isfinite(radius)) radius = 1.0;
  target = bounds.center();
  scene_radius = radius;
  // The sphere fits when its tangent cone fits the narrower of the two fields of view.
  const double tan_half_vertical = std::tan(0.5 * vertical_fov);
  const double half_angle = std::atan(tan_half_vertical * std::min(height_share, std::max(aspect, 1e-6)));
  constexpr double kMargin = 1.05;
  distance = kMargin * radius / std::sin(half_angle);
}

void Camera::reset(const Bounds& bounds, double aspect, double height_share) {
  set_yaw_pitch(kDefaultYaw, kDefaultPitch);
  frame(bounds, aspect, height_share);
}

void Camera::arcball_rotate(const glm::dvec2& from, const glm::dvec2& to) {
  const glm::dvec3 a = on_sphere(from);
  const glm::dvec3 b = on_sphere(to);
  const double cosine = glm::dot(a, b);
  if (cosine > 1.0 - 1e-12) return;  // no movement
  // Quaternion turning a onto b by the angle between them (half-angle form; stable unless
  // a = -b, which a drag cannot produce in one step).
  const glm::dvec3 axis = glm::cross(a, b);
  const glm::dquat turn = glm::normalize(glm::dquat(1.0 + cosine, axis.x, axis.y, axis.z));
  // Turning the scene by `turn` in camera space is turning the camera the other way.
  orientation = glm::normalize(orientation * glm::conjugate(turn));
}

void Camera::zoom(double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor)) return;
  distance = std::clamp(distance * factor, 1e-6 * scene_radius, 1e3 * scene_radius + 1e3);
}

void Camera::pan(const glm::dvec2& delta) {
  // One arcball unit spans half the smaller side of the viewport; at the target's depth that
  // is half_height_at_target() for a landscape viewport. Portrait viewports pan a bit slower,
  // which nobody notices.
  const double scale = half_height_at_target();
  target -= (right() * delta.x + up() * delta.y) * scale;
}

glm::dvec3 Camera::eye() const {
  return target + orientation * glm::dvec3(0.0, 0.0, distance);
}
glm::dvec3 Camera::right() const {
  return orientation * glm::dvec3(1.0, 0.0, 0.0);
}
glm::dvec3 Camera::up() const {
  return orientation * glm::dvec3(0.0, 1.0, 0.0);
}
glm::dvec3 Camera::forward() const {
  return orientation * glm::dvec3(0.0, 0.0, -1.0);
}

glm::dmat4 Camera::view_matrix() const {
  // Inverse of the camera's placement: rotate by the inverse orientation about the eye.
  const glm::dmat4 rotation = glm::mat4_cast(glm::conjugate(orientation));
  return glm::translate(rotation, -eye());
}

double Camera::half_height_at_target() const {
  return distance * std::tan(0.5 * vertical_fov);
}

glm::dmat4 Camera::projection_matrix(double aspect) const {
  aspect = std::max(aspect, 1e-6);
  const double depth = 3.0 * std::max(scene_radius, 1e-9);
  const glm::dmat4 shift = glm::translate(glm::dmat4(1.0), glm::dvec3(lens_shift, 0.0));
  if (projection == Projection::Orthographic) {
    const double half_height = half_height_at_target();
    const double half_width = half_height * aspect;
    return shift * glm::ortho(-half_width, half_width, -half_height, half_height, distance - depth, distance + depth);
  }
  const double near_plane = std::max(distance - depth, distance * 1e-3);
  const double far_plane = distance + depth;
  return shift * glm::perspective(vertical_fov, aspect, near_plane, far_plane);
}

void Camera::look_at(const glm::dvec3& eye_position, const glm::dvec3& look_target, const glm::dvec3& up_hint) {
  const glm::dvec3 back = glm::normalize(eye_position - look_target);
  const glm::dvec3 right_axis = glm::normalize(glm::cross(up_hint, back));
  const glm::dvec3 up_axis = glm::cross(back, right_axis);
  orientation = glm::normalize(glm::quat_cast(glm::dmat3(right_axis, up_axis, back)));
  target = look_target;
  distance = glm::length(eye_position - look_target);
}

void ride_camera(Camera& camera, const Frame& frame, const RiderSize& size, RideView view) {
  SWEEP_EXPECTS(size.radius > 0.0, "ride_camera: size.radius > 0");
  const double r = size.radius;
  if (view == RideView::Chase) {
    const double height = size.followed ? std::max(2.4 * r, size.top + 1.5 * r) : 1.2 * r;
    const double ahead = size.followed ? 4.0 * r : 2.0 * r;
    camera.look_at(frame.V - 3.0 * r * frame.T + height * frame.B, frame.V + ahead * frame.T, frame.B);
  } else {
    const glm::dvec3 eye = frame.V + (size.top + 0.1 * r) * frame.B;
    camera.look_at(eye, eye + 2.0 * r * frame.T, frame.B);
  }
  camera.lens_shift = glm::dvec2(0.0);
}

glm::dvec2 arcball_point(const glm::dvec2& pixel, const glm::dvec2& size) {
  const double half = 0.5 * std::max(std::min(size.x, size.y), 1.0);
  return {(pixel.x - 0.5 * size.x) / half, (0.5 * size.y - pixel.y) / half};
}

}  // namespace sweep::render
