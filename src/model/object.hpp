#pragma once
// The objects of an SWP document. Each kind is one type, in a header of its own (kind_*.hpp): it
// holds exactly that kind's data (parts.hpp), compares by defaulted equality, and declares in one
// place what the kind is (its `traits`: keyword, family, planarity, how its points are edited, its
// names for people), how it is sampled (its geometry basis), its syntax (`fields`, read and
// written from that one list, kind_fields.hpp) and its clauses (kind_clauses). Here the kinds are
// listed (ObjectKind, Payload). The reader, writer, messages, editor and panels read a kind from
// there (docs/architecture.md, "Adding a kind"). An Object is a name, where it was read, the
// editor's id, and one kind's data.
#include "model/kinds/kind_bezier.hpp"
#include "model/kinds/kind_bezier_patch.hpp"
#include "model/kinds/kind_birail.hpp"
#include "model/kinds/kind_bspline.hpp"
#include "model/kinds/kind_bspline_patch.hpp"
#include "model/kinds/kind_catmull_rom.hpp"
#include "model/kinds/kind_circle.hpp"
#include "model/kinds/kind_cylinder.hpp"
#include "model/kinds/kind_helix.hpp"
#include "model/kinds/kind_hermite.hpp"
#include "model/kinds/kind_kochanek_bartels.hpp"
#include "model/kinds/kind_material.hpp"
#include "model/kinds/kind_polygon_mesh.hpp"
#include "model/kinds/kind_polyline.hpp"
#include "model/kinds/kind_revolution.hpp"
#include "model/kinds/kind_rider.hpp"
#include "model/kinds/kind_subdivision.hpp"
#include "model/kinds/kind_torus_knot.hpp"
#include "model/kinds/parts.hpp"

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
  Hermite2,             // herm2: cubic Hermite, points and tangents alternating, in the xy-plane
  Hermite3,             // herm3
  SurfaceOfRevolution,  // srev
  GeneralizedCylinder,  // gcyl
  Birail,               // birail: a 2D profile swept along two rails (birail.hpp)
  BezierPatch,          // bezpatch: bicubic Bezier patches, 16 points each, welded into one surface (patch.hpp)
  BSplinePatch,         // bsppatch: a uniform bicubic B-spline surface of M rows of N points (patch.hpp)
  PolygonMesh,          // mesh: a polygon control cage, points and faces (subdivision.hpp)
  Subdivision,          // subd: the limit surface of a cage refined LEVELS times (subdivision.hpp)
  Material,             // material: colour, shininess, texture or checker, bump (material.hpp)
  Rider,                // rider: a surface riding a curve (kind_rider.hpp, geometry/surfaces/rider_track.hpp)
};

// ---- The kinds, in the order of ObjectKind: one header each (kind_*.hpp) ----

/// One kind's data; the alternative's index is its ObjectKind.
using Payload = std::variant<BezierCurve<2>, BezierCurve<3>, BSplineCurve<2>, BSplineCurve<3>, CircleCurve,
                             CatmullRomCurve<2>, CatmullRomCurve<3>, KochanekBartelsCurve<2>, KochanekBartelsCurve<3>,
                             HelixCurve, TorusKnotCurve, PolylineCurve<2>, PolylineCurve<3>, HermiteCurve<2>,
                             HermiteCurve<3>, RevolutionSurface, CylinderSurface, BirailSurface, BezierPatchSurface,
                             BSplinePatchSurface, PolygonMeshSurface, SubdivisionSurface, MaterialLook, RiderObject>;
static_assert(std::variant_size_v<Payload> == static_cast<std::size_t>(ObjectKind::Rider) + 1,
              "one Payload alternative per ObjectKind, in the enumerators' order");

/// A visitor of one lambda per kind type (std::visit), as in the std::visit examples.
template <typename... Functions>
struct Overloaded : Functions... {
  using Functions::operator()...;
};
template <typename... Functions>
Overloaded(Functions...) -> Overloaded<Functions...>;

/// Curves by control points with STEPS per piece: bez, bsp, cr, kb, herm.
template <typename Kind>
concept SteppedPointCurve =
    Kind::traits.family == KindFamily::Curve&& std::is_base_of_v<PointsPart, Kind>&& std::is_base_of_v<StepsPart, Kind>;

/// The default data of `kind`.
Payload make_payload(ObjectKind kind);

/// Where something was read from; line and column are 1-based, 0 when not from a file.
struct SourceLocation {
  int line = 0;
  int column = 0;
  /// The object's bytes in the text it was read from (Document::source): from its keyword to the
  /// end of its last token. begin == end: not read from the document's source (made in memory).
  std::size_t begin = 0;
  std::size_t end = 0;
  /// Where, as a message says it: line and column (the span is the writer's bookkeeping).
  bool operator==(const SourceLocation& other) const { return line == other.line && column == other.column; }
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
