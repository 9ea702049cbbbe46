#pragma once
// A "nice" number near a rough one: 1, 2 or 5 times a power of ten. The ground grid's spacing
// (editor/overlay_builder) and the size the Create panel gives a new curve (model/edit) round to
// it, so grid lines and the numbers a file is written with stay short.
#include <cmath>

namespace sweep {

/// 1, 2, 5 or 10 times the power of ten below `rough`, whichever is nearest; 1 for a `rough`
/// that is not a finite number > 0.
inline double nice_step(double rough) {
  if (!(rough > 0.0) || !std::isfinite(rough)) return 1.0;
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  const double m = rough / power;
  return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * power;
}

/// The largest of 1, 2 or 5 times a power of ten that is at most `limit`; 1 for a `limit` that
/// is not a finite number > 0.
inline double nice_at_most(double limit) {
  if (!(limit > 0.0) || !std::isfinite(limit)) return 1.0;
  const double power = std::pow(10.0, std::floor(std::log10(limit)));
  const double m = limit / power;
  return (m >= 5.0 ? 5.0 : m >= 2.0 ? 2.0 : 1.0) * power;
}

}  // namespace sweep
