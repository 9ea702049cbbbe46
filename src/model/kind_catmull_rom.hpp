#pragma once
// The Catmull-Rom splines through their points, cr2 and cr3. One kind, declared in one place (object.hpp lists the
// kinds).
#include "geometry/catmull_rom.hpp"
#include "model/kind_fields.hpp"

namespace sweep {

template <int Dim>
struct CatmullRomCurve : PointsPart, StepsPart, TolerancePart, AlphaPart, TensionPart {
  static constexpr KindTraits traits{.keyword = Dim == 2 ? "cr2" : "cr3",
                                     .family = KindFamily::Curve,
                                     .planar = Dim == 2,
                                     .points = PointRole::ControlPoints,
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
  bool operator==(const CatmullRomCurve&) const = default;
};
template <int Dim>
inline constexpr std::span<const SwpClause> kind_clauses<CatmullRomCurve<Dim>> = swp_clause_checks::kCatmullRom;

}  // namespace sweep
