#pragma once
// How a curve is defined, as geometry sees it: a basis is one table of operations, defined in its
// own file (bezier_curve.cpp, catmull_rom.cpp, circle.cpp, ...). CurveDescriptor (curve.hpp) names
// its basis; evaluate_curve and its siblings call through the table, so a new basis is a new file
// and no switch elsewhere (docs/architecture.md, "Adding a kind").
#include "geometry/curves/adaptive.hpp"
#include "geometry/curves/bezier.hpp"
#include "geometry/curves/frames.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <string_view>
#include <vector>

namespace sweep {

struct CurveDescriptor;
struct CurveSamples;

/// The 4 control points of a cubic Bezier piece.
using BezierPiece = std::array<glm::dvec3, 4>;

/// The operations of one way of defining a curve. Every entry is set; each takes a descriptor of
/// this basis that the SWP reader accepts (point counts, ranges).
struct CurveBasis {
  std::string_view name;  // "Bezier", for messages and tests
  /// Defined by control points (curve_box is the box of the points) rather than analytically.
  bool control_points = false;
  /// Samples by the curve's steps, or adaptively when `tolerance` is adaptive (already resolved
  /// against the curve's own tolerance by evaluate_curve).
  CurveSamples (*evaluate)(const CurveDescriptor& curve, const FrameOptions& options,
                           const AdaptiveTolerance& tolerance) = nullptr;
  /// Samples at curve parameters (sorted, within the curve's range), as evaluate_curve_at.
  CurveSamples (*evaluate_at)(const CurveDescriptor& curve, std::span<const double> parameters,
                              const FrameOptions& options) = nullptr;
  /// The point at a curve parameter.
  glm::dvec3 (*position)(const CurveDescriptor& curve, double parameter) = nullptr;
  /// The box of an analytic curve's exact shape; unused (null) for control-point bases.
  void (*exact_box)(const CurveDescriptor& curve, glm::dvec3& lo, glm::dvec3& hi) = nullptr;
  /// The one definition of a closed curve of this basis: its end meets its start. For control
  /// points it is a rule on the points (the editor keeps it while points move); analytic curves
  /// decide by their shape. is_closed (curve.hpp) asks this.
  bool (*closed)(const CurveDescriptor& curve) = nullptr;
  /// The point and its first and second derivatives by the curve parameter (d3 unused), exactly:
  /// at a joint of pieces (a whole parameter) the piece that starts there; at the end the last.
  PieceDerivatives (*derivatives)(const CurveDescriptor& curve, double parameter) = nullptr;
  /// The curve as the cubic Bezier pieces it is evaluated from: piece k covers the curve
  /// parameters k..k+1 and starts where piece k - 1 ends (z = 0 for a planar curve). Null for the
  /// analytic bases (circle, helix, torus knot), which have no pieces; bezier_pieces (curve.hpp)
  /// asks this.
  std::vector<BezierPiece> (*pieces)(const CurveDescriptor& curve) = nullptr;
  /// The pieces are straight, from point k to point k + 1 (a polyline): a writer may draw lines.
  bool straight = false;
};

/// The rule every control-point basis closes by: the last `repeats` points repeat the first
/// `repeats` (point n - repeats + i is point i), exactly or within 1e-9 times the size of the
/// box of the first and last max(repeats, 2) points (a lower bound of the curve's size, so the
/// test is O(1) and never looser than one relative to the whole curve). False with fewer than
/// `minimum` points. Precondition: finite points.
bool ends_repeat(std::span<const glm::dvec3> points, std::size_t repeats, std::size_t minimum);

/// Samples an analytic curve at curve parameters through its point function (position and
/// derivatives by the parameter): the evaluate_at of the analytic bases.
CurveSamples sample_analytic(const CurveDescriptor& curve, std::span<const double> parameters,
                             const FrameOptions& options, PieceDerivatives (*point)(const CurveDescriptor&, double));

}  // namespace sweep
