#pragma once
// The optional clauses of the SWP format: `key value` pairs after an object's fixed fields (for
// curves with points: after the point count, before the first '['). One table serves the reader
// (which keys a kind accepts, their ranges) and the writer (which writes a clause only when it
// differs from its default, so files without clauses are written back unchanged). A later
// clause of any kind is one more row here. Header-only: the reader and the writer share it.
#include "core/adaptive.hpp"
#include "core/curve_parameters.hpp"
#include "core/document.hpp"

#include <cstddef>
#include <iterator>
#include <span>
#include <string>
#include <string_view>

namespace sweep {

struct SwpClause {
  std::string_view key;                                 // lower case, never a keyword (the reader tells them apart)
  double Object::*field;                                // where the value goes
  double default_value;                                 // not written when the field equals it
  std::string (*check)(ObjectKind kind, double value);  // "" if valid, else the "expected ..." text
  bool default_means_off = false;  // the default is not a value one may type (tolerance 0: by STEPS)
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
      return swp_clause_checks::kCurve;
    case ObjectKind::SurfaceOfRevolution:
    case ObjectKind::GeneralizedCylinder:
      return {};
  }
  return {};
}

}  // namespace sweep
