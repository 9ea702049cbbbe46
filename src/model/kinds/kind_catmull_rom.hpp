#pragma once
// The Catmull-Rom splines through their points, cr2 and cr3. One kind, declared in one place (object.hpp lists the
// kinds).
#include "geometry/curves/catmull_rom.hpp"
#include "model/kinds/kind_fields.hpp"

namespace sweep {

template <int Dim>
struct CatmullRomCurve : PointsPart, StepsPart, TolerancePart, AlphaPart, TensionPart {
  static constexpr KindTraits traits{.keyword = Dim == 2 ? "cr2" : "cr3",
                                     .family = KindFamily::Curve,
                                     .planar = Dim == 2,
                                     .points = point_layouts::kThrough,
                                     .interpolating = true,
                                     .steps = true,
                                     .label = Dim == 2 ? "Catmull-Rom (2D)" : "Catmull-Rom (3D)",
                                     .phrase = "a Catmull-Rom curve"};
  static constexpr const CurveBasis* basis = &kCatmullRomBasis;
  static constexpr std::int64_t pieces(std::int64_t count) { return segments_through(count); }
  static std::string count_problem(std::int64_t count) { return interpolating_count_problem(count, "Catmull-Rom"); }
  static void fields(auto& self, auto& f) {
    f.steps(self.steps);
    f.points(self, "a control point count");
  }
  static void templates(auto& t) {
    using P = glm::dvec3;
    if constexpr (Dim == 2) {
      t.add("Catmull-Rom (2D)", "curve", 6, [](CatmullRomCurve& c) { c.points = wave_profile(); });
      t.add("closed Catmull-Rom (2D)", "curve", 7, [](CatmullRomCurve& c) {
        c.points =
            closed_points({P(0.5, 0, 0), P(0.15, 0.48, 0), P(-0.4, 0.29, 0), P(-0.4, -0.29, 0), P(0.15, -0.48, 0)},
                          traits.points.seam_repeats);
      });
    } else {
      t.add("Catmull-Rom (3D)", "curve", 8, [](CatmullRomCurve& c) {
        c.points = {P(-0.6, 0, -0.3), P(-0.3, 0.25, -0.15), P(0, 0, 0), P(0.3, -0.25, 0.15), P(0.6, 0, 0.3)};
      });
    }
  }
  bool operator==(const CatmullRomCurve&) const = default;
};
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<CatmullRomCurve<Dim>> = swp_clause_checks::kCatmullRom;

}  // namespace sweep
