#pragma once
// The optional clauses of each kind: `key value` pairs after an object's fixed fields (for
// curves with points: after the point count, before the first '['). One table serves the reader
// (which keys a kind accepts, their ranges) and the writer (which writes a clause only when it
// differs from its default, so files without clauses are written back unchanged). A later
// clause of any kind is one more row here. Header-only: the reader and the writer share it.
#include "geometry/adaptive.hpp"
#include "model/curve_parameters.hpp"
#include "model/document.hpp"

#include <array>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace sweep {

/// A clause's value is a number (`field`), the name of a 2D curve defined above (`reference`),
/// either of them (twist), or nothing: a flag clause is its key alone (`flag`, e.g. caps). Each
/// slot gives the field of an object of a kind that has the clause.
struct SwpClause {
  std::string_view key;                 // lower case, never a keyword (the reader tells them apart)
  double* (*field)(Object&) = nullptr;  // where a number goes
  double default_value = 0.0;           // not written when the field equals it
  std::string (*check)(ObjectKind kind, double value) = nullptr;  // "" if valid, else the "expected ..." text
  bool default_means_off = false;        // the default is not a value one may type (tolerance 0: by STEPS)
  int* (*reference)(Object&) = nullptr;  // where a curve's index goes (-1: not given)
  bool* (*flag)(Object&) = nullptr;      // set by the key alone
};

/// The class a pointer to member belongs to.
template <typename Member>
struct member_class;
template <typename Class, typename Value>
struct member_class<Value Class::*> {
  using type = Class;
};

/// The field `Member` of an object's data (a clause slot).
template <auto Member>
auto* clause_slot(Object& object) {
  using Part = typename member_class<decltype(Member)>::type;
  return &(object.as<Part>().*Member);
}

/// A clause's value in `object` (which has it), for the writer.
inline double clause_number(const SwpClause& clause, const Object& object) {
  return *clause.field(const_cast<Object&>(object));
}
inline int clause_reference(const SwpClause& clause, const Object& object) {
  return *clause.reference(const_cast<Object&>(object));
}
inline bool clause_flag(const SwpClause& clause, const Object& object) {
  return *clause.flag(const_cast<Object&>(object));
}

/// The reader keeps where each clause of an object was given in an array of this size.
inline constexpr std::size_t kMaxClausesPerKind = 8;

namespace swp_clause_checks {
inline std::string alpha(ObjectKind, double value) {
  return check_alpha(value);
}
inline std::string tension(ObjectKind kind, double value) {
  return check_tension(kind, value);
}
inline std::string continuity(ObjectKind, double value) {
  return check_kb_parameter("continuity", value);
}
inline std::string bias(ObjectKind, double value) {
  return check_kb_parameter("bias", value);
}
/// The floor relative to the curve's size is checked once its points are read (swp_parser.cpp).
inline std::string tolerance(ObjectKind, double value) {
  return check_tolerance(value, 0.0, "the curve");
}

inline constexpr SwpClause kTolerance = {"tolerance", &clause_slot<&TolerancePart::tolerance>, 0.0, &tolerance, true};
inline constexpr SwpClause kCurve[] = {kTolerance};
inline constexpr SwpClause kCatmullRom[] = {
    {"alpha", &clause_slot<&AlphaPart::alpha>, kDefaultAlpha, &alpha},
    {"tension", &clause_slot<&TensionPart::tension>, 0.0, &tension},
    kTolerance,
};
inline constexpr SwpClause kKochanekBartels[] = {
    {"tension", &clause_slot<&TensionPart::tension>, 0.0, &tension},
    {"continuity", &clause_slot<&ContinuityBiasPart::continuity>, 0.0, &continuity},
    {"bias", &clause_slot<&ContinuityBiasPart::bias>, 0.0, &bias},
    kTolerance,
};
/// A twist of any number of turns, but a finite one (1e6 degrees is 2778 turns).
inline std::string twist(ObjectKind, double value) {
  return std::abs(value) <= 1e6 ? std::string() : "expected a twist from -1e6 to 1e6 degrees";
}
inline constexpr SwpClause kCaps = {.key = "caps", .flag = &clause_slot<&CapsPart::caps>};
/// Every surface: `material NAME`, a material defined above (material.hpp).
inline constexpr SwpClause kMaterial = {.key = "material", .reference = &clause_slot<&MaterialPart::material>};
inline constexpr SwpClause kCylinder[] = {
    {.key = "scale", .reference = &clause_slot<&CylinderSurface::scale>},
    {.key = "twist",
     .field = &clause_slot<&CylinderSurface::twist>,
     .check = &twist,
     .reference = &clause_slot<&CylinderSurface::twist_curve>},
    kCaps,
    kMaterial,
};
inline constexpr SwpClause kRevolution[] = {kCaps, kMaterial};
inline constexpr SwpClause kBirail[] = {{.key = "height", .flag = &clause_slot<&BirailSurface::height>}, kMaterial};
inline constexpr SwpClause kSubdivision[] = {
    {.key = "loop", .flag = &clause_slot<&SubdivisionSurface::loop>},
    {.key = "smooth-boundary", .flag = &clause_slot<&SubdivisionSurface::smooth_boundary>},
    kMaterial,
};
inline constexpr SwpClause kNetSurface[] = {kMaterial};
static_assert(std::size(kCatmullRom) <= kMaxClausesPerKind && std::size(kKochanekBartels) <= kMaxClausesPerKind);
}  // namespace swp_clause_checks

