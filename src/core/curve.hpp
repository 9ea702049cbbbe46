#pragma once
// Evaluating curves into samples with frames.
#include "core/document.hpp"
#include "core/frames.hpp"

#include <vector>

namespace sweep {

struct CurveSamples {
  std::vector<Frame> frames;
  bool planar = false;  // lies in the xy-plane (bez2, bsp2, circ)
  bool closed = false;  // last sample equals the first in position and tangent (float noise tolerated)
};

/// Evaluates a piecewise cubic Bezier curve: 3n+1 control points, n * steps + 1 samples.
/// Preconditions: points.size() = 3n+1 with n >= 1, steps >= 1.
CurveSamples evaluate_bezier(const std::vector<glm::dvec3>& points, int steps, bool planar,
                             const FrameOptions& options = {});
/// Evaluates a uniform cubic B-spline by converting each piece to Bezier form:
/// N >= 4 points, (N-3) * steps + 1 samples. Preconditions: points.size() >= 4, steps >= 1.
CurveSamples evaluate_bspline(const std::vector<glm::dvec3>& points, int steps, bool planar,
                              const FrameOptions& options = {});
/// A counterclockwise circle about the origin in the xy-plane, steps + 1 samples, first = last.
/// Preconditions: steps >= 1, radius > 0.
CurveSamples evaluate_circle(double radius, int steps);

/// Evaluates any curve object. Precondition: is_curve(object.kind) and a valid object.
CurveSamples evaluate_curve(const Object& object, const FrameOptions& options = {});

/// True if the first and last samples coincide in position and tangent within a tolerance
/// relative to the curve's size.
bool is_closed(const std::vector<Frame>& frames);

}  // namespace sweep
