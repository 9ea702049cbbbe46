#pragma once
// The rider: a surface that rides along a curve. One kind, declared in one place (object.hpp lists
// the kinds).
#include "model/kinds/kind_fields.hpp"

#include <glm/vec3.hpp>

#include <string>

namespace sweep {

/// The rider's optional clauses' defaults: one traversal takes kDefaultRideSeconds.
inline constexpr double kDefaultRideSeconds = 10.0;

/// `rider NAME PATH MODEL [seconds S] [start F] [up X Y Z]`: the surface MODEL, modelled in its
/// own coordinates (+z along the path's T, +x along N, +y along B: the course's airplane), rides
/// the curve PATH at constant speed along its arc length, once every `seconds`, `start` of a loop
/// ahead (a phase in [0, 1)). With `up` the frames keep B as close to the up vector as the
/// tangent allows (geometry/surfaces/rider_track.hpp) instead of the path's own frames. A surface used as
/// a model is drawn only where it rides.
struct RiderObject {
  static constexpr KindTraits traits{.keyword = "rider",
                                     .family = KindFamily::Rider,
                                     .planar = false,
                                     .points = point_layouts::kNone,
                                     .interpolating = false,
                                     .steps = false,
                                     .label = "rider",
                                     .phrase = "a rider"};
  int path = -1;   // index of the curve ridden
  int model = -1;  // index of the surface carried
  double seconds = kDefaultRideSeconds;
  double start = 0.0;
  glm::dvec3 up{0.0};  // (0, 0, 0): the path's own frames
  static void fields(auto& self, auto& f) {
    f.reference("path", self.path, false);
    f.custom(self);  // MODEL: a surface, not a curve (swp/reader_surfaces.cpp)
  }
  bool operator==(const RiderObject&) const = default;
};
namespace swp_clause_checks {
inline std::string seconds(ObjectKind, double value) {
  return value > 0.0 && value <= 1e9 ? std::string() : "expected seconds greater than 0, at most 1e9";
}
inline std::string start(ObjectKind, double value) {
  return value >= 0.0 && value < 1.0 ? std::string() : "expected start from 0 up to (not including) 1";
}
inline std::string up(const glm::dvec3& value) {
  return value != glm::dvec3(0.0) ? std::string() : "expected an up vector other than 0 0 0";
}
inline constexpr SwpClause kRider[] = {
    {.key = "seconds",
     .field = &clause_slot<&RiderObject::seconds>,
     .default_value = kDefaultRideSeconds,
     .check = &seconds},
    {.key = "start", .field = &clause_slot<&RiderObject::start>, .check = &start},
    {.key = "up", .vector = &clause_slot<&RiderObject::up>, .vector_check = &up},
};
}  // namespace swp_clause_checks
template <>
inline constexpr std::span<const SwpClause> kind_clauses<RiderObject> = swp_clause_checks::kRider;

}  // namespace sweep
