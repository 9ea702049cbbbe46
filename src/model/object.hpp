#pragma once
// The objects of an SWP document. Each kind is one type below: it holds exactly that kind's data
// (parts.hpp), compares by defaulted equality, and declares in one place what the kind is (its
// `traits`: keyword, family, planarity, how its points are edited, its names for people), how it
// is sampled (its geometry basis), its syntax (`fields`, read and written from that one list) and
// its clauses (kind_clauses). The reader, writer, messages, editor and panels read a kind from
// here (docs/architecture.md, "Adding a kind"). An Object is a name, where it was read, the
// editor's id, and one kind's data.
#include "geometry/bezier.hpp"
#include "geometry/catmull_rom.hpp"
#include "geometry/circle.hpp"
#include "geometry/curve_basis.hpp"
#include "geometry/helix.hpp"
#include "geometry/kochanek_bartels.hpp"
#include "geometry/polyline.hpp"
#include "geometry/torus_knot.hpp"
#include "model/clause.hpp"
#include "model/curve_parameters.hpp"
#include "model/parts.hpp"

#include <glm/vec3.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
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

// ---- The kinds, in the order of ObjectKind ----
//
// Each kind's `fields(self, f)` lists its fixed fields after the name, in file order, to a
// visitor: the SWP reader reads them and the writer writes them from this one list, so a kind's
// syntax is written once. A visitor has:
//   f.steps(steps)                      STEPS, a whole number from 1 to limits::kMaxSteps
//   f.points(self, what)                a point count (`what`: "a control point count") checked by
//                                       Kind::count_problem and the caps, then the clauses and the
//                                       points (the last field)
//   f.samples(n)                        the curve's sample count against the caps, reported at STEPS
//   f.samples_by(n, field)              the same, given by STEPS and the field just read (TURNS)
//   f.number(name, value[, check])      a number; check() is "" or the "expected ..." text; the
//                                       editor's parameter of that name (FieldName, parts.hpp)
//   f.integer(name, value, low, high[, check])
//   f.reference(role, index, planar)    the name of a curve defined above
//   f.vertices(at)                      the surface's vertices (caps.hpp) against the caps
//   f.custom(self)                      a syntax of its own (patches, cages, subd, material)
// and `kind_clauses<Kind>` beside each kind lists its optional clauses (clause.hpp).

/// Where a surface's vertex count is reported: at its STEPS or at its keyword.
enum class VerticesAt : std::uint8_t { Steps, Keyword };

/// "expected at least 2 Catmull-Rom control points" for too few points of a kind through them.
std::string interpolating_count_problem(std::int64_t count, const char* family);

template <int Dim>
struct BezierCurve : PointsPart, StepsPart, TolerancePart {
  static constexpr KindTraits traits{.keyword = Dim == 2 ? "bez2" : "bez3",
                                     .family = KindFamily::Curve,
                                     .planar = Dim == 2,
                                     .points = PointRole::ControlPoints,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = Dim == 2 ? "Bezier (2D)" : "Bezier (3D)",
                                     .phrase = "a Bezier curve"};
  static constexpr const CurveBasis* basis = &kBezierBasis;
  static constexpr std::int64_t pieces(std::int64_t count) {
    return count >= 4 && (count - 1) % 3 == 0 ? (count - 1) / 3 : 0;
  }
  static std::string count_problem(std::int64_t count) {
    return pieces(count) > 0 ? "" : "expected a Bezier control point count of the form 3n+1 (4, 7, 10, ...)";
  }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.points(self, "a control point count");
  }
  bool operator==(const BezierCurve&) const = default;
};
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<BezierCurve<Dim>> = swp_clause_checks::kCurve;

