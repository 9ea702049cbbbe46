// The circular helix V(theta) = (a cos theta, a sin theta, c theta), c = pitch / (2 pi): its
// derivative (-a sin theta, a cos theta, c) never vanishes, its curvature a / (a^2 + c^2) and
// torsion c / (a^2 + c^2) are constant.
#include "geometry/curves/helix.hpp"

#include "base/precondition.hpp"
#include "geometry/curves/curve_basis.hpp"
#include "geometry/sample_limits.hpp"
#include "geometry/unit_vector.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sweep {

bool helix_closes(double pitch, double turns) {
  return pitch == 0.0 && std::floor(turns) == turns;
}

std::int64_t helix_sample_count(int steps, double turns) {
  const double segments = std::ceil(double(steps) * turns);
  // Exact up to 4e18 (the reader caps STEPS at 1e5 and TURNS at 1e12, so every file's count is);
  // past it a count beyond any cap: the caller compares with limits::kMaxCurveSamples.
  constexpr std::int64_t kBeyond = 4'000'000'000'000'000'000;
  return segments < static_cast<double>(kBeyond) ? static_cast<std::int64_t>(segments) + 1 : kBeyond;
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
  curve.closed = helix_closes(pitch, turns);
  if (curve.closed) curve.frames.back() = curve.frames.front();
  compute_frames(curve.frames, false, options);
  if (curve.closed && options.close_seam) curve.seam_angle = close_frames(curve.frames, options.seam_spread);
  return curve;
}

namespace {

PieceDerivatives helix_point(const CurveDescriptor& c, double u) {  // u in turns
  const double turn = 2.0 * std::numbers::pi;
  const double angle = turn * u;
  const double cos = std::cos(angle), sin = std::sin(angle);
  return {glm::dvec3(c.radius * cos, c.radius * sin, c.pitch * u),
          glm::dvec3(-turn * c.radius * sin, turn * c.radius * cos, c.pitch),
          -turn * turn * glm::dvec3(c.radius * cos, c.radius * sin, 0.0), glm::dvec3(0.0)};
}

CurveSamples evaluate(const CurveDescriptor& c, const FrameOptions& options, const AdaptiveTolerance& tolerance) {
  // Seen along +z a helix is a circle; its chords stray from it as far as the circle's do.
  const int n = tolerance.adaptive() ? circle_segments(c.radius + tolerance.offset, tolerance.distance) : c.steps;
  const bool capped = helix_sample_count(n, c.turns) > limits::kMaxCurveSamples;
  CurveSamples samples = evaluate_helix(c.radius, c.pitch, c.turns, capped ? c.steps : n, options);
  samples.capped = capped;
  return samples;
}

CurveSamples evaluate_at(const CurveDescriptor& c, std::span<const double> parameters, const FrameOptions& options) {
  return sample_analytic(c, parameters, options, &helix_point);
}

glm::dvec3 position(const CurveDescriptor& c, double u) {
  return helix_point(c, u).position;
}

void exact_box(const CurveDescriptor& c, glm::dvec3& lo, glm::dvec3& hi) {
  lo = glm::dvec3(-c.radius, -c.radius, std::min(0.0, c.pitch * c.turns));
  hi = glm::dvec3(c.radius, c.radius, std::max(0.0, c.pitch * c.turns));
}

bool closed(const CurveDescriptor& c) {
  return helix_closes(c.pitch, c.turns);
}

}  // namespace

const CurveBasis kHelixBasis{"helix",    false,   &evaluate,    &evaluate_at, &position,
                             &exact_box, &closed, &helix_point, nullptr,      false};

}  // namespace sweep
