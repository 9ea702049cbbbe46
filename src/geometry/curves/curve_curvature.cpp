#include "geometry/curves/curve_curvature.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace sweep {
namespace {

constexpr double kNoSpeed = 1e-300;  // below this |c'| has no direction: no curvature

}  // namespace

glm::dvec3 curvature_vector(const PieceDerivatives& d) {
  const double speed2 = glm::dot(d.d1, d.d1);
  if (!(speed2 > kNoSpeed * kNoSpeed)) return glm::dvec3(0.0);
  // (c' x c'') x c' = c'' |c'|^2 - c' (c' . c''): the part of c'' across the tangent.
  return (d.d2 * speed2 - d.d1 * glm::dot(d.d1, d.d2)) / (speed2 * speed2);
}

double signed_curvature(const PieceDerivatives& d) {
  const double speed2 = d.d1.x * d.d1.x + d.d1.y * d.d1.y;
  if (!(speed2 > kNoSpeed * kNoSpeed)) return 0.0;
  return (d.d1.x * d.d2.y - d.d1.y * d.d2.x) / (speed2 * std::sqrt(speed2));
}

}  // namespace sweep
