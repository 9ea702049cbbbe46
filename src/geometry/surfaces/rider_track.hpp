#pragma once
// Riding a curve: the frame at an arc length, exactly on the curve, for models that move along it
// (the course's airplane: M = [N B T V]). A track is built once per evaluation of its path and
// answers any arc length in O(log samples).
#include "geometry/curves/curve.hpp"
#include "geometry/curves/frames.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <optional>
#include <span>
#include <vector>

namespace sweep {

/// A path prepared for riding: the arc length at each of its samples and the frames a rider
/// follows there. Owns copies of everything it reads (the descriptor's points included).
struct RiderTrack {
  /// The path as geometry sees it, with `points` below in place of the borrowed points.
  CurveDescriptor shape;
  std::vector<glm::dvec3> points;
  /// The path's samples: curve parameter, and the frame a rider has there (the path's own frames,
  /// or the upright frames of `up`).
  std::vector<double> parameters;
  std::vector<Frame> frames;
  /// lengths[i]: the arc length from the start to sample i, by Gauss-Legendre quadrature of |C'|
  /// between consecutive samples (not their chords); lengths[0] = 0, non-decreasing.
  std::vector<double> lengths;
  bool closed = false;
  /// Set: the frames keep B as close to this unit vector as T allows (N = normalize(up x T)).
  std::optional<glm::dvec3> up;

  double length() const { return lengths.empty() ? 0.0 : lengths.back(); }
  /// The descriptor with its points pointing into `points`.
  CurveDescriptor descriptor() const;
};

/// Builds the track of a path from its descriptor and its evaluated samples (frames computed and,
/// for a closed path, closed: evaluate_curve). With `up` (non-zero), each sample's frame becomes
/// N = normalize(up x T), B = T x N; where T is parallel to up (|up x T| below 1e-9 |up|) the
/// previous sample's frame is carried on by rotation-minimizing transport (at the first sample:
/// the path's own frame). Preconditions: samples evaluated from `curve` (the same parameters),
/// at least one sample; up, when given, finite and not zero.
RiderTrack make_rider_track(const CurveDescriptor& curve, const CurveSamples& samples,
                            std::optional<glm::dvec3> up = std::nullopt);

/// The rider's frame at arc length `distance` (clamped to [0, length]): V exactly on the curve at
/// the parameter whose arc length is `distance` (Newton's method on the quadrature, to 1e-12 of
/// the length); T the curve's unit tangent there (the sample's T where the derivative vanishes);
/// N and B the frame of the sample before, carried to V by rotation-minimizing transport and
/// turned about T by the share of the turn to the next sample's frame, so frames are continuous
/// and equal the sampled frames at the samples. With `up`, N = normalize(up x T) wherever that is
/// defined. A path of length 0 gives its first sample's frame. Precondition: a track from
/// make_rider_track.
Frame track_frame_at(const RiderTrack& track, double distance);

/// The arc length a rider has covered at `time` seconds: length * fract(time / seconds + start)
/// (a closed path loops, an open one starts over at its beginning). Preconditions: seconds > 0,
/// start in [0, 1), time finite.
double ride_distance(const RiderTrack& track, double time, double seconds, double start);

/// The model matrix of a frame, the course's airplane: the model's +x along N, +y along B, +z
/// along T, its origin at V (columns N, B, T, V).
glm::dmat4 frame_matrix(const Frame& frame);

}  // namespace sweep
