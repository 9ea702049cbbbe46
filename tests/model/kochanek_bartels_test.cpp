// Kochanek-Bartels splines: they pass through every point, equal the uniform Catmull-Rom spline
// when tension, continuity and bias are 0, lie on the control polygon at tension 1, and their
// tangents at the points are those of Kochanek and Bartels (1984), written out here: continuous
// when the continuity is 0, a corner at every interior point otherwise.
#include "geometry/curves/kochanek_bartels.hpp"
#include "geometry/curves/catmull_rom.hpp"
#include "geometry/curves/curve.hpp"

#include "model/evaluation/curve_evaluation.hpp"
#include "support/core_test_support.hpp"
#include "support/curve_kinds_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace {

using sweep::KochanekBartelsShape;
using sweep::test::distance;

const std::vector<glm::dvec3> kZigzag2D =
    sweep::test::planar_points({{-6, 0}, {-5.2, 1}, {-4.4, 0}, {-3.6, 1.3}, {-2.8, 0}, {-1.5, 0.4}});
const std::vector<glm::dvec3> kOpen3D{{0, 0, 0}, {1, 2, -1}, {3, 2.5, 0.5}, {4, 0, 2}, {6, 1, 1}, {6.5, 3, -1}};
const std::vector<glm::dvec3> kClosed3D{{3, 0, -1}, {0, 1.5, 1}, {-3, 0, -1}, {0, -1.5, 1}, {3, 0, -1}};

const KochanekBartelsShape kShapes[] = {{0, 0, 0},    {0.5, 0, 0}, {-0.5, 0, 0},    {0, 0.6, 0},
                                        {0, -0.6, 0}, {0, 0, 0.7}, {0, 0, -0.7},    {0.3, -0.4, 0.5},
                                        {-1, 1, -1},  {1, -1, 1},  {0.9, 0.9, 0.9}, {-0.2, 1, 0.3}};

std::string describe(const KochanekBartelsShape& s) {
  return "T " + std::to_string(s.tension) + " C " + std::to_string(s.continuity) + " B " + std::to_string(s.bias);
}

/// The tangents at `p` of Kochanek and Bartels (1984): leaving p (the source derivative of the
/// segment that starts there) and arriving at p (the destination derivative of the one that ends there).
glm::dvec3 leaving_tangent(const glm::dvec3& before, const glm::dvec3& p, const glm::dvec3& after,
                           const KochanekBartelsShape& s) {
  const double t = s.tension, c = s.continuity, b = s.bias;
  return ((1 - t) * (1 + b) * (1 + c) / 2) * (p - before) + ((1 - t) * (1 - b) * (1 - c) / 2) * (after - p);
}
glm::dvec3 arriving_tangent(const glm::dvec3& before, const glm::dvec3& p, const glm::dvec3& after,
                            const KochanekBartelsShape& s) {
  const double t = s.tension, c = s.continuity, b = s.bias;
  return ((1 - t) * (1 + b) * (1 - c) / 2) * (p - before) + ((1 - t) * (1 - b) * (1 + c) / 2) * (after - p);
}

TEST(KochanekBartels, PassesThroughEveryPointAtItsKnot) {
  const int steps = 7;
  for (const auto* points : {&kZigzag2D, &kOpen3D, &kClosed3D}) {
    const bool planar = points == &kZigzag2D;
    for (const KochanekBartelsShape& shape : kShapes) {
      const sweep::CurveSamples curve = sweep::evaluate_kochanek_bartels(*points, steps, shape, planar);
      ASSERT_EQ(curve.frames.size(), (points->size() - 1) * steps + 1);
      for (std::size_t k = 0; k < points->size(); ++k) {
        EXPECT_LE(distance(curve.frames[k * steps].V, (*points)[k]), 1e-12 * sweep::test::extent_of(*points))
            << describe(shape) << " point " << k;
      }
    }
  }
}

