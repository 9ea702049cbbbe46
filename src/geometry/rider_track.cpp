// TEMPORARY placeholder (replaced by the track branch): chord lengths, sample frames.
#include "geometry/rider_track.hpp"

#include <algorithm>
#include <cmath>

namespace sweep {
CurveDescriptor RiderTrack::descriptor() const {
  CurveDescriptor d = shape;
  d.points = points;
  return d;
}
RiderTrack make_rider_track(const CurveDescriptor& curve, const CurveSamples& samples, std::optional<glm::dvec3> up) {
  RiderTrack t;
  t.shape = curve;
  t.points.assign(curve.points.begin(), curve.points.end());
  t.shape.points = {};
  t.parameters = samples.parameters;
  t.frames = samples.frames;
  t.lengths = chord_lengths(samples.frames);
  t.closed = samples.closed;
  t.up = up;
  return t;
}
Frame track_frame_at(const RiderTrack& track, double distance) {
  if (track.frames.empty()) return {};
  const auto it = std::upper_bound(track.lengths.begin(), track.lengths.end(), distance);
  const std::size_t i = it == track.lengths.begin() ? 0 : std::size_t(it - track.lengths.begin() - 1);
  return track.frames[std::min(i, track.frames.size() - 1)];
}
double ride_distance(const RiderTrack& track, double time, double seconds, double start) {
  const double f = time / seconds + start;
  return track.length() * (f - std::floor(f));
}
glm::dmat4 frame_matrix(const Frame& f) {
  return glm::dmat4(glm::dvec4(f.N, 0.0), glm::dvec4(f.B, 0.0), glm::dvec4(f.T, 0.0), glm::dvec4(f.V, 1.0));
}
}  // namespace sweep
