// Kochanek-Bartels splines:
//   D. Kochanek, R. Bartels, "Interpolating splines with local tension, continuity, and bias
//   control", SIGGRAPH 1984 (Computer Graphics 18(3)), pp. 33-41.
// Each segment P_i -> P_{i+1} is the cubic Hermite (uniform knots, one unit per segment) with the
// outgoing tangent at P_i and the incoming tangent at P_{i+1}:
//   out_i = (1-T)(1+B)(1+C)/2 (P_i - P_{i-1}) + (1-T)(1-B)(1-C)/2 (P_{i+1} - P_i)
//   in_i  = (1-T)(1+B)(1-C)/2 (P_i - P_{i-1}) + (1-T)(1-B)(1+C)/2 (P_{i+1} - P_i)
// They differ where C != 0: the curve has a corner at every interior point there.
#include "geometry/curves/kochanek_bartels.hpp"

#include "base/precondition.hpp"
#include "geometry/curves/catmull_rom.hpp"
#include "geometry/curves/curve.hpp"
#include "geometry/curves/piece_sampling.hpp"

namespace sweep {
namespace {

/// The tangent at `p` between `before` and `after`; `leaving` picks the outgoing one.
glm::dvec3 kb_tangent(const glm::dvec3& before, const glm::dvec3& p, const glm::dvec3& after,
                      const KochanekBartelsShape& s, bool leaving) {
  const double c = leaving ? s.continuity : -s.continuity;
  const double arriving_weight = (1.0 - s.tension) * (1.0 + s.bias) * (1.0 + c) / 2.0;
  const double leaving_weight = (1.0 - s.tension) * (1.0 - s.bias) * (1.0 - c) / 2.0;
  return arriving_weight * (p - before) + leaving_weight * (after - p);
}

}  // namespace

std::array<glm::dvec3, 4> kochanek_bartels_piece(std::span<const glm::dvec3> points, std::size_t k, bool closed,
                                                 const KochanekBartelsShape& shape) {
  SWEEP_EXPECTS(points.size() >= 2 && k + 1 < points.size(), "points.size() >= 2, k + 1 < points.size()");
  SWEEP_EXPECTS(!closed || is_closed_interpolating(points), "closed only if is_closed_interpolating");
  SWEEP_EXPECTS(shape.tension >= -1.0 && shape.tension <= 1.0 && shape.continuity >= -1.0 && shape.continuity <= 1.0 &&
                    shape.bias >= -1.0 && shape.bias <= 1.0,
                "tension, continuity and bias in [-1, 1]");
  const std::array<glm::dvec3, 4> p = segment_neighbourhood(points, k, closed);
  if (p[1] == p[2]) return {p[1], p[1], p[2], p[2]};  // as catmull_rom_piece: a point
  const glm::dvec3 out = kb_tangent(p[0], p[1], p[2], shape, true);
  const glm::dvec3 in = kb_tangent(p[1], p[2], p[3], shape, false);
  return {p[1], p[1] + out / 3.0, p[2] - in / 3.0, p[2]};  // Hermite to Bezier
}

namespace {

struct KochanekBartelsPieces {
  static std::size_t count(const CurveDescriptor& c) { return c.points.size() - 1; }
  // Where continuity != 0 the tangent jumps at the interior points: they are corners.
  static bool continuous(const CurveDescriptor& c) { return c.spline.continuity == 0.0; }
  static bool closed(const CurveDescriptor& c) { return is_closed_interpolating(c.points); }
  static auto piece_at(const CurveDescriptor& c) {
    return [points = c.points, closed = closed(c), shape = c.spline](std::size_t k) {
      return kochanek_bartels_piece(points, k, closed, shape);
    };
  }
  static CurveSamples evaluate(const CurveDescriptor& c, const FrameOptions& options,
                               const AdaptiveTolerance& tolerance) {
    return evaluate_kochanek_bartels(c.points, c.steps, c.spline, c.planar, options, tolerance);
  }
};

}  // namespace

const CurveBasis kKochanekBartelsBasis = piece_detail::PieceCurve<KochanekBartelsPieces>::basis("Kochanek-Bartels");

CurveSamples evaluate_kochanek_bartels(std::span<const glm::dvec3> points, int steps, const KochanekBartelsShape& shape,
                                       bool planar, const FrameOptions& options, const AdaptiveTolerance& tolerance) {
  SWEEP_EXPECTS(points.size() >= 2, "points.size() >= 2");
  SWEEP_EXPECTS(steps >= 1, "steps >= 1");
  SWEEP_EXPECTS(shape.tension >= -1.0 && shape.tension <= 1.0 && shape.continuity >= -1.0 && shape.continuity <= 1.0 &&
                    shape.bias >= -1.0 && shape.bias <= 1.0,
                "tension, continuity and bias in [-1, 1]");
  CurveDescriptor c;
  c.points = points;
  c.spline = shape;
  return piece_detail::sample_pieces(points.size() - 1, {steps, tolerance, {}}, planar, shape.continuity == 0.0,
                                     KochanekBartelsPieces::closed(c), piece_detail::extent(points), options,
                                     KochanekBartelsPieces::piece_at(c));
}

}  // namespace sweep
