// Curve evaluation: end-point interpolation, agreement with direct evaluation of the textbook
// formulas, tangents against finite differences, and sample counts.
#include "geometry/curves/curve.hpp"
#include "geometry/curves/bezier.hpp"

#include "model/evaluation/curve_evaluation.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using sweep::test::direct_bezier;
using sweep::test::direct_bspline;
using sweep::test::distance;

// Two pieces meeting with a continuous tangent (P2, P3, P4 collinear and evenly spaced), so
// the junction sample has one tangent whichever piece it is computed from.
const std::vector<glm::dvec3> kBezier3D{{0, 0, 0}, {1, 2, -1}, {3, -1, 2}, {4, 1, 0}, {5, 3, -2}, {7, 2, 1}, {8, 0, 0}};
const std::vector<glm::dvec3> kBezier2D{{-1, 2, 0}, {-3, 1, 0}, {0, 0.5, 0}, {-2, -1, 0}};
const std::vector<glm::dvec3> kBSpline3D{{-2, 0, 1}, {0, 2, 1},  {0, 3, -1}, {2, 0, -1},
                                         {3, -2, 0}, {1, -3, 2}, {-1, -1, 1}};
const std::vector<glm::dvec3> kBSpline2D{{0, -0.25, 0},   {0.75, -0.75, 0}, {0.25, 0, 0},
                                         {0.75, 0.75, 0}, {0, 0.25, 0},     {-0.75, 0.75, 0}};

/// Unit tangent by central finite differences of a position function of t.
template <typename Position>
glm::dvec3 finite_difference_tangent(Position position, double t) {
  const double h = 1e-6;
  return glm::normalize(position(t + h) - position(t - h));
}

TEST(Bezier, PieceInterpolatesItsEndPointsExactly) {
  const std::array<glm::dvec3, 4> p{glm::dvec3(0.1, 0.2, 0.3), glm::dvec3(1, 2, -1), glm::dvec3(3, -1, 2),
                                    glm::dvec3(4.7, 1.3, 0.9)};
  EXPECT_EQ(sweep::evaluate_bezier_piece(p, 0.0).position, p[0]);
  EXPECT_EQ(sweep::evaluate_bezier_piece(p, 1.0).position, p[3]);
}

TEST(Bezier, CurvePassesThroughEveryThirdControlPoint) {
  const int steps = 7;
  const sweep::CurveSamples curve = sweep::evaluate_bezier(kBezier3D, steps, false);
  ASSERT_EQ(curve.frames.size(), 2u * steps + 1);
  EXPECT_EQ(curve.frames[0].V, kBezier3D[0]);
  EXPECT_EQ(curve.frames[steps].V, kBezier3D[3]);
  EXPECT_EQ(curve.frames[2 * steps].V, kBezier3D[6]);
}

TEST(Bezier, EndTangentsPointAlongTheControlPolygon) {
  for (const auto* points : {&kBezier3D, &kBezier2D}) {
    const bool planar = points == &kBezier2D;
    const sweep::CurveSamples curve = sweep::evaluate_bezier(*points, 10, planar);
    const auto& p = *points;
    const std::size_t n = p.size();
    EXPECT_LT(distance(curve.frames.front().T, glm::normalize(p[1] - p[0])), 1e-12);
    EXPECT_LT(distance(curve.frames.back().T, glm::normalize(p[n - 1] - p[n - 2])), 1e-12);
  }
}

TEST(Bezier, RepeatedEndControlPointsStillGiveTheDirectionOfTravel) {
  // P1 = P0 (or P2 = P3): the first derivative vanishes at that end; the tangent is its limit,
  // towards P2 at the start and arriving from P1 at the end.
  const glm::dvec3 a(0, 0, 0), b(2, 1, 0), c(3, 3, 0);
  const sweep::CurveSamples start = sweep::evaluate_bezier(std::vector<glm::dvec3>{a, a, b, c}, 8, true);
  EXPECT_LT(distance(start.frames.front().T, glm::normalize(b - a)), 1e-12);
  const sweep::CurveSamples end = sweep::evaluate_bezier(std::vector<glm::dvec3>{a, b, c, c}, 8, true);
  EXPECT_LT(distance(end.frames.back().T, glm::normalize(c - b)), 1e-12);
}

