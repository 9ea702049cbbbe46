#include "geometry/surfaces/rider_track.hpp"

#include "base/precondition.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>

namespace sweep {
namespace {

// Gauss-Legendre nodes and weights of order 8 on [-1, 1] (Abramowitz and Stegun, table 25.4).
constexpr std::array<double, 4> kNodes = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                          0.9602898564975363};
constexpr std::array<double, 4> kWeights = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                            0.1012285362903763};

double speed(const CurveDescriptor& curve, double u) {
  return glm::length(curve_derivatives(curve, u).d1);
}

/// The arc length from a to b by 8-point Gauss-Legendre quadrature of |C'|; `even` tells whether
/// the speed at the nodes stays within 10 % of its least value (smooth and well resolved: the
/// rule is then exact to rounding for the cubic pieces and analytic curves here).
double gauss_length(const CurveDescriptor& curve, double a, double b, bool* even = nullptr) {
  const double middle = 0.5 * (a + b);
  const double half = 0.5 * (b - a);
  double sum = 0.0;
  double least = INFINITY;
  double most = 0.0;
  for (std::size_t k = 0; k < kNodes.size(); ++k) {
    for (const double node : {middle - half * kNodes[k], middle + half * kNodes[k]}) {
      const double v = speed(curve, node);
      sum += kWeights[k] * v;
      least = std::min(least, v);
      most = std::max(most, v);
    }
  }
  if (even) *even = least > 0.0 && most <= 1.1 * least;
  return half * sum;
}

/// The arc length from a to b, halving the interval until two halves agree with the whole to
/// `tolerance` (at most `depth` times): |C'| has kinks only where it vanishes, at cusps.
double arc_length(const CurveDescriptor& curve, double a, double b, double whole, double tolerance, int depth) {
  const double middle = 0.5 * (a + b);
  const double left = gauss_length(curve, a, middle);
  const double right = gauss_length(curve, middle, b);
  if (depth == 0 || std::abs(left + right - whole) <= tolerance) return left + right;
  return arc_length(curve, a, middle, left, 0.5 * tolerance, depth - 1) +
         arc_length(curve, middle, b, right, 0.5 * tolerance, depth - 1);
}

double arc_length(const CurveDescriptor& curve, double a, double b, double tolerance) {
  if (b <= a) return 0.0;
  bool even = false;
  const double whole = gauss_length(curve, a, b, &even);
  return even ? whole : arc_length(curve, a, b, whole, tolerance, 12);
}

/// The upright frame about `up`: N = normalize(up x T),
/// B = T x N; false (frame unchanged) where T is parallel to up.
bool upright(Frame& frame, const glm::dvec3& up) {
  const glm::dvec3 n = glm::cross(up, frame.T);
  const double length = glm::length(n);
  if (!(length >= 1e-9 * glm::length(up))) return false;
  frame.N = n / length;
  frame.B = glm::cross(frame.T, frame.N);
  return true;
}

/// The samples' frames kept upright about `up`, carried on where T is parallel to it.
void make_upright(std::vector<Frame>& frames, const glm::dvec3& up) {
  for (std::size_t i = 0; i < frames.size(); ++i) {
    if (upright(frames[i], up) || i == 0) continue;
    frames[i] = transport_rotation_minimizing(frames[i - 1], frames[i]);
  }
}

/// The parameter in [lo, hi] of sample interval i where the arc length from the start is
/// `distance`: Newton's method on the quadrature, kept in a shrinking bracket (bisection when a
/// step leaves it or the speed vanishes).
double parameter_at(const RiderTrack& track, const CurveDescriptor& curve, std::size_t i, double distance) {
  double lo = track.parameters[i];
  double hi = track.parameters[i + 1];
  const double span = track.lengths[i + 1] - track.lengths[i];
  const double tolerance = 1e-12 * std::max(track.length(), 1e-300);
  double u = lo + (hi - lo) * std::clamp((distance - track.lengths[i]) / span, 0.0, 1.0);
  for (int iteration = 0; iteration < 60; ++iteration) {
    const double error = track.lengths[i] + arc_length(curve, track.parameters[i], u, 0.1 * tolerance) - distance;
    if (std::abs(error) <= tolerance) break;
    (error > 0.0 ? hi : lo) = u;
    const double derivative = speed(curve, u);
    const double step = derivative > 0.0 ? u - error / derivative : lo - 1.0;
    u = step > lo && step < hi ? step : 0.5 * (lo + hi);
    if (hi - lo <= 1e-15 * std::max(1.0, std::abs(hi))) break;
  }
  return u;
}

