#pragma once
// The subdivision surface, subd. One kind, declared in one place (object.hpp lists the kinds).
#include "model/kinds/kind_fields.hpp"

namespace sweep {

/// The limit surface of `source` (an earlier mesh or grid surface) refined `levels` times;
/// Loop instead of Catmull-Clark, smooth boundary corners.
struct SubdivisionSurface : MaterialPart {
  static constexpr KindTraits traits{.keyword = "subd",
                                     .family = KindFamily::Surface,
                                     .planar = false,
                                     .points = point_layouts::kNone,
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

}  // namespace sweep
