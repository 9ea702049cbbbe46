// Circles, evaluated exactly (circle.hpp).
#include "geometry/curves/circle.hpp"

#include "base/precondition.hpp"
#include "geometry/curves/curve.hpp"
#include "geometry/sample_limits.hpp"

#include <cmath>
#include <numbers>

namespace sweep {

CurveSamples evaluate_circle(double radius, int steps) {
  SWEEP_EXPECTS(steps >= 1, "steps >= 1");
  SWEEP_EXPECTS(radius >= 0.0, "radius >= 0");
  CurveSamples curve;
  curve.planar = true;
  curve.frames.resize(static_cast<std::size_t>(steps) + 1);
  for (int i = 0; i < steps; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / steps;
    curve.parameters.push_back(static_cast<double>(i) / steps);
    Frame& f = curve.frames[static_cast<std::size_t>(i)];
    f.V = radius * glm::dvec3(std::cos(angle), std::sin(angle), 0.0);
    f.T = glm::dvec3(-std::sin(angle), std::cos(angle), 0.0);
  }
  curve.frames.back() = curve.frames.front();  // exactly closed
  curve.parameters.push_back(1.0);
  compute_frames(curve.frames, true, {});
  curve.closed = true;
  curve.steps = steps;
  curve.curvature.assign(curve.frames.size(), radius > 0.0 ? 1.0 / radius : 0.0);  // a point: none
  return curve;
}

namespace {

/// A point of the circle and its derivatives; a circle of radius 0 keeps the unit circle's
/// direction of travel as its first derivative (its tangent), so its frames still turn.
PieceDerivatives circle_point(const CurveDescriptor& c, double u) {
  const double turn = 2.0 * std::numbers::pi;
  const double angle = turn * u;
  const double cos = std::cos(angle), sin = std::sin(angle);
  const double speed = c.radius > 0.0 ? c.radius : 1.0;
  return {glm::dvec3(c.radius * cos, c.radius * sin, 0.0), glm::dvec3(-turn * speed * sin, turn * speed * cos, 0.0),
          -turn * turn * glm::dvec3(c.radius * cos, c.radius * sin, 0.0), glm::dvec3(0.0)};
}

CurveSamples evaluate(const CurveDescriptor& c, const FrameOptions&, const AdaptiveTolerance& tolerance) {
  // A circle of radius 0 has size 0: adaptive sampling takes its STEPS.
  const bool adaptive = tolerance.adaptive() && c.radius > 0.0;
  const int n = adaptive ? circle_segments(c.radius + tolerance.offset, tolerance.distance) : c.steps;
  const bool capped = n >= limits::kMaxCurveSamples;
  CurveSamples samples = evaluate_circle(c.radius, capped ? c.steps : n);
  samples.capped = capped;
  return samples;
}

CurveSamples evaluate_at(const CurveDescriptor& c, std::span<const double> parameters, const FrameOptions& options) {
  return sample_analytic(c, parameters, options, &circle_point);
}

glm::dvec3 position(const CurveDescriptor& c, double u) {
  return circle_point(c, u).position;
}

void exact_box(const CurveDescriptor& c, glm::dvec3& lo, glm::dvec3& hi) {
  lo = glm::dvec3(-c.radius, -c.radius, 0.0);
  hi = -lo;
}

bool closed(const CurveDescriptor&) {
  return true;
}

}  // namespace

const CurveBasis kCircleBasis{"circle",   false,   &evaluate,     &evaluate_at, &position,
                              &exact_box, &closed, &circle_point, nullptr,      false};

}  // namespace sweep
