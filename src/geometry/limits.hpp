#pragma once
// Resource caps. Every one is checked by the parser before anything is allocated, so a hostile
// or mistyped file gets a file:line:column error instead of an out-of-memory kill.
#include <cstdint>

namespace sweep::limits {

/// Largest SWP file read, in bytes.
inline constexpr std::uint64_t kMaxFileBytes = 512ull << 20;
/// Largest STEPS of any curve or surface.
inline constexpr std::int64_t kMaxSteps = 100000;
/// Largest number of control points of one curve.
inline constexpr std::int64_t kMaxControlPoints = 10'000'000;
/// Largest number of samples of one curve (pieces * STEPS + 1).
inline constexpr std::int64_t kMaxCurveSamples = 10'000'000;
/// Largest number of vertices of one surface mesh, and of all surfaces of a document together.
inline constexpr std::int64_t kMaxMeshVertices = 50'000'000;
/// Largest absolute value of a coordinate or radius; keeps every product finite in float.
inline constexpr double kMaxCoordinate = 1e12;
/// Smallest circle radius. A smaller one (1e-300 is positive) collapses to a point in the float
/// mesh, so it is rejected as a mistake rather than turned into a degenerate surface.
inline constexpr double kMinRadius = 1e-12;
/// Longest object name.
inline constexpr std::size_t kMaxNameLength = 200;

}  // namespace sweep::limits
