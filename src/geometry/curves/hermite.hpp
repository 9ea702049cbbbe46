#pragma once
// Cubic Hermite curves (hermite.cpp): points and tangents alternating, p0 t0 p1 t1 ... pn tn.
// Piece k runs from p_k to p_{k+1} over a parameter 0..1 with derivative t_k at its start and
// t_{k+1} at its end, so it is the cubic Bezier p_k, p_k + t_k / 3, p_{k+1} - t_{k+1} / 3, p_{k+1};
// neighbouring pieces share a point and its tangent, so the curve is C1 by construction.
#include "geometry/curves/curve.hpp"

#include <span>

namespace sweep {

/// The Hermite basis: closed when its last point and tangent repeat its first (ends_repeat, with
/// at least 3 points and tangents: two pieces).
extern const CurveBasis kHermiteBasis;

/// Piece k of `entries` (points and tangents alternating) as its 4 Bezier points.
/// Preconditions: entries.size() even, 2 k + 3 < entries.size().
BezierPiece hermite_piece(std::span<const glm::dvec3> entries, std::size_t k);

/// STEPS samples per piece (or adaptively within `tolerance`), frames as for any curve of cubic
/// pieces. Preconditions: entries.size() even and >= 4, steps >= 1.
CurveSamples evaluate_hermite(std::span<const glm::dvec3> entries, int steps, bool planar,
                              const FrameOptions& options = {}, const AdaptiveTolerance& tolerance = {});

}  // namespace sweep
