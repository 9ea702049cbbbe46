#include "geometry/curves/polyline.hpp"

#include "base/precondition.hpp"
#include "geometry/curves/catmull_rom.hpp"
#include "geometry/curves/piece_sampling.hpp"
#include "geometry/unit_vector.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace sweep {
namespace {

/// Smallest turn (radians) that makes a point a corner: any real turn, not float noise.
constexpr double kPolylineCornerAngle = 1e-9;

/// Unit direction of each segment; a zero-length one takes the next non-zero direction, or the
/// previous one at the end (+x if every segment is a point).
std::vector<glm::dvec3> segment_directions(std::span<const glm::dvec3> points, bool planar) {
  std::vector<glm::dvec3> dirs(points.size() - 1, glm::dvec3(0.0));
  for (std::size_t k = 0; k + 1 < points.size(); ++k) {
    glm::dvec3 d = points[k + 1] - points[k];
    if (planar) d.z = 0.0;
    if (vector_length(d) > 0.0) dirs[k] = unit_vector(d);
  }
  glm::dvec3 next(0.0);
  for (std::size_t k = dirs.size(); k-- > 0;) {
    if (vector_length(dirs[k]) > 0.0) next = dirs[k];
    dirs[k] = vector_length(dirs[k]) > 0.0 ? dirs[k] : next;
  }
  glm::dvec3 previous(1.0, 0.0, 0.0);
  for (glm::dvec3& d : dirs) {
    if (vector_length(d) > 0.0) previous = d;
    d = vector_length(d) > 0.0 ? d : previous;
  }
  return dirs;
}

bool turns(const glm::dvec3& incoming, const glm::dvec3& leaving) {
  return std::atan2(vector_length(glm::cross(incoming, leaving)), glm::dot(incoming, leaving)) > kPolylineCornerAngle;
}

}  // namespace

CurveSamples evaluate_polyline(std::span<const glm::dvec3> points, bool planar, const FrameOptions& options) {
  SWEEP_EXPECTS(points.size() >= 2, "points.size() >= 2");
  const std::size_t n = points.size();
  const std::vector<glm::dvec3> dirs = segment_directions(points, planar);
  CurveSamples curve;
  curve.planar = planar;
  curve.steps = 1;
  curve.frames.resize(n);
  curve.curvature.assign(n, 0.0);
  curve.parameters.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    curve.frames[i].V = points[i];
    if (planar) curve.frames[i].V.z = 0.0;
    curve.frames[i].T = dirs[std::min(i, n - 2)];
    curve.parameters[i] = static_cast<double>(i);
    if (i > 0 && i + 1 < n && turns(dirs[i - 1], dirs[i])) curve.corners.push_back({i, dirs[i - 1]});
  }
  curve.closed = is_closed_interpolating(points);
  if (curve.closed) {
    curve.frames.back() = curve.frames.front();  // exactly closed, leaving along the first segment
    if (turns(dirs.back(), dirs.front())) curve.corners.insert(curve.corners.begin(), Corner{0, dirs.back()});
  }
  compute_frames(curve.frames, planar, options);
  if (curve.closed && !planar && options.close_seam) curve.seam_angle = close_frames(curve.frames, options.seam_spread);
  return curve;
}

namespace {

/// Straight cubics for positions and samples at chosen parameters, so they follow the segments.
struct PolylinePieces {
  static std::size_t count(const CurveDescriptor& c) { return c.points.size() - 1; }
  static bool continuous(const CurveDescriptor&) { return false; }
  static bool closed(const CurveDescriptor& c) { return is_closed_interpolating(c.points); }
  static auto piece_at(const CurveDescriptor& c) {
    return [points = c.points](std::size_t k) {
      const glm::dvec3 step = (points[k + 1] - points[k]) / 3.0;
      return std::array<glm::dvec3, 4>{points[k], points[k] + step, points[k] + 2.0 * step, points[k + 1]};
    };
  }
  /// One sample per point, whatever the steps or tolerance.
  static CurveSamples evaluate(const CurveDescriptor& c, const FrameOptions& options, const AdaptiveTolerance&) {
    return evaluate_polyline(c.points, c.planar, options);
  }
};

}  // namespace

const CurveBasis kPolylineBasis = piece_detail::PieceCurve<PolylinePieces>::basis("polyline", true);

}  // namespace sweep
