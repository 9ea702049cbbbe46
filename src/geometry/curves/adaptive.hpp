#pragma once
// Adaptive sampling: curves and surfaces sampled for a distance tolerance D instead of a step
// count. Every chord between consecutive samples stays within D of the exact curve, every cubic
// piece's joints are samples, and the tangent turns at most kMaxTurn between samples. See
// adaptive.cpp for the method and docs/adaptive-sampling.md for the measurements.
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <numbers>
#include <string>
#include <vector>

namespace sweep {

/// What adaptive sampling must achieve.
struct AdaptiveTolerance {
  /// D: the largest distance of the curve from its chords (model units); 0 samples by STEPS.
  double distance = 0.0;
  /// Sweeps: the distance r of the farthest profile point from the sweep curve. A chord over a
  /// part that turns by an angle a then also keeps r (1 - cos(a / 2)) within D, so the tube's
  /// outer side (error magnified by about 1 + kappa r) stays within D too.
  double offset = 0.0;
  bool adaptive() const { return distance > 0.0; }
};

/// Largest turn of the tangent between consecutive samples (radians): a nearly flat but turning
/// part (a small loop, a curve much smaller than D) still gets samples, and a circle at least 8.
inline constexpr double kMaxTurn = std::numbers::pi / 4.0;

/// Smallest tolerance, relative to the scene's size (document_extent): below it a file or the
/// command line gets an error, so the sample caps (limits.hpp) are never reached silently.
inline constexpr double kMinRelativeTolerance = 1e-6;

/// The control points of the part [a, b] of the cubic Bezier piece p (de Casteljau subdivision,
/// computed as the blossoms p(a,a,a), p(a,a,b), p(a,b,b), p(b,b,b)). Precondition: 0 <= a < b <= 1.
std::array<glm::dvec3, 4> bezier_part(const std::array<glm::dvec3, 4>& p, double a, double b);

/// The largest distance of the cubic Bezier curve q from the straight line through q[0] and q[3],
/// exactly (closed form, see adaptive.cpp); if q[0] = q[3], the largest distance from q[0] of a
/// control point (a bound).
double chord_deviation(const std::array<glm::dvec3, 4>& q);

/// True if the chord q[0] -> q[3] may stand for the Bezier curve q: no two tangents of q are more
/// than kMaxTurn apart (so the curve projects monotonically onto the chord, whose segment is then
/// as close as its line) and chord_deviation(q), plus the offset term, is at most
/// tolerance.distance.
bool is_flat(const std::array<glm::dvec3, 4>& q, const AdaptiveTolerance& tolerance);

/// Appends the parameters t in (0, 1] of the samples of the cubic Bezier piece p after its start
/// (t = 0 is the caller's, usually the previous piece's end), the last one 1: each part between
/// consecutive samples is_flat. `scale` is the curve's size (parts shorter than 1e-7 of the
/// piece are accepted as they are, so degenerate input always ends). Stops early, returning
/// false, once `out` holds more than `max_samples` values. Precondition: tolerance.adaptive().
bool adaptive_piece_parameters(const std::array<glm::dvec3, 4>& p, const AdaptiveTolerance& tolerance,
                               std::size_t max_samples, std::vector<double>& out);

/// Segments of a circle of radius r within tolerance: ceil(pi / acos(1 - D / r)) (the sagitta of a
/// chord over the angle 2 pi / n is r (1 - cos(pi / n))), and at least 2 pi / kMaxTurn = 8.
/// Precondition: r > 0, D > 0.
int circle_segments(double radius, double tolerance);

/// "" if `tolerance` may be used on something of size `extent`, else the message:
/// "expected a tolerance > 0" or "expected a tolerance of at least 1e-06 of <what>'s size (E)".
std::string check_tolerance(double tolerance, double extent, const std::string& what);

}  // namespace sweep
