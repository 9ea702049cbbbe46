// The (P, Q) torus knot c(t) = (rho cos Pt, rho sin Pt, r sin Qt), rho = R + r cos Qt >= R - r > 0.
// Its derivative has the component P rho > 0 along the circle about +z, so it never vanishes.
#include "geometry/curves/torus_knot.hpp"

#include "base/precondition.hpp"
#include "geometry/sample_limits.hpp"
#include "geometry/unit_vector.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sweep {

KnotPoint knot_point(const TorusKnotShape& s, double t) {
  const double p = s.p, q = s.q, r = s.minor_radius;
  const double cp = std::cos(p * t), sp = std::sin(p * t), cq = std::cos(q * t), sq = std::sin(q * t);
  const double rho = s.major_radius + r * cq;
  const double drho = -r * q * sq;       // d rho / dt
  const double ddrho = -r * q * q * cq;  // d^2 rho / dt^2
  KnotPoint k;
  k.position = glm::dvec3(rho * cp, rho * sp, r * sq);
  k.d1 = glm::dvec3(drho * cp - p * rho * sp, drho * sp + p * rho * cp, r * q * cq);
  k.d2 = glm::dvec3(ddrho * cp - 2.0 * p * drho * sp - p * p * rho * cp,
                    ddrho * sp + 2.0 * p * drho * cp - p * p * rho * sp, -r * q * q * sq);
  return k;
}

namespace {

/// |c' x c''| / |c'|^3, each length divided first so no power overflows.
double curvature_of(const KnotPoint& k) {
  const double speed = vector_length(k.d1);
  return vector_length(glm::cross(k.d1 / speed, k.d2 / speed)) / speed;
}

}  // namespace

std::vector<double> torus_knot_parameters(const TorusKnotShape& shape, const AdaptiveTolerance& tolerance,
                                          std::size_t max_samples) {
  SWEEP_EXPECTS(tolerance.adaptive(), "tolerance.adaptive()");
  // Over a parameter step h the chord strays from the knot by about h^2 / 8 times the part of
  // c'' across the chord (exactly so for a circle), the tangent turns by w h with w = kappa |c'|,
  // and a tube point r away adds r (1 - cos(w h / 2)) <= r (w h)^2 / 8. Each step is the longest
  // whose largest rate over the step (5 points, with a 5 % margin) keeps the sum within D and the
  // turn within kMaxTurn: a step found from a longer window's rate is safe for its own window.
  const double full = 2.0 * std::numbers::pi;
  const auto allowed = [&](double t) {
    const KnotPoint k = knot_point(shape, t);
    const glm::dvec3 unit = unit_vector(k.d1);
    const double w = curvature_of(k) * vector_length(k.d1);
    const double rate = (vector_length(k.d2 - glm::dot(k.d2, unit) * unit) + tolerance.offset * w * w) / 8.0;
    return std::min(std::sqrt(tolerance.distance / (1.05 * rate)), kMaxTurn / (1.05 * w));
  };
  const auto allowed_over = [&](double t, double h) {
    double step = allowed(t);
    for (int i = 1; i <= 4; ++i) step = std::min(step, allowed(t + h * i / 4.0));
    return step;
  };
  std::vector<double> out{0.0};
  for (double t = 0.0; t < full;) {
    if (out.size() > max_samples) return {};
    const double guess = std::min(allowed(t), full - t);
    const double h = std::min(allowed_over(t, guess), guess);
    t = full - (t + h) <= 1e-12 * full ? full : t + h;
    out.push_back(t / full);
  }
  return out;
}

CurveSamples evaluate_torus_knot(const TorusKnotShape& shape, int steps, const FrameOptions& options) {
  SWEEP_EXPECTS(steps >= 1, "steps >= 1");
  SWEEP_EXPECTS(shape.p >= 1 && shape.q >= 1, "P, Q >= 1");
  SWEEP_EXPECTS(shape.minor_radius > 0.0 && shape.minor_radius < shape.major_radius &&
                    shape.major_radius <= limits::kMaxCoordinate,
                "0 < r < R <= limits::kMaxCoordinate");
  CurveSamples curve;
  curve.steps = steps;
  curve.closed = true;
  const auto count = static_cast<std::size_t>(steps) + 1;
  curve.frames.resize(count);
  curve.curvature.resize(count);
  for (std::size_t i = 0; i + 1 < count; ++i) {
    const KnotPoint k = knot_point(shape, 2.0 * std::numbers::pi * static_cast<double>(i) / steps);
    curve.parameters.push_back(static_cast<double>(i) / steps);
    curve.frames[i].V = k.position;
    curve.frames[i].T = unit_vector(k.d1);
    curve.curvature[i] = curvature_of(k);
  }
  curve.frames.back() = curve.frames.front();  // exactly closed, as evaluate_circle
  curve.curvature.back() = curve.curvature.front();
  curve.parameters.push_back(1.0);
  compute_frames(curve.frames, false, options);
  if (options.close_seam) curve.seam_angle = close_frames(curve.frames, options.seam_spread);
  return curve;
}

namespace {

TorusKnotShape shape_of(const CurveDescriptor& c) {
  return {c.knot_p, c.knot_q, c.major_radius, c.radius};
}

PieceDerivatives knot_derivatives(const CurveDescriptor& c, double u) {  // u in 0..1
  const double turn = 2.0 * std::numbers::pi;
  const KnotPoint k = knot_point(shape_of(c), turn * u);
  return {k.position, turn * k.d1, turn * turn * k.d2, glm::dvec3(0.0)};
}

CurveSamples evaluate_at(const CurveDescriptor& c, std::span<const double> parameters, const FrameOptions& options) {
  return sample_analytic(c, parameters, options, &knot_derivatives);
}

CurveSamples evaluate(const CurveDescriptor& c, const FrameOptions& options, const AdaptiveTolerance& tolerance) {
  if (!tolerance.adaptive()) return evaluate_torus_knot(shape_of(c), c.steps, options);
  const std::vector<double> at =
      torus_knot_parameters(shape_of(c), tolerance, static_cast<std::size_t>(limits::kMaxCurveSamples));
  if (!at.empty()) return evaluate_at(c, at, options);
  CurveSamples samples = evaluate_torus_knot(shape_of(c), c.steps, options);
  samples.capped = true;
  return samples;
}

glm::dvec3 position(const CurveDescriptor& c, double u) {
  return knot_derivatives(c, u).position;
}

void exact_box(const CurveDescriptor& c, glm::dvec3& lo, glm::dvec3& hi) {
  hi = glm::dvec3(c.major_radius + c.radius, c.major_radius + c.radius, c.radius);
  lo = -hi;
}

bool closed(const CurveDescriptor&) {
  return true;
}

}  // namespace

const CurveBasis kTorusKnotBasis{"torus knot", false,   &evaluate,         &evaluate_at, &position,
                                 &exact_box,   &closed, &knot_derivatives, nullptr,      false};

}  // namespace sweep
