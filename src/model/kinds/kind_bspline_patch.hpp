#pragma once
// The B-spline patch, bsppatch. One kind, declared in one place (object.hpp lists the kinds).
#include "model/kinds/kind_fields.hpp"

namespace sweep {

/// A uniform bicubic B-spline surface of `rows` rows of `columns` points.
struct BSplinePatchSurface : PointsPart, StepsPart, MaterialPart {
  static constexpr KindTraits traits{.keyword = "bsppatch",
                                     .family = KindFamily::Surface,
                                     .planar = false,
                                     .points = point_layouts::kNet,
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

}  // namespace sweep
