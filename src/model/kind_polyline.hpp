#pragma once
// The polylines, poly2 and poly3. One kind, declared in one place (object.hpp lists the kinds).
#include "geometry/polyline.hpp"
#include "model/kind_fields.hpp"

namespace sweep {

/// Straight segments through the points, one sample per point: no STEPS, and a tolerance is
/// accepted and changes nothing.
template <int Dim>
struct PolylineCurve : PointsPart, TolerancePart {
  static constexpr KindTraits traits{.keyword = Dim == 2 ? "poly2" : "poly3",
                                     .family = KindFamily::Curve,
                                     .planar = Dim == 2,
                                     .points = PointRole::ControlPoints,
                                     .interpolating = true,
                                     .steps = false,
                                     .label = Dim == 2 ? "polyline (2D)" : "polyline (3D)",
                                     .phrase = "a polyline"};
  static constexpr const CurveBasis* basis = &kPolylineBasis;
  static constexpr std::int64_t pieces(std::int64_t count) { return segments_through(count); }
  std::int64_t sample_count() const { return static_cast<std::int64_t>(points.size()); }
  static std::string count_problem(std::int64_t count) { return interpolating_count_problem(count, "polyline"); }
  static void fields(auto& self, auto& f) { f.points(self, "a point count"); }
  bool operator==(const PolylineCurve&) const = default;
};
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<PolylineCurve<Dim>> = swp_clause_checks::kCurve;

}  // namespace sweep
