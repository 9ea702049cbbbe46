#pragma once
// The bounds geometry's own evaluation keeps to: the most samples a curve may have and the range
// of a coordinate or radius. The SWP reader checks a file against these and the document's other
// size limits (model/file_limits.hpp) before anything is allocated, so a hostile or mistyped
// file gets a file:line:column error instead of an out-of-memory kill.
#include <cstdint>

namespace sweep::limits {

/// Largest number of samples of one curve (pieces * STEPS + 1).
inline constexpr std::int64_t kMaxCurveSamples = 10'000'000;
/// Largest absolute value of a coordinate or radius; keeps every product finite in float.
inline constexpr double kMaxCoordinate = 1e12;
/// Smallest circle radius. A smaller one (1e-300 is positive) collapses to a point in the float
/// mesh, so it is rejected as a mistake rather than turned into a degenerate surface.
inline constexpr double kMinRadius = 1e-12;

}  // namespace sweep::limits
