#pragma once
// The helix. One kind, declared in one place (object.hpp lists the kinds).
#include "geometry/curves/helix.hpp"
#include "model/kinds/kind_fields.hpp"

namespace sweep {

/// About +z from (radius, 0, 0), rising `pitch` per turn (negative descends), `turns` > 0 turns;
/// moved to stand at `at` (its axis's foot) by the optional `at X Y Z` clause.
struct HelixCurve : RadiusPart, StepsPart, TolerancePart, PlacePart {
  static constexpr KindTraits traits{.keyword = "helix",
                                     .family = KindFamily::Curve,
                                     .planar = false,
                                     .points = point_layouts::kNone,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = "helix",
                                     .phrase = "a helix"};
  static constexpr const CurveBasis* basis = &kHelixBasis;
  double pitch = 0.0;
  double turns = 0.0;
  std::int64_t sample_count() const { return helix_sample_count(steps, turns); }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.number("radius", self.radius, [&self] { return check_radius(self.radius); });
    f.number("pitch", self.pitch);
    f.number("turns", self.turns, [&self] { return check_turns(self.turns); });
    // TURNS is what makes a helix long, so the error is there.
    f.samples_by(self.sample_count(), "TURNS");
  }
  static void templates(auto& t) {
    t.add("helix", "helix", 10, [](HelixCurve& c) {
      c.steps = 48;
      c.radius = 0.5;
      c.pitch = 0.4;
      c.turns = 3.0;
    });
  }
  bool operator==(const HelixCurve&) const = default;
};
template <>
inline constexpr std::span<const SwpClause> kind_clauses<HelixCurve> = swp_clause_checks::kPlacedCurve;

}  // namespace sweep
