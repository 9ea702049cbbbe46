#pragma once
// Catmull-Rom splines through their points, each segment as a cubic Bezier piece, with the knot
// spacing |dP|^alpha of Yuksel, Schaefer and Keyser (catmull_rom.cpp).
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <span>
#include <vector>

namespace sweep {

struct CurveBasis;
/// The Catmull-Rom basis (catmull_rom.cpp): closed when is_closed_interpolating.
extern const CurveBasis kCatmullRomBasis;

/// True if an interpolating spline (cr, kb, poly) through `points` is closed: at least 4 points
/// (three distinct and the first repeated) and the last point equal to the first, exactly or
/// within 1e-9 times the size of the seam points (ends_repeat(points, 1, 4), curve_basis.hpp).
/// Precondition: finite points.
bool is_closed_interpolating(std::span<const glm::dvec3> points);

/// The four points around segment k (from points[k] to points[k + 1]): its previous neighbour,
/// its two ends and its next neighbour. A closed polygon wraps around (the repeated last point is
/// skipped); an open one reflects the ends: P_-1 = 2 P_0 - P_1, P_N = 2 P_{N-1} - P_{N-2}.
/// Preconditions: points.size() >= 2, k + 1 < points.size(), closed only if is_closed_interpolating.
std::array<glm::dvec3, 4> segment_neighbourhood(std::span<const glm::dvec3> points, std::size_t k, bool closed);

/// The cubic Bezier control points of segment k of the Catmull-Rom spline through `points` with
/// knot spacing |dP|^alpha, its tangents scaled by (1 - tension). The piece starts exactly at
/// points[k] and ends exactly at points[k + 1]; a zero-length segment is a single point. Never
/// divides by a zero knot interval.
/// Preconditions: as segment_neighbourhood; alpha in [0, 1]; tension in [0, 1); finite points.
std::array<glm::dvec3, 4> catmull_rom_piece(std::span<const glm::dvec3> points, std::size_t k, bool closed,
                                            double alpha, double tension);

}  // namespace sweep
