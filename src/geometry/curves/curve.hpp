#pragma once
// Evaluating curves into samples with frames.
#include "geometry/curves/adaptive.hpp"
#include "geometry/curves/bezier.hpp"
#include "geometry/curves/curve_basis.hpp"
#include "geometry/curves/frames.hpp"
#include "geometry/curves/kochanek_bartels.hpp"

#include <cstdint>
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
  bool planar = false;  // lies in the xy-plane (the 2D curves)
  /// The curve is closed (is_closed of its descriptor) and its samples meet there in position
  /// and tangent (float noise tolerated); a polyline's seam may be a corner (mitred).
  bool closed = false;
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
CurveSamples evaluate_bezier(std::span<const glm::dvec3> points, int steps, bool planar,
                             const FrameOptions& options = {}, const AdaptiveTolerance& tolerance = {});
/// Evaluates a uniform cubic B-spline by converting each piece to Bezier form:
/// N >= 4 points, (N-3) * steps + 1 samples. Preconditions: points.size() >= 4, steps >= 1.
CurveSamples evaluate_bspline(std::span<const glm::dvec3> points, int steps, bool planar,
                              const FrameOptions& options = {}, const AdaptiveTolerance& tolerance = {});
/// Control-point curves sampled adaptively (tolerance.adaptive()) keep every joint as a sample
/// and place the others by adaptive_piece_parameters.
/// Evaluates the Catmull-Rom spline through `points` (catmull_rom.hpp): knot spacing |dP|^alpha,
/// tangents scaled by 1 - tension, N - 1 segments, (N - 1) * steps + 1 samples; closed with a C1
/// seam if the last point equals the first (is_closed_interpolating), else reflected ends.
/// Preconditions: points.size() >= 2, steps >= 1, alpha in [0, 1], tension in [0, 1).
CurveSamples evaluate_catmull_rom(std::span<const glm::dvec3> points, int steps, double alpha, double tension,
                                  bool planar, const FrameOptions& options = {},
                                  const AdaptiveTolerance& tolerance = {});
/// Evaluates the Kochanek-Bartels spline through `points` (kochanek_bartels.hpp) with uniform
/// knots, (N - 1) * steps + 1 samples, closed as evaluate_catmull_rom. Where continuity != 0 the
/// tangent jumps at the interior points: they are recorded as corners.
/// Preconditions: points.size() >= 2, steps >= 1, tension, continuity and bias in [-1, 1].
CurveSamples evaluate_kochanek_bartels(std::span<const glm::dvec3> points, int steps, const KochanekBartelsShape& shape,
                                       bool planar, const FrameOptions& options = {},
                                       const AdaptiveTolerance& tolerance = {});
/// Frames of a closed 3D curve are closed (FrameOptions::close_seam): the end frame equals the
/// start frame and the rotation between them is spread along the curve.
/// A counterclockwise circle about the origin in the xy-plane, steps + 1 samples, first = last.
/// Radius 0 is the origin with the circle's tangents and frames (curvature 0), still closed.
/// Preconditions: steps >= 1, radius >= 0.
CurveSamples evaluate_circle(double radius, int steps);

/// A curve as geometry sees it, filled at the edge by whoever owns the curve (the document's
/// kinds: model/evaluation/curve_evaluation.hpp), as OpenSubdiv's TopologyDescriptor is: the points are
/// borrowed, not copied. Fields a basis does not read keep their defaults.
struct CurveDescriptor {
  const CurveBasis* basis = &kBezierBasis;  // kBSplineBasis, kCircleBasis, ... (their headers)
  bool planar = false;                      // in the xy-plane (z of the points is ignored)
  std::span<const glm::dvec3> points;       // the control-point bases
  int steps = 1;                            // samples per cubic piece (circle, knot: in all; helix: per turn)
  double tolerance = 0.0;                   // adaptive sampling within this distance; 0 samples by steps
  double alpha = 0.5;                       // CatmullRom: knot spacing |dP|^alpha
  KochanekBartelsShape spline;              // tension (CatmullRom, KochanekBartels), continuity and bias
  double radius = 0.0;                      // Circle, Helix; TorusKnot: the tube radius r
  double pitch = 0.0;                       // Helix: rise per turn
  double turns = 0.0;                       // Helix
  int knot_p = 0;                           // TorusKnot: turns about the torus axis
  int knot_q = 0;                           // TorusKnot: turns through the hole
  double major_radius = 0.0;                // TorusKnot: R
  /// Helix, TorusKnot: where the curve stands (its basis draws it about the origin; every point
  /// the functions below give is moved by this, frames and derivatives unchanged).
  glm::dvec3 origin{0.0};
};

/// The one definition of a closed curve: its end meets its start, by its basis's rule
/// (CurveBasis::closed). The editor keeps a closed curve closed; evaluation closes its seam.
bool is_closed(const CurveDescriptor& curve);

/// Evaluates any curve: by its steps, or adaptively when `tolerance` is adaptive (every chord
/// within tolerance.distance of the curve, see adaptive.hpp), else when the curve has its own
/// tolerance. Precondition: a curve the SWP reader accepts (point counts, ranges).
CurveSamples evaluate_curve(const CurveDescriptor& curve, const FrameOptions& options = {},
                            const AdaptiveTolerance& tolerance = {});

/// Samples a curve at the given curve parameters (CurveSamples::parameters' units; sorted,
/// within the curve's range), with frames, corners at joints that are among them, and a closed
/// seam when the first and last sample meet. Used to build references denser than a sampling.
CurveSamples evaluate_curve_at(const CurveDescriptor& curve, std::span<const double> parameters,
                               const FrameOptions& options = {});

/// The point of a curve at a curve parameter (CurveSamples::parameters' units).
glm::dvec3 curve_position(const CurveDescriptor& curve, double parameter);
/// The point and its first and second derivatives at a curve parameter, exactly (the basis's
/// derivatives: at a joint of pieces the piece that starts there).
PieceDerivatives curve_derivatives(const CurveDescriptor& curve, double parameter);

/// The curve as the cubic Bezier pieces it is evaluated from (CurveBasis::pieces): exactly its
/// shape, for writers of formats that draw cubics (SVG). Empty for an analytic curve (circle,
/// helix, torus knot). Precondition: a curve the SWP reader accepts.
std::vector<BezierPiece> bezier_pieces(const CurveDescriptor& curve);

/// The box around a curve (lo, hi): its control points, or for a circle, helix or torus knot the
/// box of the exact curve. False for a control-point curve without points.
bool curve_box(const CurveDescriptor& curve, glm::dvec3& lo, glm::dvec3& hi);
/// The diagonal of curve_box (0 without one).
double curve_extent(const CurveDescriptor& curve);

/// True if the first and last samples coincide in position and tangent within a tolerance
/// relative to the curve's size (a closed curve's seam is smooth).
bool is_closed(const std::vector<Frame>& frames);

}  // namespace sweep
