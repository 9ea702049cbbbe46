#include "geometry/curves/hermite.hpp"

#include "base/precondition.hpp"
#include "geometry/curves/piece_sampling.hpp"

namespace sweep {
namespace {

using piece_detail::PieceCurve;

struct HermitePieces {
  static std::size_t count(const CurveDescriptor& c) { return c.points.size() / 2 - 1; }
  static bool continuous(const CurveDescriptor&) { return true; }
  static bool closed(const CurveDescriptor& c) { return ends_repeat(c.points, 2, 6); }
  static auto piece_at(const CurveDescriptor& c) {
    return [points = c.points](std::size_t k) { return hermite_piece(points, k); };
  }
  static CurveSamples evaluate(const CurveDescriptor& c, const FrameOptions& options,
                               const AdaptiveTolerance& tolerance) {
    return evaluate_hermite(c.points, c.steps, c.planar, options, tolerance);
  }
};

}  // namespace

const CurveBasis kHermiteBasis = PieceCurve<HermitePieces>::basis("Hermite");

BezierPiece hermite_piece(std::span<const glm::dvec3> entries, std::size_t k) {
  SWEEP_EXPECTS(entries.size() % 2 == 0 && 2 * k + 3 < entries.size(), "piece k of an even list of entries");
  const glm::dvec3& p = entries[2 * k];
  const glm::dvec3& q = entries[2 * k + 2];
  return {p, p + entries[2 * k + 1] / 3.0, q - entries[2 * k + 3] / 3.0, q};
}

CurveSamples evaluate_hermite(std::span<const glm::dvec3> entries, int steps, bool planar, const FrameOptions& options,
                              const AdaptiveTolerance& tolerance) {
  SWEEP_EXPECTS(entries.size() >= 4 && entries.size() % 2 == 0, "entries.size() even and >= 4");
  SWEEP_EXPECTS(steps >= 1, "steps >= 1");
  CurveDescriptor c;
  c.points = entries;
  c.planar = planar;
  return piece_detail::sample_pieces(HermitePieces::count(c), {steps, tolerance, {}}, planar, true,
                                     HermitePieces::closed(c), piece_detail::extent(entries), options,
                                     HermitePieces::piece_at(c));
}

}  // namespace sweep