template <int Dim>
struct BSplineCurve : PointsPart, StepsPart, TolerancePart {
  static constexpr KindTraits traits{.keyword = Dim == 2 ? "bsp2" : "bsp3",
                                     .family = KindFamily::Curve,
                                     .planar = Dim == 2,
                                     .points = PointRole::ControlPoints,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = Dim == 2 ? "B-spline (2D)" : "B-spline (3D)",
                                     .phrase = "a B-spline"};
  static constexpr const CurveBasis* basis = &kBSplineBasis;
  static constexpr std::int64_t pieces(std::int64_t count) { return count >= 4 ? count - 3 : 0; }
  static std::string count_problem(std::int64_t count) {
    return count >= 4 ? "" : "expected at least 4 B-spline control points";
  }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.points(self, "a control point count");
  }
  bool operator==(const BSplineCurve&) const = default;
};
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<BSplineCurve<Dim>> = swp_clause_checks::kCurve;

struct CircleCurve : RadiusPart, StepsPart, TolerancePart {
  static constexpr KindTraits traits{.keyword = "circ",
                                     .family = KindFamily::Curve,
                                     .planar = true,
                                     .points = PointRole::None,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = "circle",
                                     .phrase = "a circle"};
  static constexpr const CurveBasis* basis = &kCircleBasis;
  std::int64_t sample_count() const { return std::int64_t{steps} + 1; }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.samples(std::int64_t{self.steps} + 1);
    f.number("radius", self.radius, [&self] { return check_circle_radius(self.radius); });
  }
  bool operator==(const CircleCurve&) const = default;
};
template <>
inline constexpr std::span<const SwpClause> kind_clauses<CircleCurve> = swp_clause_checks::kCurve;

template <int Dim>
struct CatmullRomCurve : PointsPart, StepsPart, TolerancePart, AlphaPart, TensionPart {
  static constexpr KindTraits traits{.keyword = Dim == 2 ? "cr2" : "cr3",
                                     .family = KindFamily::Curve,
                                     .planar = Dim == 2,
                                     .points = PointRole::ControlPoints,
                                     .interpolating = true,
                                     .steps = true,
                                     .label = Dim == 2 ? "Catmull-Rom (2D)" : "Catmull-Rom (3D)",
                                     .phrase = "a Catmull-Rom curve"};
  static constexpr const CurveBasis* basis = &kCatmullRomBasis;
  static constexpr std::int64_t pieces(std::int64_t count) { return segments_through(count); }
  static std::string count_problem(std::int64_t count) { return interpolating_count_problem(count, "Catmull-Rom"); }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.points(self, "a control point count");
  }
  bool operator==(const CatmullRomCurve&) const = default;
};
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<CatmullRomCurve<Dim>> = swp_clause_checks::kCatmullRom;

template <int Dim>
struct KochanekBartelsCurve : PointsPart, StepsPart, TolerancePart, TensionPart, ContinuityBiasPart {
  static constexpr KindTraits traits{.keyword = Dim == 2 ? "kb2" : "kb3",
                                     .family = KindFamily::Curve,
                                     .planar = Dim == 2,
                                     .points = PointRole::ControlPoints,
                                     .interpolating = true,
                                     .steps = true,
                                     .label = Dim == 2 ? "Kochanek-Bartels (2D)" : "Kochanek-Bartels (3D)",
                                     .phrase = "a Kochanek-Bartels curve"};
  static constexpr const CurveBasis* basis = &kKochanekBartelsBasis;
  static constexpr std::int64_t pieces(std::int64_t count) { return segments_through(count); }
  static std::string count_problem(std::int64_t count) {
    return interpolating_count_problem(count, "Kochanek-Bartels");
  }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.points(self, "a control point count");
  }
  bool operator==(const KochanekBartelsCurve&) const = default;
};
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<KochanekBartelsCurve<Dim>> =
    swp_clause_checks::kKochanekBartels;

