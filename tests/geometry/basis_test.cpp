// The Bezier and B-spline basis matrices against their textbook closed forms.
#include "geometry/curves/bezier.hpp"

#include "support/geometry_test_support.hpp"

#include <gtest/gtest.h>

#include <random>

namespace {

using sweep::test::bernstein_weights;
using sweep::test::bspline_weights;

/// The weights a basis gives the 4 control points at t: M * (1, t, t^2, t^3).
glm::dvec4 weights(const glm::dmat4& basis, double t) {
  return basis * glm::dvec4(1.0, t, t * t, t * t * t);
}

/// t in [0, 1] on a fine grid, plus points outside it (the polynomials are defined everywhere).
std::vector<double> parameters() {
  std::vector<double> ts;
  for (int i = 0; i <= 200; ++i) ts.push_back(i / 200.0);
  for (double t : {-3.5, -1.0, -0.25, 1.25, 2.0, 7.0}) ts.push_back(t);
  return ts;
}

TEST(Basis, BezierRowsArePartitionOfUnity) {
  for (double t : parameters()) {
    const glm::dvec4 w = weights(sweep::bezier_basis(), t);
    EXPECT_NEAR(w[0] + w[1] + w[2] + w[3], 1.0, 1e-12) << "t = " << t;
  }
}

TEST(Basis, BSplineRowsArePartitionOfUnity) {
  for (double t : parameters()) {
    const glm::dvec4 w = weights(sweep::bspline_basis(), t);
    EXPECT_NEAR(w[0] + w[1] + w[2] + w[3], 1.0, 1e-12) << "t = " << t;
  }
}

TEST(Basis, WeightsAreNonNegativeOnTheUnitInterval) {
  for (int i = 0; i <= 200; ++i) {
    const double t = i / 200.0;
    const glm::dvec4 bez = weights(sweep::bezier_basis(), t);
    const glm::dvec4 bsp = weights(sweep::bspline_basis(), t);
    for (int k = 0; k < 4; ++k) {
      EXPECT_GE(bez[k], -1e-15) << "Bezier weight " << k << " at t = " << t;
      EXPECT_GE(bsp[k], -1e-15) << "B-spline weight " << k << " at t = " << t;
    }
  }
}

TEST(Basis, BezierMatrixGivesTheBernsteinPolynomials) {
  for (double t : parameters()) {
    const glm::dvec4 w = weights(sweep::bezier_basis(), t);
    const glm::dvec4 expected = bernstein_weights(t);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(w[k], expected[k], 1e-9 * (1.0 + std::abs(expected[k]))) << k << " " << t;
  }
}

TEST(Basis, BSplineMatrixGivesTheBlendingFunctions) {
  for (double t : parameters()) {
    const glm::dvec4 w = weights(sweep::bspline_basis(), t);
    const glm::dvec4 expected = bspline_weights(t);
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(w[k], expected[k], 1e-9 * (1.0 + std::abs(expected[k]))) << k << " " << t;
  }
}

TEST(Basis, BSplineToBezierMatrixMatchesClosedForm) {
  // Column j holds the weights of q0..q3 in Bezier point b_j:
  // b0 = (q0 + 4 q1 + q2) / 6, b1 = (4 q1 + 2 q2) / 6, b2 = (2 q1 + 4 q2) / 6, b3 = (q1 + 4 q2 + q3) / 6.
  const double expected[4][4] = {{1, 4, 1, 0}, {0, 4, 2, 0}, {0, 2, 4, 0}, {0, 1, 4, 1}};
  const glm::dmat4& change = sweep::bspline_to_bezier();
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i)
      EXPECT_NEAR(change[j][i], expected[j][i] / 6.0, 1e-14) << "column " << j << " row " << i;
  }
}

TEST(Basis, BSplinePieceToBezierMatchesClosedForm) {
  std::mt19937 random(12345);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
  auto point = [&] { return glm::dvec3(coordinate(random), coordinate(random), coordinate(random)); };
  for (int trial = 0; trial < 100; ++trial) {
    const std::array<glm::dvec3, 4> q{point(), point(), point(), point()};
    const std::array<glm::dvec3, 4> b = sweep::bspline_piece_to_bezier(q);
    const glm::dvec3 expected[4] = {(q[0] + 4.0 * q[1] + q[2]) / 6.0, (4.0 * q[1] + 2.0 * q[2]) / 6.0,
                                    (2.0 * q[1] + 4.0 * q[2]) / 6.0, (q[1] + 4.0 * q[2] + q[3]) / 6.0};
    for (std::size_t k = 0; k < 4; ++k) EXPECT_LT(sweep::test::distance(b[k], expected[k]), 1e-12) << trial << " " << k;
  }
}

TEST(Basis, BezierPieceDerivativesMatchTheBernsteinForm) {
  // d/dt of a cubic Bezier is 3 times the quadratic Bezier of the differences of the points.
  const std::array<glm::dvec3, 4> p{glm::dvec3(0, 0, 0), glm::dvec3(1, 2, -1), glm::dvec3(3, -1, 2),
                                    glm::dvec3(4, 1, 0)};
  for (int i = 0; i <= 50; ++i) {
    const double t = i / 50.0;
    const double s = 1.0 - t;
    const glm::dvec3 d1 = 3.0 * (s * s * (p[1] - p[0]) + 2.0 * s * t * (p[2] - p[1]) + t * t * (p[3] - p[2]));
    const glm::dvec3 d2 = 6.0 * (s * (p[2] - 2.0 * p[1] + p[0]) + t * (p[3] - 2.0 * p[2] + p[1]));
    const glm::dvec3 d3 = 6.0 * (p[3] - 3.0 * p[2] + 3.0 * p[1] - p[0]);
    const sweep::PieceDerivatives d = sweep::evaluate_bezier_piece(p, t);
    EXPECT_LT(sweep::test::distance(d.position, sweep::test::direct_bezier({p.begin(), p.end()}, 0, t)), 1e-12) << t;
    EXPECT_LT(sweep::test::distance(d.d1, d1), 1e-12) << t;
    EXPECT_LT(sweep::test::distance(d.d2, d2), 1e-12) << t;
    EXPECT_LT(sweep::test::distance(d.d3, d3), 1e-12) << t;
  }
}

}  // namespace
