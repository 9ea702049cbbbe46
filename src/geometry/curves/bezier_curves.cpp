// The Bezier and B-spline bases (bezier.hpp): curves of cubic pieces sampled by piece_sampling.hpp.
#include "base/precondition.hpp"
#include "geometry/curves/bezier.hpp"
#include "geometry/curves/curve.hpp"
#include "geometry/curves/piece_sampling.hpp"

namespace sweep {
namespace {

using piece_detail::PieceCurve;

struct BezierPieces {
  static std::size_t count(const CurveDescriptor& c) { return (c.points.size() - 1) / 3; }
  static bool continuous(const CurveDescriptor&) { return false; }
  static bool closed(const CurveDescriptor& c) { return ends_repeat(c.points, 1, 4); }
  static auto piece_at(const CurveDescriptor& c) {
    return [points = c.points](std::size_t k) {
      return std::array<glm::dvec3, 4>{points[3 * k], points[3 * k + 1], points[3 * k + 2], points[3 * k + 3]};
    };
  }
  static CurveSamples evaluate(const CurveDescriptor& c, const FrameOptions& options,
                               const AdaptiveTolerance& tolerance) {
    return evaluate_bezier(c.points, c.steps, c.planar, options, tolerance);
  }
};

struct BSplinePieces {
  static std::size_t count(const CurveDescriptor& c) { return c.points.size() - 3; }
  static bool continuous(const CurveDescriptor&) { return true; }
  static bool closed(const CurveDescriptor& c) { return ends_repeat(c.points, 3, 6); }
  static auto piece_at(const CurveDescriptor& c) {
    return [points = c.points](std::size_t k) {
      return bspline_piece_to_bezier({points[k], points[k + 1], points[k + 2], points[k + 3]});
    };
  }
  static CurveSamples evaluate(const CurveDescriptor& c, const FrameOptions& options,
                               const AdaptiveTolerance& tolerance) {
    return evaluate_bspline(c.points, c.steps, c.planar, options, tolerance);
  }
};

CurveDescriptor points_curve(std::span<const glm::dvec3> points, bool planar) {
  CurveDescriptor c;
  c.points = points;
  c.planar = planar;
  return c;
}

}  // namespace

const CurveBasis kBezierBasis = PieceCurve<BezierPieces>::basis("Bezier");
const CurveBasis kBSplineBasis = PieceCurve<BSplinePieces>::basis("B-spline");

CurveSamples evaluate_bezier(std::span<const glm::dvec3> points, int steps, bool planar, const FrameOptions& options,
                             const AdaptiveTolerance& tolerance) {
  SWEEP_EXPECTS(points.size() >= 4 && (points.size() - 1) % 3 == 0, "points.size() = 3n+1 with n >= 1");
  SWEEP_EXPECTS(steps >= 1, "steps >= 1");
  const CurveDescriptor c = points_curve(points, planar);
  return piece_detail::sample_pieces(BezierPieces::count(c), {steps, tolerance, {}}, planar, false,
                                     BezierPieces::closed(c), piece_detail::extent(points), options,
                                     BezierPieces::piece_at(c));
}

CurveSamples evaluate_bspline(std::span<const glm::dvec3> points, int steps, bool planar, const FrameOptions& options,
                              const AdaptiveTolerance& tolerance) {
  SWEEP_EXPECTS(points.size() >= 4, "points.size() >= 4");
  SWEEP_EXPECTS(steps >= 1, "steps >= 1");
  const CurveDescriptor c = points_curve(points, planar);
  return piece_detail::sample_pieces(BSplinePieces::count(c), {steps, tolerance, {}}, planar, true,
                                     BSplinePieces::closed(c), piece_detail::extent(points), options,
                                     BSplinePieces::piece_at(c));
}

}  // namespace sweep