TEST(Bezier, SamplesEqualDeCasteljauAtEveryStep) {
  const int steps = 23;
  const sweep::CurveSamples curve = sweep::evaluate_bezier(kBezier3D, steps, false);
  for (std::size_t piece = 0; piece < 2; ++piece) {
    for (int s = 0; s <= steps; ++s) {
      const double t = static_cast<double>(s) / steps;
      const glm::dvec3 expected = direct_bezier(kBezier3D, piece, t);
      EXPECT_LT(distance(curve.frames[piece * steps + static_cast<std::size_t>(s)].V, expected), 1e-12)
          << piece << " " << t;
    }
  }
}

TEST(Bezier, TangentIsTheNormalizedDerivative) {
  const int steps = 16;
  for (const auto* points : {&kBezier3D, &kBezier2D}) {
    const bool planar = points == &kBezier2D;
    const sweep::CurveSamples curve = sweep::evaluate_bezier(*points, steps, planar);
    const std::size_t pieces = (points->size() - 1) / 3;
    for (std::size_t piece = 0; piece < pieces; ++piece) {
      for (int s = 0; s <= steps; ++s) {
        const double t = static_cast<double>(s) / steps;
        const glm::dvec3 expected =
            finite_difference_tangent([&](double u) { return direct_bezier(*points, piece, u); }, t);
        const std::size_t index = piece * steps + static_cast<std::size_t>(s);
        EXPECT_LT(distance(curve.frames[index].T, expected), 1e-6) << "piece " << piece << " t " << t;
      }
    }
  }
}

TEST(BSpline, BasisChangeEqualsDirectEvaluation) {
  for (const auto* points : {&kBSpline3D, &kBSpline2D}) {
    for (std::size_t piece = 0; piece + 3 < points->size(); ++piece) {
      const auto& q = *points;
      const std::array<glm::dvec3, 4> bezier =
          sweep::bspline_piece_to_bezier({q[piece], q[piece + 1], q[piece + 2], q[piece + 3]});
      for (int i = 0; i <= 1000; ++i) {
        const double t = i / 1000.0;
        EXPECT_LT(distance(sweep::evaluate_bezier_piece(bezier, t).position, direct_bspline(q, piece, t)), 1e-12)
            << "piece " << piece << " t " << t;
      }
    }
  }
}

TEST(BSpline, SamplesEqualDirectEvaluation) {
  const int steps = 37;
  for (const auto* points : {&kBSpline3D, &kBSpline2D}) {
    const bool planar = points == &kBSpline2D;
    const sweep::CurveSamples curve = sweep::evaluate_bspline(*points, steps, planar);
    const std::size_t pieces = points->size() - 3;
    ASSERT_EQ(curve.frames.size(), pieces * steps + 1);
    for (std::size_t piece = 0; piece < pieces; ++piece) {
      for (int s = 0; s <= steps; ++s) {
        const double t = static_cast<double>(s) / steps;
        const std::size_t index = piece * steps + static_cast<std::size_t>(s);
        EXPECT_LT(distance(curve.frames[index].V, direct_bspline(*points, piece, t)), 1e-12) << piece << " " << t;
      }
    }
  }
}

TEST(BSpline, TangentIsTheNormalizedDerivative) {
  const int steps = 16;
  for (const auto* points : {&kBSpline3D, &kBSpline2D}) {
    const bool planar = points == &kBSpline2D;
    const sweep::CurveSamples curve = sweep::evaluate_bspline(*points, steps, planar);
    const std::size_t pieces = points->size() - 3;
    for (std::size_t piece = 0; piece < pieces; ++piece) {
      for (int s = 0; s <= steps; ++s) {
        const double t = static_cast<double>(s) / steps;
        const glm::dvec3 fd = finite_difference_tangent([&](double u) { return direct_bspline(*points, piece, u); }, t);
        const glm::dvec3 exact = glm::normalize(sweep::test::direct_bspline_derivative(*points, piece, t));
        const std::size_t index = piece * steps + static_cast<std::size_t>(s);
        EXPECT_LT(distance(exact, fd), 1e-6);  // the reference derivative itself
        EXPECT_LT(distance(curve.frames[index].T, fd), 1e-6) << "piece " << piece << " t " << t;
      }
    }
  }
}

