// The circular helix V(theta) = (a cos theta, a sin theta, c theta), c = pitch / (2 pi): its
// derivative (-a sin theta, a cos theta, c) never vanishes, its curvature a / (a^2 + c^2) and
// torsion c / (a^2 + c^2) are constant.
#include "geometry/helix.hpp"

#include "geometry/limits.hpp"
#include "geometry/precondition.hpp"
#include "geometry/unit_vector.hpp"

#include <cmath>
#include <numbers>

namespace sweep {

std::int64_t helix_sample_count(int steps, double turns) {
  const double segments = std::ceil(double(steps) * turns);
  // Beyond any cap: the caller compares with limits::kMaxCurveSamples.
  return segments < 1e15 ? static_cast<std::int64_t>(segments) + 1 : std::int64_t{1'000'000'000'000'000};
}

CurveSamples evaluate_helix(double radius, double pitch, double turns, int steps, const FrameOptions& options) {
  SWEEP_EXPECTS(radius >= limits::kMinRadius && radius <= limits::kMaxCoordinate,
                "radius in [limits::kMinRadius, limits::kMaxCoordinate]");
  SWEEP_EXPECTS(turns > 0.0, "turns > 0");
  SWEEP_EXPECTS(steps >= 1, "steps >= 1");
  SWEEP_EXPECTS(std::abs(pitch) <= limits::kMaxCoordinate, "|pitch| at most limits::kMaxCoordinate");
  SWEEP_EXPECTS(helix_sample_count(steps, turns) <= limits::kMaxCurveSamples,
                "the sample count within limits::kMaxCurveSamples");
  CurveSamples curve;
  curve.steps = steps;  // sample i is near turn i / steps
  const auto count = static_cast<std::size_t>(helix_sample_count(steps, turns));
  curve.frames.resize(count);
  curve.parameters.reserve(count);
  const double rise = pitch / (2.0 * std::numbers::pi);  // c: rise per radian
  for (std::size_t i = 0; i < count; ++i) {
    const double share = static_cast<double>(i) / static_cast<double>(count - 1);
    const double angle = 2.0 * std::numbers::pi * turns * share;
    curve.parameters.push_back(turns * share);
    Frame& f = curve.frames[i];
    f.V = glm::dvec3(radius * std::cos(angle), radius * std::sin(angle), pitch * turns * share);
    f.T = unit_vector(glm::dvec3(-radius * std::sin(angle), radius * std::cos(angle), rise));
  }
  // a / (a^2 + c^2) without squaring either (no overflow or underflow for any finite radii).
  const double h = std::hypot(radius, rise);
  curve.curvature.assign(count, radius / h / h);
  curve.closed = is_closed(curve.frames);  // only a flat helix of whole turns
  if (curve.closed) curve.frames.back() = curve.frames.front();
  compute_frames(curve.frames, false, options);
  if (curve.closed && options.close_seam) curve.seam_angle = close_frames(curve.frames);
  return curve;
}

}  // namespace sweep
