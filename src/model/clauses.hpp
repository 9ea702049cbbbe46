#pragma once
// The optional clauses of each kind: `key value` pairs after an object's fixed fields (for
// curves with points: after the point count, before the first '['). One table serves the reader
// (which keys a kind accepts, their ranges) and the writer (which writes a clause only when it
// differs from its default, so files without clauses are written back unchanged). A later
// clause of any kind is one more row here. Header-only: the reader and the writer share it.
#include "geometry/adaptive.hpp"
#include "model/curve_parameters.hpp"
#include "model/document.hpp"

#include <cmath>
#include <cstddef>
#include <iterator>
#include <span>
#include <string>
#include <string_view>

namespace sweep {

/// A clause's value is a number (`field`), the name of a 2D curve defined above (`reference`),
/// either of them (twist), or nothing: a flag clause is its key alone (`flag`, e.g. caps).
struct SwpClause {
  std::string_view key;             // lower case, never a keyword (the reader tells them apart)
  double Object::*field = nullptr;  // where a number goes
  double default_value = 0.0;       // not written when the field equals it
  std::string (*check)(ObjectKind kind, double value) = nullptr;  // "" if valid, else the "expected ..." text
  bool default_means_off = false;    // the default is not a value one may type (tolerance 0: by STEPS)
  int Object::*reference = nullptr;  // where a curve's index goes (-1: not given)
  bool Object::*flag = nullptr;      // set by the key alone
};

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

inline constexpr SwpClause kTolerance = {"tolerance", &Object::tolerance, 0.0, &tolerance, true};
inline constexpr SwpClause kCurve[] = {kTolerance};
inline constexpr SwpClause kCatmullRom[] = {
    {"alpha", &Object::alpha, kDefaultAlpha, &alpha},
    {"tension", &Object::tension, 0.0, &tension},
    kTolerance,
};
inline constexpr SwpClause kKochanekBartels[] = {
    {"tension", &Object::tension, 0.0, &tension},
    {"continuity", &Object::continuity, 0.0, &continuity},
    {"bias", &Object::bias, 0.0, &bias},
    kTolerance,
};
/// A twist of any number of turns, but a finite one (1e6 degrees is 2778 turns).
inline std::string twist(ObjectKind, double value) {
  return std::abs(value) <= 1e6 ? std::string() : "expected a twist from -1e6 to 1e6 degrees";
}
inline constexpr SwpClause kCaps = {.key = "caps", .flag = &Object::caps};
/// Every surface: `material NAME`, a material defined above (material.hpp).
inline constexpr SwpClause kMaterial = {.key = "material", .reference = &Object::material};
inline constexpr SwpClause kCylinder[] = {
    {.key = "scale", .reference = &Object::scale},
    {.key = "twist", .field = &Object::twist, .check = &twist, .reference = &Object::twist_curve},
    kCaps,
    kMaterial,
};
inline constexpr SwpClause kRevolution[] = {kCaps, kMaterial};
inline constexpr SwpClause kBirail[] = {{.key = "height", .flag = &Object::height}, kMaterial};
inline constexpr SwpClause kSubdivision[] = {
    {.key = "loop", .flag = &Object::loop},
    {.key = "smooth-boundary", .flag = &Object::smooth_boundary},
    kMaterial,
};
inline constexpr SwpClause kNetSurface[] = {kMaterial};
static_assert(std::size(kCatmullRom) <= kMaxClausesPerKind && std::size(kKochanekBartels) <= kMaxClausesPerKind);
}  // namespace swp_clause_checks

/// The clauses `kind` accepts, in the order the writer writes them; empty for kinds without any.
inline std::span<const SwpClause> swp_clauses(ObjectKind kind) {
  switch (kind) {  // no default: a new kind must say whether it has clauses
    case ObjectKind::CatmullRom2:
    case ObjectKind::CatmullRom3:
      return swp_clause_checks::kCatmullRom;
    case ObjectKind::KochanekBartels2:
    case ObjectKind::KochanekBartels3:
      return swp_clause_checks::kKochanekBartels;
    case ObjectKind::Bezier2:
    case ObjectKind::Bezier3:
    case ObjectKind::BSpline2:
    case ObjectKind::BSpline3:
    case ObjectKind::Circle:
    case ObjectKind::Helix:
    case ObjectKind::TorusKnot:
    case ObjectKind::Polyline2:  // a tolerance is accepted and changes nothing: one sample per point
    case ObjectKind::Polyline3:
      return swp_clause_checks::kCurve;
    case ObjectKind::SurfaceOfRevolution:
      return swp_clause_checks::kRevolution;
    case ObjectKind::GeneralizedCylinder:
      return swp_clause_checks::kCylinder;
    case ObjectKind::Birail:
      return swp_clause_checks::kBirail;
    case ObjectKind::Subdivision:
      return swp_clause_checks::kSubdivision;
    case ObjectKind::BezierPatch:
    case ObjectKind::BSplinePatch:
    case ObjectKind::PolygonMesh:
      return swp_clause_checks::kNetSurface;
    case ObjectKind::Material:
      return {};  // its own clauses take several values (swp_parser.cpp, read_material)
  }
  return {};
}

}  // namespace sweep
