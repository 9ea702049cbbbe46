#pragma once
// SVG's elliptical arc (path command A) as cubic Bezier pieces. The endpoint parameterisation is
// turned into the centre one as in the W3C SVG 1.1 specification, appendix F.6
// ("Elliptical arc implementation notes": F.6.5 the conversion, F.6.6 radii out of range), then the
// arc is cut into equal pieces of at most 90 degrees, each approximated by the cubic whose handles
// have length 4/3 tan(θ/4) times the radius on the unit circle the ellipse is the affine image of.
//
// Tolerance: for a piece of 90 degrees the cubic stays within kArcRelativeError (2.7e-4) of the
// unit circle, so within 2.7e-4 * max(rx, ry) of the ellipse; its end points are exact (the
// arc's start and end points are copied, not recomputed).
#include <glm/vec2.hpp>

#include <optional>
#include <vector>

namespace sweep {

/// Largest angle of one cubic piece, in radians (90 degrees).
inline constexpr double kArcMaxPieceAngle = 1.5707963267948966;
/// Largest distance of a 90-degree piece from the unit circle (the exact value is 2.725e-4).
inline constexpr double kArcRelativeError = 2.8e-4;

/// An SVG arc in its endpoint form: from `from` to `to` on the ellipse of radii (rx, ry) whose x
/// axis is turned by `x_axis_degrees`; the large-arc and sweep flags as in the path data.
struct EndpointArc {
  glm::dvec2 from{0.0};
  glm::dvec2 to{0.0};
  double rx = 0.0;
  double ry = 0.0;
  double x_axis_degrees = 0.0;
  bool large_arc = false;
  bool sweep = false;
};

/// The same arc in its centre form: the point at angle t is centre + R(phi) (rx cos t, ry sin t),
/// t running from start_angle by delta_angle (positive: the sweep flag's direction, +y of SVG).
struct CentreArc {
  glm::dvec2 centre{0.0};
  double rx = 0.0;
  double ry = 0.0;
  double phi = 0.0;  // radians
  double start_angle = 0.0;
  double delta_angle = 0.0;
};

/// F.6.5 with F.6.6: radii taken as absolute values and scaled up if too small to reach `to`.
/// nullopt when F.6.2 says the arc is no ellipse: `from` equals `to` (the arc is omitted) or a
/// radius is 0 (a straight line), and when the radii are so unequal that the centre form
/// overflows (rx 1, ry 1e-308: an ellipse thinner than rounding, so a straight line too).
/// Precondition: finite inputs.
std::optional<CentreArc> centre_arc(const EndpointArc& arc);

/// The point of `arc` at angle t.
glm::dvec2 point_on(const CentreArc& arc, double t);

/// The cubic Bezier control points of the arc after its start point: 3 per piece, pieces of at
/// most kArcMaxPieceAngle, the last point exactly `arc.to`. A straight line (zero radius) is one
/// cubic with its handles at 1/3 and 2/3; an omitted arc (from == to) gives no point.
std::vector<glm::dvec2> arc_to_cubics(const EndpointArc& arc);

}  // namespace sweep
