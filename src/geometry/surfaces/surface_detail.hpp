#pragma once
// What surface.cpp and surface_revolution.cpp share about profiles as rings (internal to
// geometry: surface.hpp is the interface).
#include "geometry/curves/curve.hpp"

#include <cstddef>

namespace sweep::surface_detail {

/// How many segments join consecutive ring samples (a closed ring also joins last to first).
std::size_t segment_count(const CurveSamples& c);
/// Twice the signed area of the profile polygon (counterclockwise positive). If `through_axis`,
/// an open profile is closed through the y axis: its ends are joined by their projections.
double signed_area(const CurveSamples& profile, bool through_axis);

}  // namespace sweep::surface_detail
