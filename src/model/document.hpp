#pragma once
// The SWP document: the objects of a file in file order, as the editor changes and saves them.
#include "geometry/number_text.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sweep {

/// In the order of kinds() (document.cpp), which messages follow.
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

/// Everything that describes a kind as a whole, one row per kind in kKinds (document.cpp): the
/// reader, writer, messages, editor and panels read it there instead of listing kinds again.
struct KindInfo {
  ObjectKind kind;
  std::string_view keyword;  // in the SWP file, lower case
  KindFamily family;
  bool planar;  // curves in the xy-plane (2D points)
  PointRole points;
  bool interpolating;      // through its points (cr, kb, poly): closed when the last point equals the first
  bool steps;              // sampled by a STEPS the user sets (not: polylines; surfaces but srev, patches)
  std::string_view label;  // for people: "B-spline (2D)", "surface of revolution"
};

/// Every kind's row, in the order messages list them (curves, surfaces, then materials).
std::span<const KindInfo> kinds();
/// The row of `kind`.
const KindInfo& kind_info(ObjectKind kind);

/// "bez2, bez3, ..." for the kinds `wanted` accepts.
template <typename Predicate>
inline std::string keyword_list(Predicate wanted) {
  std::string out;
  for (const KindInfo& kind : kinds()) {  // in the order messages list them
    if (!wanted(kind.kind)) continue;
    if (!out.empty()) out += ", ";
    out += kind.keyword;
  }
  return out;
}

/// The optional clauses' defaults (a clause equal to its default is not written).
inline constexpr double kDefaultAlpha = 0.5;  // centripetal Catmull-Rom
/// A material's colour and shininess when not given (the viewer's default look).
inline constexpr double kDefaultColor[3] = {0.62, 0.68, 0.80};
inline constexpr double kDefaultShininess = 48.0;

/// The SWP keyword of a kind, lower case ("bez2", "srev", ...).
std::string_view keyword(ObjectKind kind);
/// The kind of a keyword, case-insensitively; nullopt if it is none.
std::optional<ObjectKind> kind_from_keyword(std::string_view word);

/// Curves, surfaces and materials: every object is exactly one of them.
bool is_curve(ObjectKind kind);
bool is_surface(ObjectKind kind);
bool is_material(ObjectKind kind);
/// True for bez2, bsp2, circ, cr2, kb2 and poly2: curves that lie in the xy-plane.
bool is_planar_curve(ObjectKind kind);
/// True for bez2/bez3/bsp2/bsp3/cr2/cr3/kb2/kb3: curves defined by control points.
bool has_control_points(ObjectKind kind);
/// True for bezpatch, bsppatch and mesh: surfaces defined by a net of 3D control points.
bool has_control_net(ObjectKind kind);
/// Curves with control points and surfaces with a control net: objects whose points one edits.
bool has_editable_points(ObjectKind kind);
/// True for cr2/cr3/kb2/kb3 and poly2/poly3: curves through their points, one segment between
/// consecutive points; closed when the last point equals the first.
bool is_interpolating(ObjectKind kind);

/// Where something was read from; line and column are 1-based, 0 when not from a file.
struct SourceLocation {
  int line = 0;
  int column = 0;
  bool operator==(const SourceLocation&) const = default;
};

