#pragma once
// The objects of an SWP document. Each kind is one type below: it holds exactly that kind's data,
// compares by defaulted equality, and declares what the kind is (its `traits`: keyword, family,
// planarity, how its points are edited, its label) and how it is sampled. The reader, writer,
// messages, editor and panels read a kind from here (docs/architecture.md, "Adding a kind").
//
// Data several kinds share with one meaning is a part (PointsPart, StepsPart, ...): code that
// works on any kind with points asks for the part (`object.find<PointsPart>()`), so it needs no
// list of kinds. An Object is a name, where it was read, the editor's id, and one kind's data.
#include "geometry/bezier.hpp"
#include "geometry/catmull_rom.hpp"
#include "geometry/circle.hpp"
#include "geometry/curve_basis.hpp"
#include "geometry/helix.hpp"
#include "geometry/kochanek_bartels.hpp"
#include "geometry/polyline.hpp"
#include "geometry/torus_knot.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

namespace sweep {

/// In the order of the alternatives of Payload (below), which messages follow.
enum class ObjectKind : std::uint8_t {
  Bezier2,              // bez2: piecewise cubic Bezier in the xy-plane
  Bezier3,              // bez3
  BSpline2,             // bsp2: uniform cubic B-spline in the xy-plane
  BSpline3,             // bsp3
  Circle,               // circ: counterclockwise circle about the origin in the xy-plane
  CatmullRom2,          // cr2: Catmull-Rom spline through its points, in the xy-plane
  CatmullRom3,          // cr3
  KochanekBartels2,     // kb2: Kochanek-Bartels (tension, continuity, bias) spline, in the xy-plane
  KochanekBartels3,     // kb3
  Helix,                // helix: about +z from (radius, 0, 0), counterclockwise seen from +z
  TorusKnot,            // knot: the (P, Q) torus knot on the torus of radii R > r
  Polyline2,            // poly2: straight segments through its points, every interior point a corner
  Polyline3,            // poly3
  SurfaceOfRevolution,  // srev
  GeneralizedCylinder,  // gcyl
  Birail,               // birail: a 2D profile swept along two rails (birail.hpp)
  BezierPatch,          // bezpatch: bicubic Bezier patches, 16 points each, welded into one surface (patch.hpp)
  BSplinePatch,         // bsppatch: a uniform bicubic B-spline surface of M rows of N points (patch.hpp)
  PolygonMesh,          // mesh: a polygon control cage, points and faces (subdivision.hpp)
  Subdivision,          // subd: the limit surface of a cage refined LEVELS times (subdivision.hpp)
  Material,             // material: colour, shininess, texture or checker, bump (material.hpp)
};

/// What an object is: every object is exactly one of them.
enum class KindFamily : std::uint8_t { Curve, Surface, Material };
/// How a kind's points are edited: none, a curve's control points (moved, inserted, deleted), or a
/// surface's fixed net (moved only).
enum class PointRole : std::uint8_t { None, ControlPoints, Net };

/// What a kind is as a whole, declared by each kind type as `traits`.
struct KindTraits {
  std::string_view keyword;  // in the SWP file, lower case
  KindFamily family;
  bool planar;  // curves in the xy-plane (2D points)
  PointRole points;
  bool interpolating;      // through its points (cr, kb, poly): closed when the last point equals the first
  bool steps;              // sampled by a STEPS the user sets (not: polylines; surfaces but srev, patches)
  std::string_view label;  // for people: "B-spline (2D)", "surface of revolution"
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
/// Curves: segments per cubic piece (circle, knot: in all; helix: per turn); srev: copies about
/// the axis; patches: segments per patch side.
struct StepsPart {
  int steps = 0;
  bool operator==(const StepsPart&) const = default;
};
/// Every curve's optional clause: sample so that every chord stays within this distance of the
/// curve (adaptive.hpp) instead of by STEPS; 0 (the default) samples by STEPS.
struct TolerancePart {
  double tolerance = 0.0;
  bool operator==(const TolerancePart&) const = default;
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

// ---- The kinds, in the order of ObjectKind ----

template <int Dim>
struct BezierCurve : PointsPart, StepsPart, TolerancePart {
  static constexpr KindTraits traits{Dim == 2 ? "bez2" : "bez3",
                                     KindFamily::Curve,
                                     Dim == 2,
                                     PointRole::ControlPoints,
                                     false,
                                     true,
                                     Dim == 2 ? "Bezier (2D)" : "Bezier (3D)"};
  static constexpr const CurveBasis* basis = &kBezierBasis;
  static constexpr std::int64_t pieces(std::int64_t count) {
    return count >= 4 && (count - 1) % 3 == 0 ? (count - 1) / 3 : 0;
  }
  bool operator==(const BezierCurve&) const = default;
};

template <int Dim>
struct BSplineCurve : PointsPart, StepsPart, TolerancePart {
  static constexpr KindTraits traits{Dim == 2 ? "bsp2" : "bsp3",
                                     KindFamily::Curve,
                                     Dim == 2,
                                     PointRole::ControlPoints,
                                     false,
                                     true,
                                     Dim == 2 ? "B-spline (2D)" : "B-spline (3D)"};
  static constexpr const CurveBasis* basis = &kBSplineBasis;
  static constexpr std::int64_t pieces(std::int64_t count) { return count >= 4 ? count - 3 : 0; }
  bool operator==(const BSplineCurve&) const = default;
};

struct CircleCurve : RadiusPart, StepsPart, TolerancePart {
  static constexpr KindTraits traits{"circ", KindFamily::Curve, true, PointRole::None, false, true, "circle"};
  static constexpr const CurveBasis* basis = &kCircleBasis;
  std::int64_t sample_count() const { return std::int64_t{steps} + 1; }
  bool operator==(const CircleCurve&) const = default;
};

template <int Dim>
struct CatmullRomCurve : PointsPart, StepsPart, TolerancePart, AlphaPart, TensionPart {
  static constexpr KindTraits traits{Dim == 2 ? "cr2" : "cr3",
                                     KindFamily::Curve,
                                     Dim == 2,
                                     PointRole::ControlPoints,
                                     true,
                                     true,
                                     Dim == 2 ? "Catmull-Rom (2D)" : "Catmull-Rom (3D)"};
  static constexpr const CurveBasis* basis = &kCatmullRomBasis;
  static constexpr std::int64_t pieces(std::int64_t count) { return segments_through(count); }
  bool operator==(const CatmullRomCurve&) const = default;
};

template <int Dim>
struct KochanekBartelsCurve : PointsPart, StepsPart, TolerancePart, TensionPart, ContinuityBiasPart {
  static constexpr KindTraits traits{Dim == 2 ? "kb2" : "kb3",
                                     KindFamily::Curve,
                                     Dim == 2,
                                     PointRole::ControlPoints,
                                     true,
                                     true,
                                     Dim == 2 ? "Kochanek-Bartels (2D)" : "Kochanek-Bartels (3D)"};
  static constexpr const CurveBasis* basis = &kKochanekBartelsBasis;
  static constexpr std::int64_t pieces(std::int64_t count) { return segments_through(count); }
  bool operator==(const KochanekBartelsCurve&) const = default;
};

/// About +z from (radius, 0, 0), rising `pitch` per turn (negative descends), `turns` > 0 turns.
struct HelixCurve : RadiusPart, StepsPart, TolerancePart {
  static constexpr KindTraits traits{"helix", KindFamily::Curve, false, PointRole::None, false, true, "helix"};
  static constexpr const CurveBasis* basis = &kHelixBasis;
  double pitch = 0.0;
  double turns = 0.0;
  std::int64_t sample_count() const { return helix_sample_count(steps, turns); }
  bool operator==(const HelixCurve&) const = default;
};

/// The (knot_p, knot_q) torus knot: knot_p turns about the torus axis, knot_q through the hole,
/// on the torus of radii major_radius (R) > radius (r).
struct TorusKnotCurve : RadiusPart, StepsPart, TolerancePart {
  static constexpr KindTraits traits{"knot", KindFamily::Curve, false, PointRole::None, false, true, "torus knot"};
  static constexpr const CurveBasis* basis = &kTorusKnotBasis;
  int knot_p = 0;
  int knot_q = 0;
  double major_radius = 0.0;
  std::int64_t sample_count() const { return std::int64_t{steps} + 1; }
  bool operator==(const TorusKnotCurve&) const = default;
};

/// Straight segments through the points, one sample per point: no STEPS, and a tolerance is
/// accepted and changes nothing.
template <int Dim>
struct PolylineCurve : PointsPart, TolerancePart {
  static constexpr KindTraits traits{Dim == 2 ? "poly2" : "poly3",
                                     KindFamily::Curve,
                                     Dim == 2,
                                     PointRole::ControlPoints,
                                     true,
                                     false,
                                     Dim == 2 ? "polyline (2D)" : "polyline (3D)"};
  static constexpr const CurveBasis* basis = &kPolylineBasis;
  static constexpr std::int64_t pieces(std::int64_t count) { return segments_through(count); }
  std::int64_t sample_count() const { return static_cast<std::int64_t>(points.size()); }
  bool operator==(const PolylineCurve&) const = default;
};

/// The profile turned `steps` times about the y-axis.
struct RevolutionSurface : ProfilePart, StepsPart, CapsPart, MaterialPart {
  static constexpr KindTraits traits{"srev", KindFamily::Surface,    false, PointRole::None, false,
                                     true,   "surface of revolution"};
  bool operator==(const RevolutionSurface&) const = default;
};

/// The profile swept along `sweep`, with the optional clauses of sweep_controls.hpp: `scale
/// CURVE` and `twist DEGREES` or `twist CURVE` (2D curves read as graphs over the sweep's arc
/// length) and `caps`.
struct CylinderSurface : ProfilePart, CapsPart, MaterialPart {
  static constexpr KindTraits traits{"gcyl", KindFamily::Surface,   false, PointRole::None, false,
                                     false,  "generalized cylinder"};
  int sweep = -1;        // index of the sweep curve
  int scale = -1;        // -1: none
  int twist_curve = -1;  // -1: none (then `twist` degrees, growing linearly)
  double twist = 0.0;
  bool operator==(const CylinderSurface&) const = default;
};

/// A 2D profile swept along two rails (birail.hpp); `height` scales only along the profile's
/// chord.
struct BirailSurface : ProfilePart, MaterialPart {
  static constexpr KindTraits traits{"birail", KindFamily::Surface, false, PointRole::None, false,
                                     false,    "birail surface"};
  int rail1 = -1;  // RAIL1
  int rail2 = -1;  // RAIL2
  bool height = false;
  bool operator==(const BirailSurface&) const = default;
};

/// Bicubic Bezier patches of 16 points each (row by row), `steps` segments per patch side.
struct BezierPatchSurface : PointsPart, StepsPart, MaterialPart {
  static constexpr KindTraits traits{"bezpatch", KindFamily::Surface, false, PointRole::Net, false,
                                     true,       "Bezier patches"};
  bool operator==(const BezierPatchSurface&) const = default;
};

/// A uniform bicubic B-spline surface of `rows` rows of `columns` points.
struct BSplinePatchSurface : PointsPart, StepsPart, MaterialPart {
  static constexpr KindTraits traits{"bsppatch", KindFamily::Surface, false, PointRole::Net, false,
                                     true,       "B-spline patch"};
  int rows = 0;
  int columns = 0;
  bool operator==(const BSplinePatchSurface&) const = default;
};

/// A polygon control cage: face f has face_sizes[f] vertices, listed in face_vertices after
/// those of the faces before it (0-based indices into `points`, counterclockwise seen from
/// outside).
struct PolygonMeshSurface : PointsPart, MaterialPart {
  static constexpr KindTraits traits{"mesh", KindFamily::Surface, false, PointRole::Net, false, false, "polygon mesh"};
  std::vector<int> face_sizes;
  std::vector<int> face_vertices;
  bool operator==(const PolygonMeshSurface&) const = default;
};

/// The limit surface of `source` (an earlier mesh or grid surface) refined `levels` times;
/// Loop instead of Catmull-Clark, smooth boundary corners.
struct SubdivisionSurface : MaterialPart {
  static constexpr KindTraits traits{"subd", KindFamily::Surface,  false, PointRole::None, false,
                                     false,  "subdivision surface"};
  int levels = 0;
  int source = -1;
  bool loop = false;
  bool smooth_boundary = false;
  bool operator==(const SubdivisionSurface&) const = default;
};

/// A material: colour (0-1 each), shininess, a texture (PNG path as written, relative to the SWP
/// file) or an N x N checker (0: none), a bump (height PNG) and its height in model units.
struct MaterialLook {
  static constexpr KindTraits traits{"material", KindFamily::Material, false, PointRole::None, false, false,
                                     "material"};
  glm::dvec3 color{kDefaultColor[0], kDefaultColor[1], kDefaultColor[2]};
  double shininess = kDefaultShininess;
  std::string texture;
  int checker = 0;
  std::string bump;
  double bump_height = 0.0;
  bool operator==(const MaterialLook&) const = default;
};

/// One kind's data; the alternative's index is its ObjectKind.
using Payload =
    std::variant<BezierCurve<2>, BezierCurve<3>, BSplineCurve<2>, BSplineCurve<3>, CircleCurve, CatmullRomCurve<2>,
                 CatmullRomCurve<3>, KochanekBartelsCurve<2>, KochanekBartelsCurve<3>, HelixCurve, TorusKnotCurve,
                 PolylineCurve<2>, PolylineCurve<3>, RevolutionSurface, CylinderSurface, BirailSurface,
                 BezierPatchSurface, BSplinePatchSurface, PolygonMeshSurface, SubdivisionSurface, MaterialLook>;
static_assert(std::variant_size_v<Payload> == static_cast<std::size_t>(ObjectKind::Material) + 1,
              "one Payload alternative per ObjectKind, in the enumerators' order");

/// A visitor of one lambda per kind type (std::visit), as in the std::visit examples.
template <typename... Functions>
struct Overloaded : Functions... {
  using Functions::operator()...;
};
template <typename... Functions>
Overloaded(Functions...) -> Overloaded<Functions...>;

/// Curves by control points with STEPS per piece: bez, bsp, cr, kb.
template <typename Kind>
concept SteppedPointCurve =
    Kind::traits.family == KindFamily::Curve&& std::is_base_of_v<PointsPart, Kind>&& std::is_base_of_v<StepsPart, Kind>;

/// The default data of `kind`.
Payload make_payload(ObjectKind kind);

/// Where something was read from; line and column are 1-based, 0 when not from a file.
struct SourceLocation {
  int line = 0;
  int column = 0;
  bool operator==(const SourceLocation&) const = default;
};

namespace detail {
/// A failed Object::as (SWEEP_EXPECTS in checked builds; nothing otherwise).
[[noreturn]] void wrong_part(ObjectKind kind, const char* file, int line);
}  // namespace detail

/// One curve, surface or material: a name, where it was read, the editor's id, and its kind's data.
struct Object {
  std::string name;  // empty for an anonymous object ('.' in the file)
  Payload data;
  SourceLocation location;  // of the keyword; ignored by ==
  /// Identity given by the editor (src/editor), kept through edits, undo and redo because it
  /// travels with the object; 0 until the editor assigns one. Never written; ignored by ==.
  std::uint64_t id = 0;

