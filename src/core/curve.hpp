#pragma once
// Evaluating curves into samples with frames.
#include "core/document.hpp"
#include "core/frames.hpp"

#include <vector>

namespace sweep {

/// A joint of a piecewise curve where the tangent jumps (a sharp corner). The joint sample's frame
/// carries the leaving tangent; sweeps place the profile in the mitre plane there (surface.hpp).
struct Corner {
  std::size_t sample = 0;    // index of the joint sample in CurveSamples::frames
  glm::dvec3 incoming{0.0};  // unit tangent arriving at the joint
};

struct CurveSamples {
  std::vector<Frame> frames;
  bool planar = false;  // lies in the xy-plane (bez2, bsp2, circ)
  bool closed = false;  // last sample equals the first in position and tangent (float noise tolerated)
  int steps = 1;        // samples per cubic piece: sample i is at curve parameter i / steps (pieces)
  /// Closed 3D curves: the angle (radians, about T) from the start frame to the propagated end
  /// frame, which close_frames spread along the curve. 0 for open and planar curves.
  double seam_angle = 0.0;
  /// |kappa| at each sample from the curve's derivatives (0 where the first derivative vanishes).
  std::vector<double> curvature;
  std::vector<Corner> corners;  // in sample order
};

/// Evaluates a piecewise cubic Bezier curve: 3n+1 control points, n * steps + 1 samples.
/// Preconditions: points.size() = 3n+1 with n >= 1, steps >= 1.
CurveSamples evaluate_bezier(const std::vector<glm::dvec3>& points, int steps, bool planar,
                             const FrameOptions& options = {});
/// Evaluates a uniform cubic B-spline by converting each piece to Bezier form:
/// N >= 4 points, (N-3) * steps + 1 samples. Preconditions: points.size() >= 4, steps >= 1.
CurveSamples evaluate_bspline(const std::vector<glm::dvec3>& points, int steps, bool planar,
                              const FrameOptions& options = {});
/// Frames of a closed 3D curve are closed (FrameOptions::close_seam): the end frame equals the
/// start frame and the rotation between them is spread along the curve.
/// A counterclockwise circle about the origin in the xy-plane, steps + 1 samples, first = last.
/// Preconditions: steps >= 1, radius > 0.
CurveSamples evaluate_circle(double radius, int steps);

/// Evaluates any curve object. Precondition: is_curve(object.kind) and a valid object.
CurveSamples evaluate_curve(const Object& object, const FrameOptions& options = {});

/// True if the first and last samples coincide in position and tangent within a tolerance
/// relative to the curve's size.
bool is_closed(const std::vector<Frame>& frames);

}  // namespace sweep
