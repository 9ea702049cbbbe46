#pragma once
// Evaluating curves into samples with frames.
#include "core/adaptive.hpp"
#include "core/document.hpp"
#include "core/frames.hpp"
#include "core/kochanek_bartels.hpp"

#include <span>
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
  bool planar = false;  // lies in the xy-plane (bez2, bsp2, circ, cr2, kb2)
  bool closed = false;  // last sample equals the first in position and tangent (float noise tolerated)
  /// Samples per cubic piece: sample i is at curve parameter i / steps (pieces; a circle or torus
  /// knot: 0..1; a helix: about the number of turns, exactly so when steps * turns is whole).
  /// 0 for pieces sampled adaptively (parameters tells where the samples are).
  int steps = 1;
  /// The curve parameter of each sample: pieces (0..piece count) for control-point curves, 0..1
  /// for a circle or torus knot, turns for a helix.
  std::vector<double> parameters;
  /// Adaptive sampling would have passed limits::kMaxCurveSamples: the curve was sampled by its
  /// STEPS instead, and the tolerance asked for is too small for it.
  bool capped = false;
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
                             const FrameOptions& options = {}, const AdaptiveTolerance& tolerance = {});
/// Evaluates a uniform cubic B-spline by converting each piece to Bezier form:
/// N >= 4 points, (N-3) * steps + 1 samples. Preconditions: points.size() >= 4, steps >= 1.
CurveSamples evaluate_bspline(const std::vector<glm::dvec3>& points, int steps, bool planar,
                              const FrameOptions& options = {}, const AdaptiveTolerance& tolerance = {});
/// Control-point curves sampled adaptively (tolerance.adaptive()) keep every joint as a sample
/// and place the others by adaptive_piece_parameters.
/// Evaluates the Catmull-Rom spline through `points` (catmull_rom.hpp): knot spacing |dP|^alpha,
/// tangents scaled by 1 - tension, N - 1 segments, (N - 1) * steps + 1 samples; closed with a C1
/// seam if the last point equals the first (is_closed_interpolating), else reflected ends.
/// Preconditions: points.size() >= 2, steps >= 1, alpha in [0, 1], tension in [0, 1).
CurveSamples evaluate_catmull_rom(const std::vector<glm::dvec3>& points, int steps, double alpha, double tension,
                                  bool planar, const FrameOptions& options = {},
                                  const AdaptiveTolerance& tolerance = {});
/// Evaluates the Kochanek-Bartels spline through `points` (kochanek_bartels.hpp) with uniform
/// knots, (N - 1) * steps + 1 samples, closed as evaluate_catmull_rom. Where continuity != 0 the
/// tangent jumps at the interior points: they are recorded as corners.
/// Preconditions: points.size() >= 2, steps >= 1, tension, continuity and bias in [-1, 1].
CurveSamples evaluate_kochanek_bartels(const std::vector<glm::dvec3>& points, int steps,
                                       const KochanekBartelsShape& shape, bool planar, const FrameOptions& options = {},
                                       const AdaptiveTolerance& tolerance = {});
/// Frames of a closed 3D curve are closed (FrameOptions::close_seam): the end frame equals the
/// start frame and the rotation between them is spread along the curve.
/// A counterclockwise circle about the origin in the xy-plane, steps + 1 samples, first = last.
/// Preconditions: steps >= 1, radius > 0.
CurveSamples evaluate_circle(double radius, int steps);

/// Evaluates any curve object (helices: evaluate_helix in helix.hpp, torus knots:
/// evaluate_torus_knot in torus_knot.hpp): by its STEPS, or adaptively when `tolerance` is
/// adaptive (every chord within tolerance.distance of the curve, see adaptive.hpp), else when the
/// object has its own `tolerance` clause. Precondition: is_curve(object.kind) and a valid object.
CurveSamples evaluate_curve(const Object& object, const FrameOptions& options = {},
                            const AdaptiveTolerance& tolerance = {});

/// Samples a curve object at the given curve parameters (CurveSamples::parameters' units; sorted,
/// within the curve's range), with frames, corners at joints that are among them, and a closed
/// seam when the first and last sample meet. Used to build references denser than a sampling.
CurveSamples evaluate_curve_at(const Object& object, std::span<const double> parameters,
                               const FrameOptions& options = {});

/// The point of a curve object at a curve parameter (CurveSamples::parameters' units).
glm::dvec3 curve_position(const Object& object, double parameter);

/// True if the first and last samples coincide in position and tangent within a tolerance
/// relative to the curve's size.
bool is_closed(const std::vector<Frame>& frames);

}  // namespace sweep
