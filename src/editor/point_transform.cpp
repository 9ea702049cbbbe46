#include "editor/point_transform.hpp"

#include "base/precondition.hpp"
#include "editor/point_drag.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>

namespace sweep::editor {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Closer to the centre's screen position than this many pixels the pointer's angle is noise and
// its distance too small to divide by.
constexpr double kMinScreenRadius = 2.0;
constexpr std::size_t kMaxTyped = 24;        // more digits than a double holds
constexpr const char* kDegree = "\xC2\xB0";  // the degree sign in UTF-8, as the status bar draws it
constexpr const char* kAxisNames[] = {"x", "y", "z"};

struct CosSin {
  double cos = 1.0;
  double sin = 0.0;
};

/// cos and sin of `degrees`, exact for multiples of 90 degrees so that quarter turns permute and
/// negate coordinates without rounding (std::cos(pi / 2) is 6e-17, not 0).
CosSin cos_sin(double degrees) {
  const double reduced = std::fmod(degrees, 360.0);  // exact
  const double quarters = std::round(reduced / 90.0);
  if (quarters * 90.0 == reduced) {
    static constexpr CosSin kQuarterTurns[] = {{1.0, 0.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, -1.0}};
    return kQuarterTurns[(static_cast<int>(quarters) % 4 + 4) % 4];
  }
  const double radians = reduced * (kPi / 180.0);
  return {std::cos(radians), std::sin(radians)};
}

/// `v` turned by the angle of `turn` about unit axis `u` (Rodrigues' rotation formula).
glm::dvec3 rotate_about(const glm::dvec3& v, const glm::dvec3& u, const CosSin& turn) {
  return v * turn.cos + glm::cross(u, v) * turn.sin + u * (glm::dot(u, v) * (1.0 - turn.cos));
}

/// The angle of `d` (a window offset, y down) anticlockwise as seen on the screen.
double screen_angle(const glm::dvec2& d) {
  return std::atan2(-d.y, d.x);
}

/// `angle` moved by a multiple of 2 pi into (-pi, pi].
double wrap_angle(double angle) {
  while (angle > kPi) angle -= 2.0 * kPi;
  while (angle <= -kPi) angle += 2.0 * kPi;
  return angle;
}

std::string number_text(double value) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", value + 0.0);  // + 0.0 shows -0 as 0
  return text;
}

}  // namespace

TransformStart transform_start(TransformMode mode, std::span<const glm::dvec3> points, const PointSelection& selection,
                               bool planar) {
  TransformStart start;
  start.mode = mode;
  start.centre = centre(points, selection);  // checks the preconditions
  start.indices = selection.points();
  for (int i : start.indices) start.positions.push_back(points[std::size_t(i)]);
  start.planar = planar;
  return start;
}

void PointTransform::start(TransformStart start) {
  SWEEP_EXPECTS(start.indices.size() == start.positions.size(), "one start position per point");
  SWEEP_EXPECTS(glm::length(start.view_forward) > 0.0, "the view direction is not zero");
  start_ = std::move(start);
  active_ = true;
  axis_ = -1;
  typed_.clear();
  pointer_ = start_.pointer;
  centre_on_screen_ = to_screen(start_.mapping, start_.centre);
  pointer_offset_ = glm::dvec3(0.0);
  pointer_turn_ = 0.0;
  last_angle_.reset();
  if (centre_on_screen_ && glm::length(pointer_ - *centre_on_screen_) >= kMinScreenRadius) {
    last_angle_ = screen_angle(pointer_ - *centre_on_screen_);
  }
  pointer_factor_ = 1.0;
}

std::vector<PointMove> PointTransform::update(const glm::dvec2& pointer) {
  SWEEP_EXPECTS(active_, "a transform is in progress");
  update_pointer(pointer);
  return moves();
}

void PointTransform::update_pointer(const glm::dvec2& pointer) {
  pointer_ = pointer;
  if (start_.mode == TransformMode::Grab) {
    PointDragInput input;
    input.start = start_.anchor.value_or(start_.centre);
    input.planar = start_.planar;
    input.axis = axis_;
    input.view_forward = start_.view_forward;
    if (pointer == start_.pointer) {
      pointer_offset_ = glm::dvec3(0.0);  // exactly: a grab that comes back puts the points back
      return;
    }
    const auto from = drag_target(pointer_ray(start_.mapping, start_.pointer), input);
    const auto to = drag_target(pointer_ray(start_.mapping, pointer), input);
    if (from && to) pointer_offset_ = *to - *from;
    if (start_.anchor && start_.grid > 0.0) {
      glm::bvec3 mask(axis_ < 0);
      if (axis_ >= 0) mask[axis_] = true;
      if (start_.planar) mask.z = false;
      pointer_offset_ = snap_to_grid(*start_.anchor + pointer_offset_, start_.grid, mask) - *start_.anchor;
    }
    return;
  }
  if (!centre_on_screen_) return;  // the centre is behind the eye: only typed numbers work
  const glm::dvec2 d = pointer - *centre_on_screen_;
  const double radius = glm::length(d);
  if (radius < kMinScreenRadius) return;
  if (start_.mode == TransformMode::Rotate) {
    // Unwrapped, so that going round the centre more than half a turn keeps turning.
    const double angle = screen_angle(d);
    if (last_angle_) pointer_turn_ += wrap_angle(angle - *last_angle_);
    last_angle_ = angle;
    return;
  }
  const double start_radius = glm::length(start_.pointer - *centre_on_screen_);
  if (start_radius >= kMinScreenRadius) pointer_factor_ = radius / start_radius;
}

