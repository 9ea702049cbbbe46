#pragma once
// The size limits of a document, as read from a file or made by the editor: these and geometry's
// own bounds (geometry/sample_limits.hpp), all in sweep::limits. Every one is checked by the
// parser before anything is allocated; the running totals and their messages are caps.hpp's.
#include "geometry/sample_limits.hpp"

#include <cstddef>
#include <cstdint>

namespace sweep::limits {

/// Largest SWP file read, in bytes.
inline constexpr std::uint64_t kMaxFileBytes = 512ull << 20;
/// Largest STEPS of any curve or surface.
inline constexpr std::int64_t kMaxSteps = 100000;
/// Largest number of control points of one curve.
inline constexpr std::int64_t kMaxControlPoints = 10'000'000;
/// Largest number of vertices of one surface mesh, and of all surfaces of a document together.
inline constexpr std::int64_t kMaxMeshVertices = 50'000'000;
/// Longest object name.
inline constexpr std::size_t kMaxNameLength = 200;

}  // namespace sweep::limits