/// About +z from (radius, 0, 0), rising `pitch` per turn (negative descends), `turns` > 0 turns.
struct HelixCurve : RadiusPart, StepsPart, TolerancePart {
  static constexpr KindTraits traits{.keyword = "helix",
                                     .family = KindFamily::Curve,
                                     .planar = false,
                                     .points = PointRole::None,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = "helix",
                                     .phrase = "a helix"};
  static constexpr const CurveBasis* basis = &kHelixBasis;
  double pitch = 0.0;
  double turns = 0.0;
  std::int64_t sample_count() const { return helix_sample_count(steps, turns); }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.number("radius", self.radius, [&self] { return check_radius(self.radius); });
    f.number("pitch", self.pitch);
    f.number("turns", self.turns, [&self] { return check_turns(self.turns); });
    // ceil(STEPS * TURNS) + 1: TURNS is what makes a helix long, so the error is there. Both are
    // capped (1e5, 1e12), so the product is far from the end of int64.
    f.samples_by(static_cast<std::int64_t>(std::ceil(self.steps * self.turns)) + 1, "TURNS");
  }
  bool operator==(const HelixCurve&) const = default;
};
template <>
inline constexpr std::span<const SwpClause> kind_clauses<HelixCurve> = swp_clause_checks::kCurve;

/// The (knot_p, knot_q) torus knot: knot_p turns about the torus axis, knot_q through the hole,
/// on the torus of radii major_radius (R) > radius (r).
struct TorusKnotCurve : RadiusPart, StepsPart, TolerancePart {
  static constexpr KindTraits traits{.keyword = "knot",
                                     .family = KindFamily::Curve,
                                     .planar = false,
                                     .points = PointRole::None,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = "torus knot",
                                     .phrase = "a torus knot"};
  static constexpr const CurveBasis* basis = &kTorusKnotBasis;
  int knot_p = 0;
  int knot_q = 0;
  double major_radius = 0.0;
  std::int64_t sample_count() const { return std::int64_t{steps} + 1; }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.samples(std::int64_t{self.steps} + 1);
    f.integer("P", self.knot_p, 1, kMaxKnotWinding);
    f.integer("Q", self.knot_q, 1, kMaxKnotWinding, [&self] { return check_knot_pq(self.knot_p, self.knot_q); });
    f.number({"torus radius R", "R"}, self.major_radius);
    f.number({"tube radius r", "radius"}, self.radius,
             [&self] { return check_knot_radii(self.major_radius, self.radius); });
  }
  bool operator==(const TorusKnotCurve&) const = default;
};
template <>
inline constexpr std::span<const SwpClause> kind_clauses<TorusKnotCurve> = swp_clause_checks::kCurve;

/// Straight segments through the points, one sample per point: no STEPS, and a tolerance is
/// accepted and changes nothing.
template <int Dim>
struct PolylineCurve : PointsPart, TolerancePart {
  static constexpr KindTraits traits{.keyword = Dim == 2 ? "poly2" : "poly3",
                                     .family = KindFamily::Curve,
                                     .planar = Dim == 2,
                                     .points = PointRole::ControlPoints,
                                     .interpolating = true,
                                     .steps = false,
                                     .label = Dim == 2 ? "polyline (2D)" : "polyline (3D)",
                                     .phrase = "a polyline"};
  static constexpr const CurveBasis* basis = &kPolylineBasis;
  static constexpr std::int64_t pieces(std::int64_t count) { return segments_through(count); }
  std::int64_t sample_count() const { return static_cast<std::int64_t>(points.size()); }
  static std::string count_problem(std::int64_t count) { return interpolating_count_problem(count, "polyline"); }
  static void fields(auto& self, auto& f) { f.points(self, "a point count"); }
  bool operator==(const PolylineCurve&) const = default;
};
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<PolylineCurve<Dim>> = swp_clause_checks::kCurve;