TEST(KochanekBartels, ZeroTensionContinuityAndBiasIsTheUniformCatmullRom) {
  for (const auto* points : {&kZigzag2D, &kOpen3D, &kClosed3D}) {
    const bool planar = points == &kZigzag2D;
    const sweep::CurveSamples kb = sweep::evaluate_kochanek_bartels(*points, 11, {}, planar);
    const sweep::CurveSamples cr = sweep::evaluate_catmull_rom(*points, 11, 0.0, 0.0, planar);
    ASSERT_EQ(kb.frames.size(), cr.frames.size());
    const double size = sweep::test::extent_of(*points);
    for (std::size_t i = 0; i < kb.frames.size(); ++i) {
      EXPECT_LT(distance(kb.frames[i].V, cr.frames[i].V), 1e-12 * size) << i;
      EXPECT_LT(distance(kb.frames[i].T, cr.frames[i].T), 1e-12) << i;
      EXPECT_LT(distance(kb.frames[i].N, cr.frames[i].N), 1e-12) << i;
      EXPECT_LT(distance(kb.frames[i].B, cr.frames[i].B), 1e-12) << i;
    }
    EXPECT_EQ(kb.closed, cr.closed);
  }
}

TEST(KochanekBartels, TensionOneLiesOnTheControlPolygon) {
  const int steps = 10;
  for (const auto* points : {&kZigzag2D, &kOpen3D}) {
    const auto& p = *points;
    for (const double continuity : {-0.5, 0.0, 0.8}) {
      for (const double bias : {-1.0, 0.0, 0.4}) {
        const sweep::CurveSamples curve =
            sweep::evaluate_kochanek_bartels(p, steps, {1.0, continuity, bias}, points == &kZigzag2D);
        for (std::size_t k = 0; k + 1 < p.size(); ++k) {
          for (std::size_t i = k * steps; i <= (k + 1) * steps; ++i) {
            EXPECT_LT(sweep::test::distance_to_segment(curve.frames[i].V, p[k], p[k + 1]),
                      1e-12 * sweep::test::extent_of(p))
                << "segment " << k << " sample " << i;
            const bool inside = i > k * steps && (i < (k + 1) * steps || k + 2 == p.size());
            if (inside) {
              EXPECT_LT(distance(curve.frames[i].T, glm::normalize(p[k + 1] - p[k])), 1e-9) << i;
            }
          }
        }
        // The polygon turns at every interior point: each joint is a corner.
        EXPECT_EQ(curve.corners.size(), p.size() - 2);
      }
    }
  }
}

/// Checks a corner at every interior point with the arriving and leaving directions of the paper.
void expect_corners_as_the_paper(const std::vector<glm::dvec3>& p, const KochanekBartelsShape& shape, bool planar) {
  const int steps = 6;
  const sweep::CurveSamples curve = sweep::evaluate_kochanek_bartels(p, steps, shape, planar);
  ASSERT_EQ(curve.corners.size(), p.size() - 2) << describe(shape);
  for (std::size_t k = 1; k + 1 < p.size(); ++k) {
    const sweep::Corner& corner = curve.corners[k - 1];
    ASSERT_EQ(corner.sample, k * steps) << describe(shape);
    const glm::dvec3 in = glm::normalize(arriving_tangent(p[k - 1], p[k], p[k + 1], shape));
    const glm::dvec3 out = glm::normalize(leaving_tangent(p[k - 1], p[k], p[k + 1], shape));
    EXPECT_LT(distance(corner.incoming, in), 1e-12) << describe(shape) << " point " << k;
    EXPECT_LT(distance(curve.frames[corner.sample].T, out), 1e-12) << describe(shape) << " point " << k;
    EXPECT_GT(distance(in, out), 1e-3) << describe(shape) << " point " << k;
  }
}

TEST(KochanekBartels, ContinuityMakesACornerAtEveryInteriorPoint) {
  for (const KochanekBartelsShape& shape : kShapes) {
    // Tension 1 has no tangents; |bias| = |continuity| = 1 zeroes the leaving or arriving one.
    const bool degenerate = std::abs(shape.bias) == 1.0 && std::abs(shape.continuity) == 1.0;
    if (shape.continuity == 0.0 || shape.tension == 1.0 || degenerate) continue;
    expect_corners_as_the_paper(kZigzag2D, shape, true);
    expect_corners_as_the_paper(kOpen3D, shape, false);
  }
}