TEST(BSpline, RepeatingTheFirstThreePointsClosesTheCurve) {
  std::vector<glm::dvec3> closed = kBSpline2D;
  closed.insert(closed.end(), kBSpline2D.begin(), kBSpline2D.begin() + 3);
  const sweep::CurveSamples curve = sweep::evaluate_bspline(closed, 5, true);
  EXPECT_TRUE(curve.closed);
  EXPECT_LT(distance(curve.frames.front().V, curve.frames.back().V), 1e-12);
  EXPECT_FALSE(sweep::evaluate_bspline(kBSpline2D, 5, true).closed);
}

TEST(Curve, PlanarCurvesStayInTheXYPlane) {
  for (const auto& f : sweep::evaluate_bspline(kBSpline2D, 9, true).frames) {
    EXPECT_EQ(f.V.z, 0.0);
    EXPECT_EQ(f.T.z, 0.0);
  }
  for (const auto& f : sweep::evaluate_bezier(kBezier2D, 9, true).frames) {
    EXPECT_EQ(f.V.z, 0.0);
    EXPECT_EQ(f.T.z, 0.0);
  }
}

TEST(SampleCount, BezierIsPiecesTimesStepsPlusOne) {
  for (int pieces : {1, 2, 3, 5}) {
    std::vector<glm::dvec3> points;
    for (int i = 0; i < 3 * pieces + 1; ++i) points.emplace_back(i, (i * 7) % 5, (i * 3) % 4);
    for (int steps : {1, 2, 13, 50}) {
      const auto expected = static_cast<std::size_t>(pieces * steps + 1);
      EXPECT_EQ(sweep::evaluate_bezier(points, steps, false).frames.size(), expected) << pieces << " " << steps;
      sweep::Object object;
      object.set_kind(sweep::ObjectKind::Bezier3);
      object.as<sweep::PointsPart>().points = points;
      object.as<sweep::StepsPart>().steps = steps;
      EXPECT_EQ(sweep::curve_sample_count(object), static_cast<std::int64_t>(expected));
      EXPECT_EQ(sweep::evaluate_curve(object).frames.size(), expected);
    }
  }
}

TEST(SampleCount, BSplineIsCountMinusThreeTimesStepsPlusOne) {
  for (int count : {4, 5, 8, 11}) {
    std::vector<glm::dvec3> points;
    for (int i = 0; i < count; ++i) points.emplace_back(i, (i * 7) % 5, 0);
    for (int steps : {1, 3, 20}) {
      const auto expected = static_cast<std::size_t>((count - 3) * steps + 1);
      EXPECT_EQ(sweep::evaluate_bspline(points, steps, true).frames.size(), expected) << count << " " << steps;
      sweep::Object object;
      object.set_kind(sweep::ObjectKind::BSpline2);
      object.as<sweep::PointsPart>().points = points;
      object.as<sweep::StepsPart>().steps = steps;
      EXPECT_EQ(sweep::curve_sample_count(object), static_cast<std::int64_t>(expected));
    }
  }
}

TEST(SampleCount, CircleIsStepsPlusOneWithFirstEqualToLast) {
  for (int steps : {1, 3, 4, 30, 101}) {
    const sweep::CurveSamples curve = sweep::evaluate_circle(2.5, steps);
    ASSERT_EQ(curve.frames.size(), static_cast<std::size_t>(steps + 1));
    EXPECT_EQ(curve.frames.front().V, curve.frames.back().V);
    EXPECT_EQ(curve.frames.front().T, curve.frames.back().T);
    EXPECT_TRUE(curve.closed);
  }
}

TEST(Circle, SamplesLieOnTheCircleCounterclockwise) {
  const double radius = 1.75;
  const int steps = 36;
  const sweep::CurveSamples curve = sweep::evaluate_circle(radius, steps);
  for (int i = 0; i <= steps; ++i) {
    const double angle = 2.0 * std::numbers::pi * (i % steps) / steps;
    const sweep::Frame& f = curve.frames[static_cast<std::size_t>(i)];
    EXPECT_LT(distance(f.V, radius * glm::dvec3(std::cos(angle), std::sin(angle), 0.0)), 1e-12) << i;
    EXPECT_LT(distance(f.T, glm::dvec3(-std::sin(angle), std::cos(angle), 0.0)), 1e-12) << i;
  }
}

}  // namespace