/// One curve or surface. Fields that a kind does not use stay at their defaults.
struct Object {
  ObjectKind kind = ObjectKind::Bezier2;
  std::string name;                // empty for an anonymous object ('.' in the file)
  int steps = 0;                   // curves: segments per cubic piece (circle: in all); srev: copies; patches: per
                                   // patch side; subd: LEVELS
  std::vector<glm::dvec3> points;  // control points (patches: row by row; mesh: vertices); z is 0 for planar curves
  int rows = 0;                    // bsppatch: M rows of `columns` points
  int columns = 0;                 // bsppatch: N
  // mesh: face f has face_sizes[f] vertices, listed in face_vertices after those of the faces
  // before it (0-based indices into `points`, counterclockwise seen from outside).
  std::vector<int> face_sizes;
  std::vector<int> face_vertices;
  double radius = 0.0;  // circ, helix; knot: the tube radius r
  // Optional clauses of cr/kb (KEY VALUE after the point count): knot spacing |dP|^alpha (cr),
  // tension (cr: [0, 1), kb: [-1, 1]), continuity and bias (kb, [-1, 1]).
  double alpha = kDefaultAlpha;
  double tension = 0.0;
  double continuity = 0.0;
  double bias = 0.0;
  double pitch = 0.0;         // helix: rise per turn (negative descends)
  double turns = 0.0;         // helix: > 0, not necessarily whole
  int knot_p = 0;             // knot: turns about the torus axis
  int knot_q = 0;             // knot: turns through the torus hole
  double major_radius = 0.0;  // knot: R
  /// Optional clause of every curve: sample so that every chord stays within this distance of the
  /// curve (adaptive.hpp) instead of by STEPS; 0 (the default) samples by STEPS.
  double tolerance = 0.0;
  int profile = -1;  // srev, gcyl, birail: index of the profile curve in Document::objects
  int sweep = -1;    // gcyl: index of the sweep curve; birail: of the first rail (RAIL1)
  int rail2 = -1;    // birail: index of the second rail (RAIL2)
  // Optional clauses of the surfaces (sweep_controls.hpp): gcyl `scale CURVE` and `twist DEGREES`
  // or `twist CURVE` (2D curves read as graphs over the sweep's arc length), gcyl and srev `caps`
  // (close the ends into a solid), birail `height` (scale only along the profile's chord).
  int scale = -1;        // -1: none
  int twist_curve = -1;  // -1: none (then `twist` degrees, growing linearly)
  double twist = 0.0;
  bool caps = false;
  bool height = false;
  int source = -1;  // subd: index of the cage (a mesh) or grid surface it refines
  // Optional clauses of subd: Loop instead of Catmull-Clark; smooth boundary corners.
  bool loop = false;
  bool smooth_boundary = false;
  int material = -1;  // every surface: index of its `material` (-1: the default look)
  // material: colour (0-1 each), shininess, a texture (PNG path as written, relative to the SWP
  // file) or an N x N checker (0: none), a bump (height PNG) and its height in model units.
  glm::dvec3 color{kDefaultColor[0], kDefaultColor[1], kDefaultColor[2]};
  double shininess = kDefaultShininess;
  std::string texture;
  int checker = 0;
  std::string bump;
  double bump_height = 0.0;
  SourceLocation location;  // of the keyword; ignored by ==
  /// Identity given by the editor (src/editor), kept through edits, undo and redo because it
  /// travels with the object; 0 until the editor assigns one. Never written; ignored by ==.
  std::uint64_t id = 0;

  bool operator==(const Object& other) const {
    return kind == other.kind && name == other.name && steps == other.steps && points == other.points &&
           radius == other.radius && profile == other.profile && sweep == other.sweep && alpha == other.alpha &&
           tension == other.tension && continuity == other.continuity && bias == other.bias && pitch == other.pitch &&
           turns == other.turns && knot_p == other.knot_p && knot_q == other.knot_q &&
           major_radius == other.major_radius && tolerance == other.tolerance && rail2 == other.rail2 &&
           scale == other.scale && twist_curve == other.twist_curve && twist == other.twist && caps == other.caps &&
           height == other.height && rows == other.rows && columns == other.columns && face_sizes == other.face_sizes &&
           face_vertices == other.face_vertices && source == other.source && loop == other.loop &&
           smooth_boundary == other.smooth_boundary && material == other.material && color == other.color &&
           shininess == other.shininess && texture == other.texture && checker == other.checker && bump == other.bump &&
           bump_height == other.bump_height;
  }
};

/// The objects `object` refers to (profile, sweep or first rail, second rail, scale, twist
/// curve, subd source, material), -1 where it has none. References always point to earlier
/// objects.
std::array<int, 7> references(const Object& object);
/// The same references as fields to change (an object inserted or erased before them moves
/// them); one list, so no edit can forget one.
std::array<int*, 7> reference_slots(Object& object);

struct Document {
  std::vector<Object> objects;

  /// Index of the object with this name, or -1. Anonymous objects are never found.
  int find(std::string_view name) const;
  bool operator==(const Document&) const = default;
};

/// True for a valid SWP object name: a letter or '_' followed by letters, digits, '_', '-' or
/// '.', at most limits::kMaxNameLength bytes (names become file names on export).
bool is_valid_object_name(std::string_view name);

/// `text` for a message: at most `max_bytes` bytes, control and non-ASCII bytes as \xHH, and
/// "..." when cut, so binary junk in a file never garbles a terminal.
std::string printable_excerpt(std::string_view text, std::size_t max_bytes);

/// A display name: the object's name, or "kind#index" for an anonymous one.
std::string display_name(const Document& doc, int index);

/// Number of cubic pieces of a control-point curve with `count` points (0 if too few; cr/kb:
/// count - 1 segments).
std::int64_t piece_count(ObjectKind kind, std::int64_t count);
/// Number of samples a curve evaluates to (pieces * steps + 1; circle and knot: steps + 1;
/// helix: ceil(steps * turns) + 1).
std::int64_t curve_sample_count(const Object& curve);

}  // namespace sweep