TEST(KochanekBartels, ZeroContinuityKeepsTheTangentContinuous) {
  for (const auto* points : {&kZigzag2D, &kOpen3D, &kClosed3D}) {
    const auto& p = *points;
    const bool closed = points == &kClosed3D;
    for (const KochanekBartelsShape& shape : kShapes) {
      if (shape.continuity != 0.0) continue;
      const sweep::CurveSamples curve = sweep::evaluate_kochanek_bartels(p, 8, shape, points == &kZigzag2D);
      EXPECT_TRUE(curve.corners.empty()) << describe(shape);
      for (std::size_t k = 1; k + 1 < p.size(); ++k) {
        const auto arriving = sweep::kochanek_bartels_piece(p, k - 1, closed, shape);
        const auto leaving = sweep::kochanek_bartels_piece(p, k, closed, shape);
        const glm::dvec3 in = glm::normalize(arriving[3] - arriving[2]);
        const glm::dvec3 out = glm::normalize(leaving[1] - leaving[0]);
        EXPECT_LT(distance(in, out), 1e-12) << describe(shape) << " point " << k;
        EXPECT_LT(distance(out, glm::normalize(leaving_tangent(p[k - 1], p[k], p[k + 1], shape))), 1e-12);
      }
      if (closed) {
        EXPECT_TRUE(curve.closed) << describe(shape);
        EXPECT_GT(glm::dot(curve.frames.front().T, curve.frames.back().T), 1.0 - 1e-12) << describe(shape);
      }
    }
  }
}

TEST(KochanekBartels, BiasLeansTheTangentTowardsOneChord) {
  // Bias 1: the tangent at a point follows the chord arriving there; bias -1: the one leaving it.
  const int steps = 4;
  for (const double bias : {1.0, -1.0}) {
    const sweep::CurveSamples curve = sweep::evaluate_kochanek_bartels(kOpen3D, steps, {0.0, 0.0, bias}, false);
    for (std::size_t k = 1; k + 1 < kOpen3D.size(); ++k) {
      const glm::dvec3 chord = bias > 0 ? kOpen3D[k] - kOpen3D[k - 1] : kOpen3D[k + 1] - kOpen3D[k];
      EXPECT_LT(distance(curve.frames[k * steps].T, glm::normalize(chord)), 1e-12) << bias << " point " << k;
    }
  }
}

TEST(KochanekBartels, EvaluateCurveDispatchesKochanekBartelsObjects) {
  sweep::Object object;
  object.set_kind(sweep::ObjectKind::KochanekBartels3);
  object.as<sweep::PointsPart>().points = kOpen3D;
  object.as<sweep::StepsPart>().steps = 5;
  object.as<sweep::TensionPart>().tension = 0.2;
  object.as<sweep::ContinuityBiasPart>().continuity = -0.3;
  object.as<sweep::ContinuityBiasPart>().bias = 0.4;
  const sweep::CurveSamples curve = sweep::evaluate_curve(object);
  const sweep::CurveSamples direct = sweep::evaluate_kochanek_bartels(kOpen3D, 5, {0.2, -0.3, 0.4}, false);
  ASSERT_EQ(static_cast<std::int64_t>(curve.frames.size()), sweep::curve_sample_count(object));
  for (std::size_t i = 0; i < curve.frames.size(); ++i) EXPECT_EQ(curve.frames[i].V, direct.frames[i].V);
  EXPECT_EQ(curve.corners.size(), kOpen3D.size() - 2);
  object.set_kind(sweep::ObjectKind::KochanekBartels2);  // a new kind starts from its defaults
  object.as<sweep::PointsPart>().points = kZigzag2D;
  object.as<sweep::StepsPart>().steps = 5;
  object.as<sweep::ContinuityBiasPart>().continuity = -0.3;
  EXPECT_TRUE(sweep::evaluate_curve(object).planar);
}

}  // namespace
