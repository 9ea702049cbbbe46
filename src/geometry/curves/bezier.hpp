#pragma once
// Cubic Bezier and uniform cubic B-spline bases. Both are 4x4 matrices in GLM's column-major
// layout: a point on a piece is G * M * (1, t, t^2, t^3) with G the 4 control points as columns.
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>

namespace sweep {

struct CurveBasis;
/// The bases of piecewise cubic Bezier curves (3n+1 points) and uniform cubic B-splines (N >= 4
/// points), defined in bezier_curves.cpp; closed: bez when its last point is its first, bsp when
/// its last three repeat its first three (ends_repeat, curve_basis.hpp).
extern const CurveBasis kBezierBasis;
extern const CurveBasis kBSplineBasis;

/// Bernstein (Bezier) basis matrix.
const glm::dmat4& bezier_basis();
/// Uniform cubic B-spline basis matrix.
const glm::dmat4& bspline_basis();
/// Basis change that turns 4 B-spline control points into the 4 Bezier control points of the
/// same piece: bezier = bspline * bspline_to_bezier(), i.e. B_bsp * inverse(B_bez).
const glm::dmat4& bspline_to_bezier();

/// Position and first three derivatives of a cubic piece at t in [0, 1].
struct PieceDerivatives {
  glm::dvec3 position;
  glm::dvec3 d1;
  glm::dvec3 d2;
  glm::dvec3 d3;
};

/// Evaluates the cubic Bezier piece with control points p at t. At t = 0 and t = 1 the
/// position is exactly p[0] and p[3], so consecutive pieces meet bit for bit.
PieceDerivatives evaluate_bezier_piece(const std::array<glm::dvec3, 4>& p, double t);

/// The Bezier control points of the B-spline piece with control points q.
std::array<glm::dvec3, 4> bspline_piece_to_bezier(const std::array<glm::dvec3, 4>& q);

}  // namespace sweep
