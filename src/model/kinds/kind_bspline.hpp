#pragma once
// The uniform cubic B-splines, bsp2 and bsp3. One kind, declared in one place (object.hpp lists the kinds).
#include "geometry/curves/bezier.hpp"
#include "model/kinds/kind_fields.hpp"

namespace sweep {

template <int Dim>
struct BSplineCurve : PointsPart, StepsPart, TolerancePart {
  static constexpr KindTraits traits{.keyword = Dim == 2 ? "bsp2" : "bsp3",
                                     .family = KindFamily::Curve,
                                     .planar = Dim == 2,
                                     .points = point_layouts::kBSpline,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = Dim == 2 ? "B-spline (2D)" : "B-spline (3D)",
                                     .phrase = "a B-spline"};
  static constexpr const CurveBasis* basis = &kBSplineBasis;
  static constexpr std::int64_t pieces(std::int64_t count) { return count >= 4 ? count - 3 : 0; }
  static std::string count_problem(std::int64_t count) {
    return count >= 4 ? "" : "expected at least 4 B-spline control points";
  }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.points(self, "a control point count");
  }
  static void templates(auto& t) {
    using P = glm::dvec3;
    if constexpr (Dim == 2) {
      t.add("open B-spline (2D)", "curve", 0, [](BSplineCurve& c) {
        c.points = {P(-0.2, 0.5, 0),   P(-0.35, 0.35, 0),  P(-0.45, 0.1, 0),
                    P(-0.45, -0.1, 0), P(-0.35, -0.35, 0), P(-0.2, -0.5, 0)};
      });
      // A counterclockwise hexagon of radius 0.5 (0.433 ~ 0.5 sin 60 deg).
      t.add("closed B-spline (2D)", "curve", 1, [](BSplineCurve& c) {
        c.points = closed_points({P(0.5, 0, 0), P(0.25, 0.433, 0), P(-0.25, 0.433, 0), P(-0.5, 0, 0),
                                  P(-0.25, -0.433, 0), P(0.25, -0.433, 0)},
                                 traits.points.seam_repeats);
      });
    } else {
      t.add("open B-spline (3D)", "curve", 2, [](BSplineCurve& c) {
        c.points = {P(-0.5, -0.2, -0.25), P(-0.3, 0.05, -0.15), P(-0.1, 0.15, -0.05),
                    P(0.1, 0.15, 0.05),   P(0.3, 0.05, 0.15),   P(0.5, -0.2, 0.25)};
      });
    }
  }
  bool operator==(const BSplineCurve&) const = default;
};
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<BSplineCurve<Dim>> = swp_clause_checks::kCurve;

}  // namespace sweep