/// The sample interval [i, i + 1] holding `distance` (lengths[i] <= distance < lengths[i + 1],
/// skipping intervals of length 0). Precondition: 0 < distance < length.
std::size_t interval_of(const RiderTrack& track, double distance) {
  const auto after = std::upper_bound(track.lengths.begin(), track.lengths.end(), distance);
  return static_cast<std::size_t>(after - track.lengths.begin()) - 1;
}

/// The frame at parameter u in interval i: carried from sample i and turned towards sample i + 1
/// by the share `share` of the turn between them.
Frame frame_between(const RiderTrack& track, const CurveDescriptor& curve, std::size_t i, double u, double share) {
  const PieceDerivatives d = curve_derivatives(curve, u);
  const Frame& a = track.frames[i];
  const Frame& b = track.frames[i + 1];
  Frame at;
  at.V = d.position;
  const double speed_here = glm::length(d.d1);
  at.T = speed_here > 0.0 && std::isfinite(speed_here) ? d.d1 / speed_here : glm::normalize(glm::mix(a.T, b.T, share));
  if (!std::isfinite(at.T.x)) at.T = a.T;
  if (track.up && upright(at, *track.up)) return at;
  if (curve.planar && !track.up) {
    at.B = glm::dvec3(0.0, 0.0, 1.0);
    at.N = glm::normalize(glm::cross(at.B, at.T));
    return at;
  }
  const Frame carried_to_b = transport_rotation_minimizing(a, b);
  const double turn = angle_about(b.T, carried_to_b.N, b.N);
  at = transport_rotation_minimizing(a, at);
  rotate_about_tangent(at, share * turn);
  return at;
}

}  // namespace

CurveDescriptor RiderTrack::descriptor() const {
  CurveDescriptor d = shape;
  d.points = points;
  return d;
}

RiderTrack make_rider_track(const CurveDescriptor& curve, const CurveSamples& samples, std::optional<glm::dvec3> up) {
  SWEEP_EXPECTS(!samples.frames.empty() && samples.parameters.size() == samples.frames.size(),
                "samples evaluated from curve, at least one");
  SWEEP_EXPECTS(!up || (std::isfinite(up->x) && std::isfinite(up->y) && std::isfinite(up->z) && *up != glm::dvec3(0.0)),
                "up, when given, finite and not zero");
  RiderTrack track;
  track.shape = curve;
  track.points.assign(curve.points.begin(), curve.points.end());
  track.shape.points = {};
  track.parameters = samples.parameters;
  track.frames = samples.frames;
  track.closed = samples.closed;
  track.up = up;
  if (up) make_upright(track.frames, *up);
  const CurveDescriptor own = track.descriptor();
  const double chords = std::max(chord_lengths(samples.frames).back(), 1e-300);
  track.lengths.assign(track.frames.size(), 0.0);
  for (std::size_t i = 1; i < track.frames.size(); ++i) {
    const double piece = arc_length(own, track.parameters[i - 1], track.parameters[i], 1e-13 * chords);
    track.lengths[i] = track.lengths[i - 1] + piece;
  }
  return track;
}

Frame track_frame_at(const RiderTrack& track, double distance) {
  SWEEP_EXPECTS(!track.frames.empty() && track.lengths.size() == track.frames.size(), "a track from make_rider_track");
  const CurveDescriptor curve = track.descriptor();
  const double length = track.length();
  if (!(distance > 0.0) || length <= 0.0) return track.frames.front();
  if (distance >= length) return track.frames.back();
  const std::size_t i = interval_of(track, distance);
  const double share = (distance - track.lengths[i]) / (track.lengths[i + 1] - track.lengths[i]);
  return frame_between(track, curve, i, parameter_at(track, curve, i, distance), share);
}

double ride_distance(const RiderTrack& track, double time, double seconds, double start) {
  SWEEP_EXPECTS(seconds > 0.0 && start >= 0.0 && start < 1.0 && std::isfinite(time),
                "seconds > 0, start in [0, 1), time finite");
  const double loops = time / seconds + start;
  const double share = loops - std::floor(loops);
  return track.length() * std::min(share, 1.0 - 1e-16);  // fract below 1 even after rounding
}

glm::dmat4 frame_matrix(const Frame& frame) {
  return glm::dmat4(glm::dvec4(frame.N, 0.0), glm::dvec4(frame.B, 0.0), glm::dvec4(frame.T, 0.0),
                    glm::dvec4(frame.V, 1.0));
}

}  // namespace sweep
