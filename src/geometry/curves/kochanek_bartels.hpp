#pragma once
// Kochanek-Bartels (tension, continuity, bias) splines through their points, each segment as a
// cubic Bezier piece (kochanek_bartels.cpp).
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace sweep {

struct CurveBasis;
/// The Kochanek-Bartels basis (kochanek_bartels.cpp): closed when is_closed_interpolating.
extern const CurveBasis kKochanekBartelsBasis;

/// Tension, continuity and bias of a Kochanek-Bartels spline; all 0 is the uniform Catmull-Rom.
struct KochanekBartelsShape {
  double tension = 0.0;
  double continuity = 0.0;
  double bias = 0.0;
};

/// The cubic Bezier control points of segment k (points[k] to points[k + 1]) of the
/// Kochanek-Bartels spline through `points`, with uniform knots. Neighbours as
/// segment_neighbourhood (catmull_rom.hpp): wrapped when `closed`, else reflected ends. The piece
/// starts exactly at points[k] and ends exactly at points[k + 1]; a zero-length segment is a point.
/// Preconditions: points.size() >= 2, k + 1 < points.size(), closed only if is_closed_interpolating;
/// tension, continuity and bias in [-1, 1]; finite points.
std::array<glm::dvec3, 4> kochanek_bartels_piece(std::span<const glm::dvec3> points, std::size_t k, bool closed,
                                                 const KochanekBartelsShape& shape);

}  // namespace sweep
