#pragma once
// What the kinds of object.hpp are made of: the traits each kind declares, and the parts, data
// that several kinds share with one meaning each (PointsPart, StepsPart, ...). Code that works on
// any kind with points asks for the part (`object.find<PointsPart>()`), so it needs no list of
// kinds.
#include "model/kinds/point_layout.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <string_view>
#include <vector>

namespace sweep {

/// What an object is: every object is exactly one of them.
enum class KindFamily : std::uint8_t { Curve, Surface, Material, Rider };

/// What a kind is as a whole, declared by each kind type as `traits`.
struct KindTraits {
  std::string_view keyword;  // in the SWP file, lower case
  KindFamily family;
  bool planar;              // curves in the xy-plane (2D points)
  PointLayout points;       // how its points are laid out and edited (point_layout.hpp)
  bool interpolating;       // through its points (cr, kb, poly): closed when the last point equals the first
  bool steps;               // sampled by a STEPS the user sets (not: polylines; surfaces but srev, patches)
  std::string_view label;   // for people: "B-spline (2D)", "surface of revolution"
  std::string_view phrase;  // in a sentence: "a B-spline", "a polyline", "a surface of revolution"
};

/// A fixed number field's name: in the reader's messages ("torus radius R") and as the editor's
/// parameter (CurveParameter's name: "R"); one name serves both for most fields.
struct FieldName {
  std::string_view role;
  std::string_view parameter;
  constexpr FieldName(const char* both) : role(both), parameter(both) {}
  constexpr FieldName(const char* message_role, const char* parameter_name)
      : role(message_role), parameter(parameter_name) {}
};

/// The optional clauses' defaults (a clause equal to its default is not written).
inline constexpr double kDefaultAlpha = 0.5;  // centripetal Catmull-Rom
/// A material's colour and shininess when not given (the viewer's default look).
inline constexpr double kDefaultColor[3] = {0.62, 0.68, 0.80};
inline constexpr double kDefaultShininess = 48.0;

// ---- Parts: data that several kinds share, with one meaning each ----

/// Control points: z is 0 for planar curves; patches: row by row; a mesh: its vertices.
struct PointsPart {
  std::vector<glm::dvec3> points;
  bool operator==(const PointsPart&) const = default;
};
/// Curves: segments per cubic piece (circle, knot: in all; helix: per turn); patches: segments
/// per patch side.
struct StepsPart {
  int steps = 0;
  bool operator==(const StepsPart&) const = default;
};
/// srev: copies of the profile about the y-axis (the number its file line writes as STEPS).
struct CopiesPart {
  int copies = 0;
  bool operator==(const CopiesPart&) const = default;
};
/// Every curve's optional clause: sample so that every chord stays within this distance of the
/// curve (adaptive.hpp) instead of by STEPS; 0 (the default) samples by STEPS.
struct TolerancePart {
  double tolerance = 0.0;
  bool operator==(const TolerancePart&) const = default;
};
/// Helix and torus knot: where the curve stands, its optional `at X Y Z` clause (the course's
/// curves stand about the origin: (0, 0, 0), the default, is not written).
struct PlacePart {
  glm::dvec3 at{0.0};
  bool operator==(const PlacePart&) const = default;
};
/// Circle and helix: the radius; torus knot: the tube radius r.
struct RadiusPart {
  double radius = 0.0;
  bool operator==(const RadiusPart&) const = default;
};
/// cr and kb: tangents scaled by 1 - tension (cr: [0, 1), kb: [-1, 1]).
struct TensionPart {
  double tension = 0.0;
  bool operator==(const TensionPart&) const = default;
};
/// cr: knot spacing |dP|^alpha.
struct AlphaPart {
  double alpha = kDefaultAlpha;
  bool operator==(const AlphaPart&) const = default;
};
/// kb: continuity and bias, each in [-1, 1].
struct ContinuityBiasPart {
  double continuity = 0.0;
  double bias = 0.0;
  bool operator==(const ContinuityBiasPart&) const = default;
};
/// srev, gcyl, birail: the index of the profile curve in Document::objects.
struct ProfilePart {
  int profile = -1;
  bool operator==(const ProfilePart&) const = default;
};
/// srev and gcyl's `caps`: close the ends into a solid.
struct CapsPart {
  bool caps = false;
  bool operator==(const CapsPart&) const = default;
};
/// Every surface: the index of its `material` (-1: the default look).
struct MaterialPart {
  int material = -1;
  bool operator==(const MaterialPart&) const = default;
};

/// Cubic pieces of `count` points, for the kinds through their points (cr, kb, poly).
constexpr std::int64_t segments_through(std::int64_t count) {
  return count >= 2 ? count - 1 : 0;
}

}  // namespace sweep