std::vector<PointMove> PointTransform::moves() const {
  SWEEP_EXPECTS(active_, "a transform is in progress");
  std::vector<PointMove> result;
  result.reserve(start_.indices.size());
  for (std::size_t i = 0; i < start_.indices.size(); ++i) {
    result.push_back({start_.indices[i], transformed(start_.positions[i])});
  }
  return result;
}

bool PointTransform::toggle_axis(int axis) {
  SWEEP_EXPECTS(axis >= 0 && axis <= 2, "the axis is x, y or z");
  if (start_.planar && axis == 2) return false;
  axis_ = axis_ == axis ? -1 : axis;
  if (active_ && start_.mode == TransformMode::Grab) update_pointer(pointer_);  // the offset depends on the axis
  return true;
}

bool PointTransform::type(char key) {
  if (key == '-') {
    if (!typed_.empty() && typed_.front() == '-') {
      typed_.erase(0, 1);
    } else {
      typed_.insert(0, 1, '-');
    }
    return true;
  }
  const bool digit = std::isdigit(static_cast<unsigned char>(key)) != 0;
  if (!digit && key != '.') return false;
  if (key == '.' && typed_.find('.') != std::string::npos) return false;
  if (typed_.size() >= kMaxTyped) return false;
  typed_.push_back(key);
  return true;
}

void PointTransform::backspace() {
  if (!typed_.empty()) typed_.pop_back();
}

std::vector<PointMove> PointTransform::confirm() {
  std::vector<PointMove> result = moves();
  active_ = false;
  return result;
}

std::vector<PointMove> PointTransform::cancel() {
  SWEEP_EXPECTS(active_, "a transform is in progress");
  std::vector<PointMove> result;
  result.reserve(start_.indices.size());
  for (std::size_t i = 0; i < start_.indices.size(); ++i) result.push_back({start_.indices[i], start_.positions[i]});
  active_ = false;
  return result;
}

std::optional<double> PointTransform::typed_value() const {
  if (std::none_of(typed_.begin(), typed_.end(), [](char c) { return std::isdigit(static_cast<unsigned char>(c)); })) {
    return std::nullopt;
  }
  double value = 0.0;
  const auto [end, error] = std::from_chars(typed_.data(), typed_.data() + typed_.size(), value);
  if (error != std::errc()) return std::nullopt;  // beyond the range of a double
  return value;
}

int PointTransform::rotation_axis_index() const {
  if (axis_ >= 0) return axis_;
  return start_.planar ? 2 : -1;
}

glm::dvec3 PointTransform::rotation_axis() const {
  const int k = rotation_axis_index();
  if (k < 0) return -glm::normalize(start_.view_forward);
  glm::dvec3 u(0.0);
  u[k] = 1.0;
  return u;
}

glm::dvec3 PointTransform::grab_offset() const {
  const std::optional<double> value = typed_value();
  if (!value) return pointer_offset_;
  glm::dvec3 offset(0.0);
  offset[std::max(axis_, 0)] = *value;
  return offset;
}

double PointTransform::rotation_degrees() const {
  if (const std::optional<double> value = typed_value()) return *value;
  // The pointer turns anticlockwise on screen, which is right-handed about an axis pointing at
  // the viewer and left-handed about one pointing away.
  const double facing = glm::dot(rotation_axis(), -start_.view_forward);
  return (facing < 0.0 ? -pointer_turn_ : pointer_turn_) * (180.0 / kPi);
}

double PointTransform::scale_factor() const {
  return typed_value().value_or(pointer_factor_);
}

glm::dvec3 PointTransform::transformed(const glm::dvec3& p) const {
  const glm::dvec3& c = start_.centre;
  switch (start_.mode) {
    case TransformMode::Grab:
      return p + grab_offset();  // a zero component leaves its coordinate exactly
    case TransformMode::Rotate: {
      const CosSin turn = cos_sin(rotation_degrees());
      if (turn.cos == 1.0 && turn.sin == 0.0) return p;
      const int k = rotation_axis_index();
      glm::dvec3 out = c + rotate_about(p - c, rotation_axis(), turn);
      if (k >= 0) out[k] = p[k];  // the coordinate along the axis stays exactly
      return out;
    }
    case TransformMode::Scale: {
      const double factor = scale_factor();
      glm::dvec3 out = p;
      for (int i = 0; i < 3; ++i) {
        // Coordinates off the constraint axis, and all of them for a factor of 1, stay exactly.
        if ((axis_ < 0 || axis_ == i) && factor != 1.0) out[i] = c[i] + factor * (p[i] - c[i]);
      }
      return out;
    }
  }
  return p;
}

std::string PointTransform::status() const {
  if (!active_) return "";
  const auto shown = [&](double pointer_value) {
    return typed_.empty() ? number_text(pointer_value) : "[" + typed_ + "]";
  };
  switch (start_.mode) {
    case TransformMode::Grab: {
      const glm::dvec3 offset = grab_offset();
      if (axis_ >= 0 || !typed_.empty()) {
        const int k = std::max(axis_, 0);
        return std::string("Grab along ") + kAxisNames[k] + ": " + shown(offset[k]);
      }
      std::string text = "Grab " + number_text(offset.x) + ", " + number_text(offset.y);
      return start_.planar ? text : text + ", " + number_text(offset.z);
    }
    case TransformMode::Rotate: {
      const int k = rotation_axis_index();
      const std::string about = k >= 0 ? std::string(kAxisNames[k]) : "the view axis";
      return "Rotate " + shown(rotation_degrees()) + kDegree + " about " + about;
    }
    case TransformMode::Scale: {
      const std::string text = "Scale " + shown(scale_factor());
      return axis_ >= 0 ? text + " along " + kAxisNames[axis_] : text;
    }
  }
  return "";
}

}  // namespace sweep::editor