/// The profile turned `steps` times about the y-axis.
struct RevolutionSurface : ProfilePart, StepsPart, CapsPart, MaterialPart {
  static constexpr KindTraits traits{.keyword = "srev",
                                     .family = KindFamily::Surface,
                                     .planar = false,
                                     .points = PointRole::None,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = "surface of revolution",
                                     .phrase = "a surface of revolution"};
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.reference("profile", self.profile, true);
    f.vertices(VerticesAt::Steps);
  }
  bool operator==(const RevolutionSurface&) const = default;
};
template <>
inline constexpr std::span<const SwpClause> kind_clauses<RevolutionSurface> = swp_clause_checks::kRevolution;

/// The profile swept along `sweep`, with the optional clauses of sweep_controls.hpp: `scale
/// CURVE` and `twist DEGREES` or `twist CURVE` (2D curves read as graphs over the sweep's arc
/// length) and `caps`.
struct CylinderSurface : ProfilePart, CapsPart, MaterialPart {
  static constexpr KindTraits traits{.keyword = "gcyl",
                                     .family = KindFamily::Surface,
                                     .planar = false,
                                     .points = PointRole::None,
                                     .interpolating = false,
                                     .steps = false,
                                     .label = "generalized cylinder",
                                     .phrase = "a generalized cylinder"};
  int sweep = -1;        // index of the sweep curve
  int scale = -1;        // -1: none
  int twist_curve = -1;  // -1: none (then `twist` degrees, growing linearly)
  double twist = 0.0;
  static void fields(auto& self, auto& f) {
    f.reference("profile", self.profile, true);
    f.reference("sweep", self.sweep, false);
    f.vertices(VerticesAt::Keyword);
  }
  bool operator==(const CylinderSurface&) const = default;
};
namespace swp_clause_checks {
inline constexpr SwpClause kCylinder[] = {
    {.key = "scale", .reference = &clause_slot<&CylinderSurface::scale>},
    {.key = "twist",
     .field = &clause_slot<&CylinderSurface::twist>,
     .check = &twist,
     .reference = &clause_slot<&CylinderSurface::twist_curve>},
    kCaps,
    kMaterial,
};
}  // namespace swp_clause_checks
template <>
inline constexpr std::span<const SwpClause> kind_clauses<CylinderSurface> = swp_clause_checks::kCylinder;

/// A 2D profile swept along two rails (birail.hpp); `height` scales only along the profile's
/// chord.
struct BirailSurface : ProfilePart, MaterialPart {
  static constexpr KindTraits traits{.keyword = "birail",
                                     .family = KindFamily::Surface,
                                     .planar = false,
                                     .points = PointRole::None,
                                     .interpolating = false,
                                     .steps = false,
                                     .label = "birail surface",
                                     .phrase = "a birail surface"};
  int rail1 = -1;  // RAIL1
  int rail2 = -1;  // RAIL2
  bool height = false;
  static void fields(auto& self, auto& f) {
    f.reference("profile", self.profile, true);
    f.reference("the first rail", self.rail1, false);
    f.reference("the second rail", self.rail2, false);
    f.vertices(VerticesAt::Keyword);
  }
  bool operator==(const BirailSurface&) const = default;
};
namespace swp_clause_checks {
inline constexpr SwpClause kBirail[] = {{.key = "height", .flag = &clause_slot<&BirailSurface::height>}, kMaterial};
}  // namespace swp_clause_checks
template <>
inline constexpr std::span<const SwpClause> kind_clauses<BirailSurface> = swp_clause_checks::kBirail;

/// Bicubic Bezier patches of 16 points each (row by row), `steps` segments per patch side.
struct BezierPatchSurface : PointsPart, StepsPart, MaterialPart {
  static constexpr KindTraits traits{.keyword = "bezpatch",
                                     .family = KindFamily::Surface,
                                     .planar = false,
                                     .points = PointRole::Net,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = "Bezier patches",
                                     .phrase = "a Bezier patch surface"};
  static void fields(auto& self, auto& f) { f.custom(self); }
  bool operator==(const BezierPatchSurface&) const = default;
};
template <>
inline constexpr std::span<const SwpClause> kind_clauses<BezierPatchSurface> = swp_clause_checks::kNetSurface;

