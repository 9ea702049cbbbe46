// Catmull-Rom segments with the knot spacing of
//   C. Yuksel, S. Schaefer, J. Keyser, "Parameterization and applications of Catmull-Rom curves",
//   Computer-Aided Design 43(7), 2011, pp. 747-755.
// Knots t_{i+1} - t_i = |P_{i+1} - P_i|^alpha: 0 uniform, 0.5 centripetal, 1 chordal. Only the
// centripetal spacing is proven never to form a cusp or a self-intersection within a segment.
//
// The segment P1 -> P2 (neighbours P0, P3, knots t0..t3) is the cubic Hermite whose derivatives
// with respect to t at P1 and P2 are those of the Barry-Goldman pyramid,
//   m1 = (P1 - P0)/(t1 - t0) - (P2 - P0)/(t2 - t0) + (P2 - P1)/(t2 - t1),
// which equals the knot-weighted mean of the chord velocities v_i = (P_{i+1} - P_i)/(t_{i+1} - t_i):
//   m1 = ((t2 - t1) v0 + (t1 - t0) v1) / (t2 - t0).
// That form divides only by a sum of intervals and by intervals of non-zero chords, so repeated
// points give no NaN: a zero chord has velocity 0, which is the limit of |dP|^(1 - alpha) for
// alpha < 1. Over the segment's own parameter u in [0, 1] the derivatives are (t2 - t1) m.
#include "geometry/curves/catmull_rom.hpp"

#include "base/precondition.hpp"
#include "geometry/curves/curve.hpp"
#include "geometry/curves/piece_sampling.hpp"
#include "geometry/unit_vector.hpp"

#include <glm/common.hpp>

#include <cmath>

namespace sweep {
namespace {

/// A chord of the control polygon: its knot interval and its velocity over that interval.
struct Chord {
  glm::dvec3 velocity{0.0};
  double interval = 0.0;
};

Chord chord(const glm::dvec3& from, const glm::dvec3& to, double alpha) {
  const glm::dvec3 d = to - from;
  // pow(0, 0) = 1: uniform knots stay 1 apart even across repeated points. |d| / |d|^alpha is at
  // most max(|d|, 1), so the velocity never overflows.
  const double interval = std::pow(vector_length(d), alpha);
  return {interval > 0.0 ? d / interval : glm::dvec3(0.0), interval};
}

/// The derivative at the point where chord `in` ends and chord `out` starts.
glm::dvec3 joint_derivative(const Chord& in, const Chord& out) {
  const double sum = in.interval + out.interval;
  if (sum <= 0.0) return glm::dvec3(0.0);  // two zero chords: the point is repeated three times
  return (out.interval / sum) * in.velocity + (in.interval / sum) * out.velocity;
}

}  // namespace

bool is_closed_interpolating(std::span<const glm::dvec3> points) {
  return ends_repeat(points, 1, 4);
}

std::array<glm::dvec3, 4> segment_neighbourhood(std::span<const glm::dvec3> points, std::size_t k, bool closed) {
  SWEEP_EXPECTS(points.size() >= 2 && k + 1 < points.size(), "points.size() >= 2, k + 1 < points.size()");
  SWEEP_EXPECTS(!closed || is_closed_interpolating(points), "closed only if is_closed_interpolating");
  const std::size_t n = points.size();
  if (closed) {
    const std::size_t m = n - 1;  // distinct points: points[m] repeats points[0]
    return {points[(k + m - 1) % m], points[k], points[k + 1], points[(k + 2) % m]};
  }
  const glm::dvec3 before = k > 0 ? points[k - 1] : 2.0 * points[0] - points[1];
  const glm::dvec3 after = k + 2 < n ? points[k + 2] : 2.0 * points[n - 1] - points[n - 2];
  return {before, points[k], points[k + 1], after};
}

std::array<glm::dvec3, 4> catmull_rom_piece(std::span<const glm::dvec3> points, std::size_t k, bool closed,
                                            double alpha, double tension) {
  SWEEP_EXPECTS(points.size() >= 2 && k + 1 < points.size(), "points.size() >= 2, k + 1 < points.size()");
  SWEEP_EXPECTS(!closed || is_closed_interpolating(points), "closed only if is_closed_interpolating");
  SWEEP_EXPECTS(alpha >= 0.0 && alpha <= 1.0, "alpha in [0, 1]");
  SWEEP_EXPECTS(tension >= 0.0 && tension < 1.0, "tension in [0, 1)");
  const std::array<glm::dvec3, 4> p = segment_neighbourhood(points, k, closed);
  // A zero-length segment is a point (uniform knots would otherwise make it a small loop); the
  // tangent repair gives its samples the neighbouring direction.
  if (p[1] == p[2]) return {p[1], p[1], p[2], p[2]};
  const Chord before = chord(p[0], p[1], alpha);
  const Chord segment = chord(p[1], p[2], alpha);
  const Chord after = chord(p[2], p[3], alpha);
  const double scale = segment.interval * (1.0 - tension);  // from d/dt to d/du
  // Hermite to Bezier: B1 = P1 + m1 / 3, B2 = P2 - m2 / 3.
  return {p[1], p[1] + scale * joint_derivative(before, segment) / 3.0,
          p[2] - scale * joint_derivative(segment, after) / 3.0, p[2]};
}

namespace {

struct CatmullRomPieces {
  static std::size_t count(const CurveDescriptor& c) { return c.points.size() - 1; }
  // The derivative is continuous across joints (G1: each segment has its own parameter).
  static bool continuous(const CurveDescriptor&) { return true; }
  static bool closed(const CurveDescriptor& c) { return is_closed_interpolating(c.points); }
  static auto piece_at(const CurveDescriptor& c) {
    return [points = c.points, closed = closed(c), alpha = c.alpha, tension = c.spline.tension](std::size_t k) {
      return catmull_rom_piece(points, k, closed, alpha, tension);
    };
  }
  static CurveSamples evaluate(const CurveDescriptor& c, const FrameOptions& options,
                               const AdaptiveTolerance& tolerance) {
    return evaluate_catmull_rom(c.points, c.steps, c.alpha, c.spline.tension, c.planar, options, tolerance);
  }
};

}  // namespace

const CurveBasis kCatmullRomBasis = piece_detail::PieceCurve<CatmullRomPieces>::basis("Catmull-Rom");

CurveSamples evaluate_catmull_rom(std::span<const glm::dvec3> points, int steps, double alpha, double tension,
                                  bool planar, const FrameOptions& options, const AdaptiveTolerance& tolerance) {
  SWEEP_EXPECTS(points.size() >= 2, "points.size() >= 2");
  SWEEP_EXPECTS(steps >= 1, "steps >= 1");
  SWEEP_EXPECTS(alpha >= 0.0 && alpha <= 1.0, "alpha in [0, 1]");
  SWEEP_EXPECTS(tension >= 0.0 && tension < 1.0, "tension in [0, 1)");
  CurveDescriptor c;
  c.points = points;
  c.alpha = alpha;
  c.spline.tension = tension;
  return piece_detail::sample_pieces(points.size() - 1, {steps, tolerance, {}}, planar, true,
                                     CatmullRomPieces::closed(c), piece_detail::extent(points), options,
                                     CatmullRomPieces::piece_at(c));
}

}  // namespace sweep
