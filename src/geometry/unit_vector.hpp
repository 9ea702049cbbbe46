#pragma once
// Length and normalization that stay exact for vectors of any finite size. glm::length squares the
// components first, so a vector of 1e-160 has a squared length of 0 or a denormal and glm::normalize
// returns a non-unit vector or NaN (and 1e160 overflows to inf). Dividing by the largest component
// first keeps the squared length between 1 and 3; vectors of usual size skip that (the benchmarks
// stay as fast as with glm). Found by the fuzzer: a B-spline whose control points differ by 1e-300
// got tangents of length 0.999994.
#include "base/precondition.hpp"

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>

namespace sweep {

namespace detail {
/// vector_length of a zero vector or one whose squared length is out of double's comfortable
/// range: by its largest component.
inline double scaled_length(const glm::dvec3& v) {
  const double m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  if (m == 0.0) return 0.0;
  const glm::dvec3 w = v / m;
  return m * std::sqrt(glm::dot(w, w));
}
}  // namespace detail

/// Euclidean length of a finite vector, without underflow or overflow in the squares.
[[gnu::always_inline]] inline double vector_length(const glm::dvec3& v) {
  const double squared = glm::dot(v, v);
  if (squared > 1e-250 && squared < 1e250) [[likely]] {
    return std::sqrt(squared);  // the usual case, exact as it is
  }
  return detail::scaled_length(v);
}

/// v scaled to unit length. Precondition: v is finite and not zero (as for glm::normalize).
inline glm::dvec3 unit_vector(const glm::dvec3& v) {
  SWEEP_EXPECTS(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && v != glm::dvec3(0.0),
                "v is finite and not zero");
  const double squared = glm::dot(v, v);
  if (squared > 1e-250 && squared < 1e250) return v / std::sqrt(squared);  // the usual case
  const double m = std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  const glm::dvec3 w = v / m;
  return w / std::sqrt(glm::dot(w, w));
}

}  // namespace sweep
