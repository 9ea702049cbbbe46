// Evaluating any curve through its basis (curve_basis.hpp); the bases live in their own files.
#include "geometry/curves/curve.hpp"

#include "geometry/curves/piece_sampling.hpp"
#include "geometry/unit_vector.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>

namespace sweep {

bool ends_repeat(std::span<const glm::dvec3> points, std::size_t repeats, std::size_t minimum) {
  const std::size_t n = points.size();
  if (n < minimum || n < 2 * repeats) return false;
  bool exact = true;
  for (std::size_t i = 0; i < repeats; ++i) exact = exact && points[i] == points[n - repeats + i];
  if (exact) return true;
  const std::size_t seam = std::max<std::size_t>(repeats, 2);
  glm::dvec3 lo = points[0], hi = lo;
  for (std::size_t i = 0; i < seam; ++i) {
    for (const glm::dvec3& p : {points[i], points[n - 1 - i]}) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
  }
  const double tolerance = 1e-9 * vector_length(hi - lo);
  for (std::size_t i = 0; i < repeats; ++i) {
    if (!(vector_length(points[n - repeats + i] - points[i]) <= tolerance)) return false;
  }
  return true;
}

bool is_closed(const CurveDescriptor& curve) {
  return curve.basis->closed(curve);
}

namespace {

/// The samples of an analytic curve moved to where it stands (CurveDescriptor::origin); untouched
/// at the origin, so curves without a place evaluate bit for bit as their basis does.
CurveSamples placed(const CurveDescriptor& curve, CurveSamples samples) {
  if (curve.origin == glm::dvec3(0.0)) return samples;
  for (Frame& f : samples.frames) f.V += curve.origin;
  return samples;
}

}  // namespace

CurveSamples evaluate_curve(const CurveDescriptor& curve, const FrameOptions& options,
                            const AdaptiveTolerance& override) {
  const AdaptiveTolerance tolerance = override.adaptive() ? override : AdaptiveTolerance{curve.tolerance, 0.0};
  return placed(curve, curve.basis->evaluate(curve, options, tolerance));
}

CurveSamples sample_analytic(const CurveDescriptor& curve, std::span<const double> parameters,
                             const FrameOptions& options, PieceDerivatives (*point)(const CurveDescriptor&, double)) {
  const bool planar = curve.planar;
  CurveSamples samples;
  samples.planar = planar;
  samples.steps = 0;
  samples.parameters.assign(parameters.begin(), parameters.end());
  samples.frames.resize(parameters.size());
  samples.curvature.resize(parameters.size());
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const PieceDerivatives d = point(curve, parameters[i]);
    samples.frames[i].V = d.position;
    samples.frames[i].T = unit_vector(d.d1);
    samples.curvature[i] = piece_detail::curvature_of(d, 0.0);
  }
  samples.closed = is_closed(curve) && is_closed(samples.frames);
  if (samples.closed) samples.frames.back() = samples.frames.front();
  compute_frames(samples.frames, planar, options);
  if (samples.closed && !planar && options.close_seam)
    samples.seam_angle = close_frames(samples.frames, options.seam_spread);
  return samples;
}

CurveSamples evaluate_curve_at(const CurveDescriptor& curve, std::span<const double> parameters,
                               const FrameOptions& options) {
  return placed(curve, curve.basis->evaluate_at(curve, parameters, options));
}

glm::dvec3 curve_position(const CurveDescriptor& curve, double parameter) {
  return curve.basis->position(curve, parameter) + curve.origin;
}

PieceDerivatives curve_derivatives(const CurveDescriptor& curve, double parameter) {
  PieceDerivatives d = curve.basis->derivatives(curve, parameter);
  d.position += curve.origin;
  return d;
}

std::vector<BezierPiece> bezier_pieces(const CurveDescriptor& curve) {
  return curve.basis->pieces ? curve.basis->pieces(curve) : std::vector<BezierPiece>{};
}

bool curve_box(const CurveDescriptor& curve, glm::dvec3& lo, glm::dvec3& hi) {
  if (!curve.basis->control_points) {
    curve.basis->exact_box(curve, lo, hi);
    lo += curve.origin;
    hi += curve.origin;
    return true;
  }
  if (curve.points.empty()) return false;
  lo = hi = curve.points.front();
  for (const glm::dvec3& p : curve.points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return true;
}

double curve_extent(const CurveDescriptor& curve) {
  glm::dvec3 lo, hi;
  return curve_box(curve, lo, hi) ? vector_length(hi - lo) : 0.0;
}

bool is_closed(const std::vector<Frame>& frames) {
  if (frames.size() < 3) return false;
  glm::dvec3 lo = frames.front().V, hi = lo;
  for (const auto& f : frames) {
    lo = glm::min(lo, f.V);
    hi = glm::max(hi, f.V);
  }
  const double size = vector_length(hi - lo);
  if (size <= 0.0) return false;
  const Frame& a = frames.front();
  const Frame& b = frames.back();
  // Relative tolerances: files write coordinates with about 6 digits, evaluation adds rounding.
  return vector_length(b.V - a.V) <= 1e-6 * size && glm::dot(a.T, b.T) >= 1.0 - 1e-8;
}

}  // namespace sweep
