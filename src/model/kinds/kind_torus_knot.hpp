#pragma once
// The torus knot, knot. One kind, declared in one place (object.hpp lists the kinds).
#include "geometry/curves/torus_knot.hpp"
#include "model/kinds/kind_fields.hpp"

namespace sweep {

/// The (knot_p, knot_q) torus knot: knot_p turns about the torus axis, knot_q through the hole,
/// on the torus of radii major_radius (R) > radius (r), centred on the origin or on `at` (the
/// optional `at X Y Z` clause).
struct TorusKnotCurve : RadiusPart, StepsPart, TolerancePart, PlacePart {
  static constexpr KindTraits traits{.keyword = "knot",
                                     .family = KindFamily::Curve,
                                     .planar = false,
                                     .points = point_layouts::kNone,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = "torus knot",
                                     .phrase = "a torus knot"};
  static constexpr const CurveBasis* basis = &kTorusKnotBasis;
  int knot_p = 0;
  int knot_q = 0;
  double major_radius = 0.0;
  std::int64_t sample_count() const { return std::int64_t{steps} + 1; }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.samples(std::int64_t{self.steps} + 1);
    f.integer("P", self.knot_p, 1, kMaxKnotWinding);
    f.integer("Q", self.knot_q, 1, kMaxKnotWinding, [&self] { return check_knot_pq(self.knot_p, self.knot_q); });
    f.number({"torus radius R", "R"}, self.major_radius);
    f.number({"tube radius r", "radius"}, self.radius,
             [&self] { return check_knot_radii(self.major_radius, self.radius); });
  }
  static void templates(auto& t) {
    t.add("trefoil knot", "knot", 11, [](TorusKnotCurve& c) {
      c.steps = 240;
      c.knot_p = 2;
      c.knot_q = 3;
      c.major_radius = 1.0;
      c.radius = 0.4;
    });
  }
  bool operator==(const TorusKnotCurve&) const = default;
};
template <>
inline constexpr std::span<const SwpClause> kind_clauses<TorusKnotCurve> = swp_clause_checks::kPlacedCurve;

}  // namespace sweep