  Object() = default;
  explicit Object(ObjectKind kind) : data(make_payload(kind)) {}
  template <typename Kind>
  requires(!std::is_same_v<std::decay_t<Kind>, Object> &&
           !std::is_same_v<std::decay_t<Kind>, ObjectKind>) explicit Object(Kind&& kind_data)
      : data(std::forward<Kind>(kind_data)) {}

  ObjectKind kind() const { return static_cast<ObjectKind>(data.index()); }
  /// Replaces the data by the default data of `kind` (the name, location and id stay).
  void set_kind(ObjectKind kind) { data = make_payload(kind); }

  /// The data as `Part` (a part or a kind type), or nullptr if this kind has none.
  template <typename Part>
  Part* find() {
    return std::visit(
        [](auto& kind_data) -> Part* {
          if constexpr (std::is_base_of_v<Part, std::decay_t<decltype(kind_data)>>) {
            return &kind_data;
          } else {
            return nullptr;
          }
        },
        data);
  }
  template <typename Part>
  const Part* find() const {
    return const_cast<Object*>(this)->find<Part>();
  }
  /// The data as `Part`. Precondition: this kind has it (find<Part>() is not null); checked
  /// always, since a wrong kind's data has no meaningful value: the program stops, naming the
  /// caller.
  template <typename Part>
  Part& as(const char* file = __builtin_FILE(), int line = __builtin_LINE()) {
    if (Part* part = find<Part>()) return *part;
    detail::wrong_part(kind(), file, line);
  }
  template <typename Part>
  const Part& as(const char* file = __builtin_FILE(), int line = __builtin_LINE()) const {
    return const_cast<Object*>(this)->as<Part>(file, line);
  }

  /// Name and data; where it was read and the editor's id are not part of what an object is.
  bool operator==(const Object& other) const { return name == other.name && data == other.data; }
};

}  // namespace sweep
