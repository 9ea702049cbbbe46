#pragma once
// The Bezier patches, bezpatch. One kind, declared in one place (object.hpp lists the kinds).
#include "model/kinds/kind_fields.hpp"

namespace sweep {

/// Bicubic Bezier patches of 16 points each (row by row), `steps` segments per patch side.
struct BezierPatchSurface : PointsPart, StepsPart, MaterialPart {
  static constexpr KindTraits traits{.keyword = "bezpatch",
                                     .family = KindFamily::Surface,
                                     .planar = false,
                                     .points = point_layouts::kNet,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = "Bezier patches",
                                     .phrase = "a Bezier patch surface"};
  static void fields(auto& self, auto& f) { f.custom(self); }
  bool operator==(const BezierPatchSurface&) const = default;
};
template <>
inline constexpr std::span<const SwpClause> kind_clauses<BezierPatchSurface> = swp_clause_checks::kNetSurface;

}  // namespace sweep