/// A uniform bicubic B-spline surface of `rows` rows of `columns` points.
struct BSplinePatchSurface : PointsPart, StepsPart, MaterialPart {
  static constexpr KindTraits traits{.keyword = "bsppatch",
                                     .family = KindFamily::Surface,
                                     .planar = false,
                                     .points = PointRole::Net,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = "B-spline patch",
                                     .phrase = "a B-spline patch"};
  int rows = 0;
  int columns = 0;
  static void fields(auto& self, auto& f) { f.custom(self); }
  bool operator==(const BSplinePatchSurface&) const = default;
};
template <>
inline constexpr std::span<const SwpClause> kind_clauses<BSplinePatchSurface> = swp_clause_checks::kNetSurface;

/// A polygon control cage: face f has face_sizes[f] vertices, listed in face_vertices after
/// those of the faces before it (0-based indices into `points`, counterclockwise seen from
/// outside).
struct PolygonMeshSurface : PointsPart, MaterialPart {
  static constexpr KindTraits traits{.keyword = "mesh",
                                     .family = KindFamily::Surface,
                                     .planar = false,
                                     .points = PointRole::Net,
                                     .interpolating = false,
                                     .steps = false,
                                     .label = "polygon mesh",
                                     .phrase = "a polygon mesh"};
  std::vector<int> face_sizes;
  std::vector<int> face_vertices;
  static void fields(auto& self, auto& f) { f.custom(self); }
  bool operator==(const PolygonMeshSurface&) const = default;
};
template <>
inline constexpr std::span<const SwpClause> kind_clauses<PolygonMeshSurface> = swp_clause_checks::kNetSurface;

/// The limit surface of `source` (an earlier mesh or grid surface) refined `levels` times;
/// Loop instead of Catmull-Clark, smooth boundary corners.
struct SubdivisionSurface : MaterialPart {
  static constexpr KindTraits traits{.keyword = "subd",
                                     .family = KindFamily::Surface,
                                     .planar = false,
                                     .points = PointRole::None,
                                     .interpolating = false,
                                     .steps = false,
                                     .label = "subdivision surface",
                                     .phrase = "a subdivision surface"};
  int levels = 0;
  int source = -1;
  bool loop = false;
  bool smooth_boundary = false;
  static void fields(auto& self, auto& f) { f.custom(self); }
  bool operator==(const SubdivisionSurface&) const = default;
};
namespace swp_clause_checks {
inline constexpr SwpClause kSubdivision[] = {
    {.key = "loop", .flag = &clause_slot<&SubdivisionSurface::loop>},
    {.key = "smooth-boundary", .flag = &clause_slot<&SubdivisionSurface::smooth_boundary>},
    kMaterial,
};
}  // namespace swp_clause_checks
template <>
inline constexpr std::span<const SwpClause> kind_clauses<SubdivisionSurface> = swp_clause_checks::kSubdivision;

/// A material: colour (0-1 each), shininess, a texture (PNG path as written, relative to the SWP
/// file) or an N x N checker (0: none), a bump (height PNG) and its height in model units.
struct MaterialLook {
  static constexpr KindTraits traits{.keyword = "material",
                                     .family = KindFamily::Material,
                                     .planar = false,
                                     .points = PointRole::None,
                                     .interpolating = false,
                                     .steps = false,
                                     .label = "material",
                                     .phrase = "a material"};
  glm::dvec3 color{kDefaultColor[0], kDefaultColor[1], kDefaultColor[2]};
  double shininess = kDefaultShininess;
  std::string texture;
  int checker = 0;
  std::string bump;
  double bump_height = 0.0;
  static void fields(auto& self, auto& f) { f.custom(self); }
  bool operator==(const MaterialLook&) const = default;
};
/// A material's own clauses take several values (swp_reader_surfaces.cpp, read_material).
template <>
inline constexpr std::span<const SwpClause> kind_clauses<MaterialLook> = {};

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
