#pragma once
// The cubic Hermite curves, herm2 and herm3: points and tangents alternating (p0 t0 p1 t1 ...),
// piece k from p_k to p_{k+1} with derivatives t_k and t_{k+1} (geometry/curves/hermite.hpp). One kind,
// declared in one place (object.hpp lists the kinds).
#include "geometry/curves/hermite.hpp"
#include "model/kinds/kind_fields.hpp"

namespace sweep {

template <int Dim>
struct HermiteCurve : PointsPart, StepsPart, TolerancePart {
  using E = EntryRole;
  static constexpr KindTraits traits{
      .keyword = Dim == 2 ? "herm2" : "herm3",
      .family = KindFamily::Curve,
      .planar = Dim == 2,
      // A point and its tangent are one group: inserted and deleted together, repeated together
      // at a closed curve's seam; the tangent is shown and dragged as a handle at p + t/3.
      .points = {PointRole::ControlPoints,
                 2,
                 {E::Position, E::Tangent, E::Position},
                 2,
                 2,
                 2,
                 EditUnit::PointAndTangent,
                 PolygonStyle::Handles},
      .interpolating = true,
      .steps = true,
      .label = Dim == 2 ? "Hermite (2D)" : "Hermite (3D)",
      .phrase = "a Hermite curve"};
  static constexpr const CurveBasis* basis = &kHermiteBasis;
  static constexpr std::int64_t pieces(std::int64_t count) { return count >= 4 && count % 2 == 0 ? count / 2 - 1 : 0; }
  static std::string count_problem(std::int64_t count) {
    return pieces(count) > 0 ? ""
                             : "expected an even count of at least 4 Hermite entries (points and tangents "
                               "alternating: p0 t0 p1 t1 ...)";
  }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.points(self, "a count of points and tangents");
  }
  static void templates(auto& t) {
    using P = glm::dvec3;
    if constexpr (Dim == 2) {
      // A profile as the other open 2D templates: top to bottom, left of the y axis, bulging out.
      t.add("Hermite (2D)", "curve", 13, [](HermiteCurve& c) {
        c.points = {P(-0.25, 0.6, 0), P(-0.6, -0.3, 0),  P(-0.45, 0, 0),
                    P(0, -0.6, 0),    P(-0.25, -0.6, 0), P(0.6, -0.3, 0)};
      });
    } else {
      t.add("Hermite (3D)", "curve", 14, [](HermiteCurve& c) {
        c.points = {P(-0.5, 0, -0.25), P(0.3, 0.9, 0.3), P(0, 0, 0),
                    P(0.9, -0.6, 0.3), P(0.5, 0, 0.25),  P(0.3, 0.9, 0.3)};
      });
    }
  }
  bool operator==(const HermiteCurve&) const = default;
};
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<HermiteCurve<Dim>> = swp_clause_checks::kCurve;

}  // namespace sweep
