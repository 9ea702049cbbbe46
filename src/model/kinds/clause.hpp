#pragma once
// The optional clauses of the kinds: `key value` pairs after an object's fixed fields (for
// curves with points: after the point count, before the first '['). One table serves the reader
// (which keys a kind accepts, their ranges) and the writer (which writes a clause only when it
// differs from its default, so files without clauses are written back unchanged). Each kind in
// object.hpp declares its clauses (kind_clauses) beside it; the clauses several kinds share are
// here.
#include "geometry/curves/adaptive.hpp"
#include "geometry/sample_limits.hpp"
#include "model/curve_parameters.hpp"
#include "model/kinds/parts.hpp"

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <span>
#include <string>
#include <string_view>

namespace sweep {

struct Object;

/// A clause's value is a number (`field`), the name of a 2D curve defined above (`reference`),
/// either of them (twist), three numbers (`vector`: a rider's up), or nothing: a flag clause is its
/// key alone (`flag`, e.g. caps). Each slot gives the field of an object of a kind that has the
/// clause.
struct SwpClause {
  std::string_view key;                 // lower case, never a keyword (the reader tells them apart)
  double* (*field)(Object&) = nullptr;  // where a number goes
  double default_value = 0.0;           // not written when the field equals it
  std::string (*check)(ObjectKind kind, double value) = nullptr;  // "" if valid, else the "expected ..." text
  bool default_means_off = false;        // the default is not a value one may type (tolerance 0: by STEPS)
  int* (*reference)(Object&) = nullptr;  // where a curve's index goes (-1: not given)
  bool* (*flag)(Object&) = nullptr;      // set by the key alone
  /// Three numbers; (0, 0, 0) means not given (not written), which vector_check refuses to read.
  glm::dvec3* (*vector)(Object&) = nullptr;
  std::string (*vector_check)(const glm::dvec3& value) = nullptr;  // "" if valid, else "expected ..."
};

/// The class a pointer to member belongs to.
template <typename Member>
struct member_class;
template <typename Class, typename Value>
struct member_class<Value Class::*> {
  using type = Class;
};

template <typename Member>
struct member_value;
template <typename Class, typename Value>
struct member_value<Value Class::*> {
  using type = Value;
};

/// The field `Member` of an object's data (a clause slot). A template of the object type too, so
/// that kinds name their slots before Object is complete.
template <auto Member, typename O = Object>
typename member_value<decltype(Member)>::type* clause_slot(O& object) {
  using Part = typename member_class<decltype(Member)>::type;
  return &(object.template as<Part>().*Member);
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
/// The floor relative to the curve's size is checked once its points are read (swp/read.cpp).
inline std::string tolerance(ObjectKind, double value) {
  return check_tolerance(value, 0.0, "the curve");
}

inline constexpr SwpClause kTolerance = {"tolerance", &clause_slot<&TolerancePart::tolerance>, 0.0, &tolerance, true};
inline constexpr SwpClause kCurve[] = {kTolerance};
inline std::string place(const glm::dvec3& value) {
  const double far = std::max({std::abs(value.x), std::abs(value.y), std::abs(value.z)});
  return far <= limits::kMaxCoordinate ? std::string() : "expected a place with coordinates from -1e12 to 1e12";
}
/// The helix's and the torus knot's: where they stand (PlacePart), then the curves' tolerance.
inline constexpr SwpClause kPlacedCurve[] = {
    {.key = "at", .vector = &clause_slot<&PlacePart::at>, .vector_check = &place},
    kTolerance,
};
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
inline constexpr SwpClause kRevolution[] = {kCaps, kMaterial};
inline constexpr SwpClause kNetSurface[] = {kMaterial};
static_assert(std::size(kCatmullRom) <= kMaxClausesPerKind && std::size(kKochanekBartels) <= kMaxClausesPerKind);
}  // namespace swp_clause_checks

/// The clauses of each kind, in the order the writer writes them. Declared beside every kind
/// type (object.hpp): a new kind that does not say which clauses it has does not compile.
template <typename Kind>
inline constexpr std::span<const SwpClause> kind_clauses = Kind::no_clauses_declared;

}  // namespace sweep
