#pragma once
// Polylines: straight segments through their points (polyline.cpp).
#include "geometry/curves/curve.hpp"

#include <span>

namespace sweep {

/// The polyline basis (polyline.cpp): closed when is_closed_interpolating.
extern const CurveBasis kPolylineBasis;

/// One sample per point: sample i is point i (z = 0 when planar), its tangent the direction of
/// the segment leaving it (the last sample's: of the segment arriving), curvature 0. Every
/// interior point where the direction turns is a corner (incoming: the arriving segment's
/// direction), so sweeps mitre it. A polyline whose last point equals its first
/// (is_closed_interpolating) is closed: its last sample is its first, with a corner there too
/// when the path turns at the seam, and a closed 3D polyline's seam is closed as any closed 3D
/// curve's (options.close_seam). A zero-length segment takes the direction of the next non-zero
/// one (or the previous one at the end). Parameters are the point indices.
/// Preconditions: points.size() >= 2.
CurveSamples evaluate_polyline(std::span<const glm::dvec3> points, bool planar, const FrameOptions& options = {});

}  // namespace sweep
