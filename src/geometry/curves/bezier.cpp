#include "geometry/curves/bezier.hpp"

namespace sweep {

// GLM matrices are built column by column; column j holds the coefficients of t^j, row i
// belongs to control point i.
const glm::dmat4& bezier_basis() {
  static const glm::dmat4 basis(1, 0, 0, 0,     // 1
                                -3, 3, 0, 0,    // t
                                3, -6, 3, 0,    // t^2
                                -1, 3, -3, 1);  // t^3
  return basis;
}

const glm::dmat4& bspline_basis() {
  static const glm::dmat4 basis = glm::dmat4(1, 4, 1, 0,   // 1
                                             -3, 0, 3, 0,  // t
                                             3, -6, 3, 0,  // t^2
                                             -1, 3, -3, 1) /
                                  6.0;  // t^3
  return basis;
}

const glm::dmat4& bspline_to_bezier() {
  // G_bsp * B_bsp = G_bez * B_bez, so G_bez = G_bsp * (B_bsp * B_bez^-1).
  static const glm::dmat4 change = bspline_basis() * glm::inverse(bezier_basis());
  return change;
}

PieceDerivatives evaluate_bezier_piece(const std::array<glm::dvec3, 4>& p, double t) {
  // Power-basis coefficients c_j = sum_i p_i * M[j][i].
  const glm::dmat4& m = bezier_basis();
  glm::dvec3 c[4];
  for (int j = 0; j < 4; ++j) c[j] = p[0] * m[j][0] + p[1] * m[j][1] + p[2] * m[j][2] + p[3] * m[j][3];
  PieceDerivatives d;
  d.position = t == 1.0 ? p[3] : t == 0.0 ? p[0] : c[0] + t * (c[1] + t * (c[2] + t * c[3]));
  d.d1 = c[1] + t * (2.0 * c[2] + 3.0 * t * c[3]);
  d.d2 = 2.0 * c[2] + 6.0 * t * c[3];
  d.d3 = 6.0 * c[3];
  return d;
}

std::array<glm::dvec3, 4> bspline_piece_to_bezier(const std::array<glm::dvec3, 4>& q) {
  const glm::dmat4& m = bspline_to_bezier();
  std::array<glm::dvec3, 4> b;
  for (int j = 0; j < 4; ++j)
    b[static_cast<std::size_t>(j)] = q[0] * m[j][0] + q[1] * m[j][1] + q[2] * m[j][2] + q[3] * m[j][3];
  return b;
}

}  // namespace sweep
