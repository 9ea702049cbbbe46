// The (P, Q) torus knot c(t) = (rho cos Pt, rho sin Pt, r sin Qt), rho = R + r cos Qt >= R - r > 0.
// Its derivative has the component P rho > 0 along the circle about +z, so it never vanishes.
#include "core/torus_knot.hpp"

#include "core/unit_vector.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace sweep {
namespace {

struct KnotPoint {
  glm::dvec3 position;
  glm::dvec3 d1;  // dc/dt
  glm::dvec3 d2;  // d^2c/dt^2
};

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

/// |c' x c''| / |c'|^3, each length divided first so no power overflows.
double curvature_of(const KnotPoint& k) {
  const double speed = vector_length(k.d1);
  return vector_length(glm::cross(k.d1 / speed, k.d2 / speed)) / speed;
}

}  // namespace

CurveSamples evaluate_torus_knot(const TorusKnotShape& shape, int steps, const FrameOptions& options) {
  CurveSamples curve;
  curve.steps = steps;
  curve.closed = true;
  const auto count = static_cast<std::size_t>(steps) + 1;
  curve.frames.resize(count);
  curve.curvature.resize(count);
  for (std::size_t i = 0; i + 1 < count; ++i) {
    const KnotPoint k = knot_point(shape, 2.0 * std::numbers::pi * static_cast<double>(i) / steps);
    curve.frames[i].V = k.position;
    curve.frames[i].T = unit_vector(k.d1);
    curve.curvature[i] = curvature_of(k);
  }
  curve.frames.back() = curve.frames.front();  // exactly closed, as evaluate_circle
  curve.curvature.back() = curve.curvature.front();
  compute_frames(curve.frames, false, options);
  if (options.close_seam) curve.seam_angle = close_frames(curve.frames);
  return curve;
}

}  // namespace sweep