/// The clauses of each kind, in the order the writer writes them. Declared for every kind type:
/// a new kind that does not say which clauses it has does not compile.
template <typename Kind>
inline constexpr std::span<const SwpClause> kind_clauses = Kind::no_clauses_declared;
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<BezierCurve<Dim>> = swp_clause_checks::kCurve;
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<BSplineCurve<Dim>> = swp_clause_checks::kCurve;
template <>
inline constexpr std::span<const SwpClause> kind_clauses<CircleCurve> = swp_clause_checks::kCurve;
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<CatmullRomCurve<Dim>> = swp_clause_checks::kCatmullRom;
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<KochanekBartelsCurve<Dim>> =
    swp_clause_checks::kKochanekBartels;
template <>
inline constexpr std::span<const SwpClause> kind_clauses<HelixCurve> = swp_clause_checks::kCurve;
template <>
inline constexpr std::span<const SwpClause> kind_clauses<TorusKnotCurve> = swp_clause_checks::kCurve;
/// A tolerance is accepted and changes nothing: one sample per point.
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<PolylineCurve<Dim>> = swp_clause_checks::kCurve;
template <>
inline constexpr std::span<const SwpClause> kind_clauses<RevolutionSurface> = swp_clause_checks::kRevolution;
template <>
inline constexpr std::span<const SwpClause> kind_clauses<CylinderSurface> = swp_clause_checks::kCylinder;
template <>
inline constexpr std::span<const SwpClause> kind_clauses<BirailSurface> = swp_clause_checks::kBirail;
template <>
inline constexpr std::span<const SwpClause> kind_clauses<BezierPatchSurface> = swp_clause_checks::kNetSurface;
template <>
inline constexpr std::span<const SwpClause> kind_clauses<BSplinePatchSurface> = swp_clause_checks::kNetSurface;
template <>
inline constexpr std::span<const SwpClause> kind_clauses<PolygonMeshSurface> = swp_clause_checks::kNetSurface;
template <>
inline constexpr std::span<const SwpClause> kind_clauses<SubdivisionSurface> = swp_clause_checks::kSubdivision;
/// A material's own clauses take several values (swp_reader_surfaces.cpp, read_material).
template <>
inline constexpr std::span<const SwpClause> kind_clauses<MaterialLook> = {};

namespace swp_clause_checks {
template <std::size_t... I>
constexpr std::array<std::span<const SwpClause>, sizeof...(I)> clauses_by_kind(std::index_sequence<I...>) {
  return {kind_clauses<std::variant_alternative_t<I, Payload>>...};
}
inline constexpr auto kByKind = clauses_by_kind(std::make_index_sequence<std::variant_size_v<Payload>>());
}  // namespace swp_clause_checks

/// The clauses `kind` accepts, in the order the writer writes them; empty for kinds without any.
inline std::span<const SwpClause> swp_clauses(ObjectKind kind) {
  return swp_clause_checks::kByKind[static_cast<std::size_t>(kind)];
}

}  // namespace sweep
