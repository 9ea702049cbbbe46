#pragma once
// The circle, circ. One kind, declared in one place (object.hpp lists the kinds).
#include "geometry/curves/circle.hpp"
#include "model/kinds/kind_fields.hpp"

namespace sweep {

struct CircleCurve : RadiusPart, StepsPart, TolerancePart {
  static constexpr KindTraits traits{.keyword = "circ",
                                     .family = KindFamily::Curve,
                                     .planar = true,
                                     .points = point_layouts::kNone,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = "circle",
                                     .phrase = "a circle"};
  static constexpr const CurveBasis* basis = &kCircleBasis;
  std::int64_t sample_count() const { return std::int64_t{steps} + 1; }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.samples(std::int64_t{self.steps} + 1);
    f.number("radius", self.radius, [&self] { return check_circle_radius(self.radius); });
  }
  static void templates(auto& t) {
    t.add("circle", "circle", 5, [](CircleCurve& c) {
      c.steps = 32;
      c.radius = 1.0;
    });
  }
  bool operator==(const CircleCurve&) const = default;
};
template <>
inline constexpr std::span<const SwpClause> kind_clauses<CircleCurve> = swp_clause_checks::kCurve;

}  // namespace sweep
