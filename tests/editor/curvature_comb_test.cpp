// Curvature combs against analytic curvature: a circle of radius r has 1/r everywhere with its
// needles pointing out of it, a helix a / (a^2 + b^2), a parabola written as one cubic Bezier
// 2 / (1 + 4x^2)^(3/2), a straight piece 0; a curvature jump at a joint breaks the tip line.
#include "editor/curvature_comb.hpp"

#include "geometry/curves/curve_curvature.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <string>

namespace sweep::editor {
namespace {

/// The comb of the first object of `text`, sampled by its STEPS.
CurvatureComb comb_of(const std::string& text, double factor = 1.0) {
  const Document doc = io::parse_swp(text, "comb.swp");
  const Object& curve = doc.objects.at(0);
  return curvature_comb(curve, evaluate_curve(curve), factor);
}

TEST(CurvatureComb, ACircleOfRadiusRHasCurvatureOneOverREverywhereAndItsNeedlesPointOut) {
  const CurvatureComb comb = comb_of("circ ring 40 2\n");
  ASSERT_EQ(comb.bases.size(), 41u);
  EXPECT_TRUE(comb.joint_arc_lengths.empty()) << "an analytic curve has no pieces";
  EXPECT_NEAR(comb.scale, 0.2 * curve_extent(io::parse_swp("circ ring 40 2\n").objects[0]) / 0.5, 1e-12);
  for (std::size_t i = 0; i < comb.bases.size(); ++i) {
    EXPECT_NEAR(comb.curvature[i], 0.5, 1e-12) << "counterclockwise: it turns left, towards N";
    const glm::dvec3 needle = comb.tips[i] - comb.bases[i];
    EXPECT_NEAR(glm::length(needle), comb.scale * 0.5, 1e-9);
    // Away from the centre: the tip is farther out than the curve.
    EXPECT_NEAR(glm::length(comb.tips[i]), 2.0 + comb.scale * 0.5, 1e-9);
  }
}

TEST(CurvatureComb, The2DNeedleIsMinusTheSignedCurvatureTimesN) {
  // An S: it turns left, then right. Needles are -k N: on the right of travel where it turns left.
  const std::string text = "bez2 s 16 7\n[0 0]\n[1 0]\n[2 1]\n[2 2]\n[2 3]\n[3 4]\n[4 4]\n";
  const Document doc = io::parse_swp(text, "s.swp");
  const CurveSamples samples = evaluate_curve(doc.objects[0]);
  const CurvatureComb comb = curvature_comb(doc.objects[0], samples, 1.0);
  std::size_t frame = 0;
  bool left = false, right = false;
  for (std::size_t i = 0; i < comb.bases.size(); ++i) {
    while (samples.frames[frame].V != comb.bases[i]) ++frame;
    const glm::dvec3 expected = -comb.scale * comb.curvature[i] * samples.frames[frame].N;
    EXPECT_LT(glm::length(comb.tips[i] - comb.bases[i] - expected), 1e-9) << i;
    left |= comb.curvature[i] > 1e-6;
    right |= comb.curvature[i] < -1e-6;
  }
  EXPECT_TRUE(left && right) << "the S turns both ways";
}

TEST(CurvatureComb, AHelixHasTheCurvatureOfItsFormula) {
  const double a = 1.0, pitch = 0.6;  // swp/helix.swp
  const double b = pitch / (2.0 * std::numbers::pi);
  const CurvatureComb comb = comb_of("helix coil 32 1 0.6 6\n");
  ASSERT_GT(comb.bases.size(), 100u);
  for (double k : comb.curvature) EXPECT_NEAR(k, a / (a * a + b * b), 1e-12);
}

TEST(CurvatureComb, AParabolaAsOneCubicBezierHasTheParabolasCurvature) {
  // y = x^2 on [-1, 1]: the quadratic (-1, 1), (0, -1), (1, 1) raised to a cubic.
  const CurvatureComb comb = comb_of(
      "bez2 parabola 24 4\n[-1 1]\n[-0.33333333333333333 -0.33333333333333333]\n"
      "[0.33333333333333333 -0.33333333333333333]\n[1 1]\n");
  ASSERT_EQ(comb.bases.size(), 25u);
  for (std::size_t i = 0; i < comb.bases.size(); ++i) {
    const double x = comb.bases[i].x;
    EXPECT_NEAR(comb.bases[i].y, x * x, 1e-12);
    EXPECT_NEAR(comb.curvature[i], 2.0 / std::pow(1.0 + 4.0 * x * x, 1.5), 1e-9) << "at x = " << x;
  }
}

TEST(CurvatureComb, AStraightPieceHasNoCurvatureAndNoNeedles) {
  const CurvatureComb comb = comb_of("bez2 line 8 4\n[0 0]\n[1 1]\n[2 2]\n[3 3]\n");
  for (std::size_t i = 0; i < comb.bases.size(); ++i) {
    EXPECT_EQ(comb.curvature[i], 0.0);
    EXPECT_EQ(comb.tips[i], comb.bases[i]);
  }
  EXPECT_EQ(comb.scale, 1.0) << "nothing to scale to";
}

TEST(CurvatureComb, AJumpInCurvatureAtAJointBreaksTheTipLine) {
  // A straight piece, then a bend leaving it tangentially: curvature 0 before the joint, not after.
  const CurvatureComb comb = comb_of("bez2 bend 8 7\n[0 0]\n[1 0]\n[2 0]\n[3 0]\n[4 0]\n[5 1]\n[5 2]\n");
  ASSERT_EQ(comb.joint_arc_lengths.size(), 1u);
  EXPECT_DOUBLE_EQ(comb.joint_arc_lengths[0], 3.0);
  ASSERT_EQ(comb.bases.size(), 8u + 8u + 1u + 1u) << "the joint has two needles";
  const std::size_t before = 8, after = 9;  // the samples of the first piece are 0..7
  EXPECT_EQ(comb.bases[before], glm::dvec3(3, 0, 0));
  EXPECT_EQ(comb.bases[after], comb.bases[before]);
  EXPECT_NEAR(comb.curvature[before], 0.0, 1e-12) << "the end of the straight piece";
  EXPECT_GT(comb.curvature[after], 0.1) << "the start of the bend";
  EXPECT_NE(comb.tips[after], comb.tips[before]);
}

TEST(CurvatureComb, ThePlotSamplesTheCurvatureEvenlyAlongTheCurve) {
  const CurvatureComb circle = comb_of("circ ring 40 2\n");
  for (float k : curvature_plot(circle, 50)) EXPECT_NEAR(k, 0.5f, 1e-6f);
  const CurvatureComb bend = comb_of("bez2 bend 8 7\n[0 0]\n[1 0]\n[2 0]\n[3 0]\n[4 0]\n[5 1]\n[5 2]\n");
  const std::vector<float> plot = curvature_plot(bend, 101);
  ASSERT_EQ(plot.size(), 101u);
  EXPECT_EQ(plot.front(), 0.0f);
  EXPECT_GT(plot.back(), 0.1f);
}

TEST(CurvatureVector, IsKappaTowardsTheCentreAndZeroWithoutSpeed) {
  // A circle of radius 3 at angle t: c' = 3(-sin, cos), c'' = -3(cos, sin).
  const double t = 0.7;
  const PieceDerivatives d{glm::dvec3(3 * std::cos(t), 3 * std::sin(t), 0),
                           glm::dvec3(-3 * std::sin(t), 3 * std::cos(t), 0),
                           glm::dvec3(-3 * std::cos(t), -3 * std::sin(t), 0), glm::dvec3(0.0)};
  const glm::dvec3 k = curvature_vector(d);
  EXPECT_NEAR(glm::length(k), 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(glm::dot(glm::normalize(k), -glm::normalize(d.position)), 1.0, 1e-15);
  EXPECT_NEAR(signed_curvature(d), 1.0 / 3.0, 1e-15);
  const PieceDerivatives still{glm::dvec3(1.0), glm::dvec3(0.0), glm::dvec3(1.0), glm::dvec3(0.0)};
  EXPECT_EQ(curvature_vector(still), glm::dvec3(0.0));
  EXPECT_EQ(signed_curvature(still), 0.0);
}

}  // namespace
}  // namespace sweep::editor
