#pragma once
// The piecewise cubic Bezier curves, bez2 and bez3. One kind, declared in one place (object.hpp lists the kinds).
#include "geometry/curves/bezier.hpp"
#include "model/kinds/kind_fields.hpp"

namespace sweep {

template <int Dim>
struct BezierCurve : PointsPart, StepsPart, TolerancePart {
  static constexpr KindTraits traits{.keyword = Dim == 2 ? "bez2" : "bez3",
                                     .family = KindFamily::Curve,
                                     .planar = Dim == 2,
                                     .points = point_layouts::kBezier,
                                     .interpolating = false,
                                     .steps = true,
                                     .label = Dim == 2 ? "Bezier (2D)" : "Bezier (3D)",
                                     .phrase = "a Bezier curve"};
  static constexpr const CurveBasis* basis = &kBezierBasis;
  static constexpr std::int64_t pieces(std::int64_t count) {
    return count >= 4 && (count - 1) % 3 == 0 ? (count - 1) / 3 : 0;
  }
  static std::string count_problem(std::int64_t count) {
    return pieces(count) > 0 ? "" : "expected a Bezier control point count of the form 3n+1 (4, 7, 10, ...)";
  }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.points(self, "a control point count");
  }
  static void templates(auto& t) {
    using P = glm::dvec3;
    if constexpr (Dim == 2) {
      // An S profile of two pieces with a smooth joint at (-0.35, 0) (handles collinear with it).
      t.add("Bezier (2D)", "curve", 3, [](BezierCurve& c) {
        c.points = {P(-0.2, 0.5, 0),  P(-0.5, 0.5, 0),  P(-0.5, 0.2, 0), P(-0.35, 0, 0),
                    P(-0.2, -0.2, 0), P(-0.2, -0.5, 0), P(-0.5, -0.5, 0)};
      });
    } else {
      t.add("Bezier (3D)", "curve", 4, [](BezierCurve& c) {
        c.points = {P(-0.5, 0, -0.25),  P(-0.5, 0.3, -0.15), P(-0.2, 0.3, -0.05), P(0, 0, 0),
                    P(0.2, -0.3, 0.05), P(0.5, -0.3, 0.15),  P(0.5, 0, 0.25)};
      });
    }
  }
  bool operator==(const BezierCurve&) const = default;
};
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<BezierCurve<Dim>> = swp_clause_checks::kCurve;

}  // namespace sweep
