#pragma once
// The Kochanek-Bartels splines, kb2 and kb3. One kind, declared in one place (object.hpp lists the kinds).
#include "geometry/curves/kochanek_bartels.hpp"
#include "model/kinds/kind_fields.hpp"

namespace sweep {

template <int Dim>
struct KochanekBartelsCurve : PointsPart, StepsPart, TolerancePart, TensionPart, ContinuityBiasPart {
  static constexpr KindTraits traits{.keyword = Dim == 2 ? "kb2" : "kb3",
                                     .family = KindFamily::Curve,
                                     .planar = Dim == 2,
                                     .points = point_layouts::kThrough,
                                     .interpolating = true,
                                     .steps = true,
                                     .label = Dim == 2 ? "Kochanek-Bartels (2D)" : "Kochanek-Bartels (3D)",
                                     .phrase = "a Kochanek-Bartels curve"};
  static constexpr const CurveBasis* basis = &kKochanekBartelsBasis;
  static constexpr std::int64_t pieces(std::int64_t count) { return segments_through(count); }
  static std::string count_problem(std::int64_t count) {
    return interpolating_count_problem(count, "Kochanek-Bartels");
  }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.points(self, "a control point count");
  }
  static void templates(auto& t) {
    if constexpr (Dim == 2) {
      t.add("Kochanek-Bartels (2D)", "curve", 9, [](KochanekBartelsCurve& c) { c.points = wave_profile(); });
    }
  }
  bool operator==(const KochanekBartelsCurve&) const = default;
};
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<KochanekBartelsCurve<Dim>> =
    swp_clause_checks::kKochanekBartels;

}  // namespace sweep
