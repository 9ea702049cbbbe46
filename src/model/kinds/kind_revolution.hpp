#pragma once
// The surface of revolution, srev. One kind, declared in one place (object.hpp lists the kinds).
#include "model/kinds/kind_fields.hpp"

namespace sweep {

/// The profile turned about the y-axis, `copies` copies of it (the file's STEPS).
struct RevolutionSurface : ProfilePart, CopiesPart, CapsPart, MaterialPart {
  static constexpr KindTraits traits{.keyword = "srev",
                                     .family = KindFamily::Surface,
                                     .planar = false,
                                     .points = point_layouts::kNone,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = "surface of revolution",
                                     .phrase = "a surface of revolution"};
  static void fields(auto& self, auto& f) {
    f.steps(self.copies);
    f.reference("profile", self.profile, true);
    f.vertices(VerticesAt::Steps);
  }
  bool operator==(const RevolutionSurface&) const = default;
};
template <>
inline constexpr std::span<const SwpClause> kind_clauses<RevolutionSurface> = swp_clause_checks::kRevolution;

}  // namespace sweep
