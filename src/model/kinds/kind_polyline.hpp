#pragma once
// The polylines, poly2 and poly3. One kind, declared in one place (object.hpp lists the kinds).
#include "geometry/curves/polyline.hpp"
#include "model/kinds/kind_fields.hpp"

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace sweep {

/// Straight segments through the points, one sample per point: no STEPS, and a tolerance is
/// accepted and changes nothing.
template <int Dim>
struct PolylineCurve : PointsPart, TolerancePart {
  static constexpr KindTraits traits{.keyword = Dim == 2 ? "poly2" : "poly3",
                                     .family = KindFamily::Curve,
                                     .planar = Dim == 2,
                                     .points = point_layouts::kThrough,
                                     .interpolating = true,
                                     .steps = false,
                                     .label = Dim == 2 ? "polyline (2D)" : "polyline (3D)",
                                     .phrase = "a polyline"};
  static constexpr const CurveBasis* basis = &kPolylineBasis;
  static constexpr std::int64_t pieces(std::int64_t count) { return segments_through(count); }
  std::int64_t sample_count() const { return static_cast<std::int64_t>(points.size()); }
  static std::string count_problem(std::int64_t count) { return interpolating_count_problem(count, "polyline"); }
  static void fields(auto& self, auto& f) { f.points(self, "a point count"); }
  static void templates(auto& t) {
    if constexpr (Dim == 2) {
      // Outer points at radius 0.5, inner at 0.2, the first at the top.
      t.add("star polyline (2D)", "star", 12, [](PolylineCurve& c) {
        std::vector<glm::dvec3> star;
        for (int k = 0; k < 10; ++k) {
          const double angle = std::numbers::pi / 2.0 + k * std::numbers::pi / 5.0;
          const double r = k % 2 == 0 ? 0.5 : 0.2;
          star.emplace_back(r * std::cos(angle), r * std::sin(angle), 0.0);
        }
        c.points = closed_points(std::move(star), traits.points.seam_repeats);
      });
    }
  }
  bool operator==(const PolylineCurve&) const = default;
};
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<PolylineCurve<Dim>> = swp_clause_checks::kCurve;

}  // namespace sweep
