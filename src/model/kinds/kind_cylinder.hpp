#pragma once
// The generalized cylinder, gcyl. One kind, declared in one place (object.hpp lists the kinds).
#include "model/kinds/kind_fields.hpp"

namespace sweep {

/// The profile swept along `sweep`, with the optional clauses of sweep_controls.hpp: `scale
/// CURVE` and `twist DEGREES` or `twist CURVE` (2D curves read as graphs over the sweep's arc
/// length) and `caps`.
struct CylinderSurface : ProfilePart, CapsPart, MaterialPart {
  static constexpr KindTraits traits{.keyword = "gcyl",
                                     .family = KindFamily::Surface,
                                     .planar = false,
                                     .points = point_layouts::kNone,
                                     .interpolating = false,
                                     .steps = false,
                                     .label = "generalized cylinder",
                                     .phrase = "a generalized cylinder"};
  int sweep = -1;        // index of the sweep curve
  int scale = -1;        // -1: none
  int twist_curve = -1;  // -1: none (then `twist` degrees, growing linearly)
  double twist = 0.0;
  static void fields(auto& self, auto& f) {
    f.reference("profile", self.profile, true);
    f.reference("sweep", self.sweep, false);
    f.vertices(VerticesAt::Keyword);
  }
  bool operator==(const CylinderSurface&) const = default;
};
namespace swp_clause_checks {
inline constexpr SwpClause kCylinder[] = {
    {.key = "scale", .reference = &clause_slot<&CylinderSurface::scale>},
    {.key = "twist",
     .field = &clause_slot<&CylinderSurface::twist>,
     .check = &twist,
     .reference = &clause_slot<&CylinderSurface::twist_curve>},
    kCaps,
    kMaterial,
};
}  // namespace swp_clause_checks
template <>
inline constexpr std::span<const SwpClause> kind_clauses<CylinderSurface> = swp_clause_checks::kCylinder;

}  // namespace sweep
