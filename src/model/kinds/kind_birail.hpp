#pragma once
// The birail surface. One kind, declared in one place (object.hpp lists the kinds).
#include "model/kinds/kind_fields.hpp"

namespace sweep {

/// A 2D profile swept along two rails (birail.hpp); `height` scales only along the profile's
/// chord.
struct BirailSurface : ProfilePart, MaterialPart {
  static constexpr KindTraits traits{.keyword = "birail",
                                     .family = KindFamily::Surface,
                                     .planar = false,
                                     .points = point_layouts::kNone,
                                     .interpolating = false,
                                     .steps = false,
                                     .label = "birail surface",
                                     .phrase = "a birail surface"};
  int rail1 = -1;  // RAIL1
  int rail2 = -1;  // RAIL2
  bool height = false;
  static void fields(auto& self, auto& f) {
    f.reference("profile", self.profile, true);
    f.reference("the first rail", self.rail1, false);
    f.reference("the second rail", self.rail2, false);
    f.vertices(VerticesAt::Keyword);
  }
  bool operator==(const BirailSurface&) const = default;
};
namespace swp_clause_checks {
inline constexpr SwpClause kBirail[] = {{.key = "height", .flag = &clause_slot<&BirailSurface::height>}, kMaterial};
}  // namespace swp_clause_checks
template <>
inline constexpr std::span<const SwpClause> kind_clauses<BirailSurface> = swp_clause_checks::kBirail;

}  // namespace sweep
