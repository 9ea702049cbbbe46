// Helices: samples on the cylinder, counterclockwise, rising PITCH per turn (falling for a negative
// pitch), ceil(STEPS * TURNS) + 1 samples, curvature a / (a^2 + c^2) and torsion c / (a^2 + c^2)
// (c = PITCH / 2 pi) estimated from the samples and the frames, and a polyline length that
// converges to TURNS * sqrt((2 pi a)^2 + PITCH^2).
#include "geometry/curves/helix.hpp"

#include "model/evaluation/curve_evaluation.hpp"
#include "support/core_test_support.hpp"
#include "support/curve_kinds_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace {

using sweep::test::distance;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

struct HelixCase {
  double radius;
  double pitch;
  double turns;
  int steps;
};
const HelixCase kHelices[] = {
    {1.0, 0.6, 6.0, 32}, {2.5, -1.0, 2.25, 10}, {0.3, 4.0, 0.1, 7}, {1e-6, 1e-6, 3.5, 40}, {1e6, 2e5, 1.0, 64}};

TEST(Helix, SampleCountIsCeilStepsTimesTurnsPlusOne) {
  for (const HelixCase& h : kHelices) {
    const sweep::CurveSamples curve = sweep::evaluate_helix(h.radius, h.pitch, h.turns, h.steps);
    const auto expected = static_cast<std::size_t>(std::ceil(h.steps * h.turns)) + 1;
    EXPECT_EQ(curve.frames.size(), expected) << h.turns;
    EXPECT_EQ(static_cast<std::int64_t>(expected), sweep::helix_sample_count(h.steps, h.turns));
    EXPECT_FALSE(curve.closed);
    EXPECT_FALSE(curve.planar);
  }
  EXPECT_EQ(sweep::evaluate_helix(1.0, 1.0, 2.25, 10).frames.size(), 24u);  // ceil(22.5) + 1
  EXPECT_EQ(sweep::evaluate_helix(1.0, 1.0, 0.1, 7).frames.size(), 2u);     // ceil(0.7) + 1
}

TEST(Helix, SamplesLieOnTheCylinderAndRisePitchPerTurnCounterclockwise) {
  for (const HelixCase& h : kHelices) {
    const sweep::CurveSamples curve = sweep::evaluate_helix(h.radius, h.pitch, h.turns, h.steps);
    EXPECT_EQ(curve.frames.front().V, glm::dvec3(h.radius, 0.0, 0.0));
    double unwrapped = 0.0;  // angle about +z travelled so far, from the samples
    for (std::size_t i = 0; i < curve.frames.size(); ++i) {
      const glm::dvec3& v = curve.frames[i].V;
      EXPECT_NEAR(std::hypot(v.x, v.y), h.radius, 1e-12 * h.radius) << i;
      if (i > 0) {
        const glm::dvec3& u = curve.frames[i - 1].V;
        const double turn = std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y);
        EXPECT_GT(turn, 0.0) << "counterclockwise seen from +z, sample " << i;
        unwrapped += turn;
      }
      EXPECT_NEAR(v.z, h.pitch * unwrapped / kTwoPi, 1e-9 * (std::abs(h.pitch) * h.turns + h.radius)) << i;
    }
    EXPECT_NEAR(unwrapped, kTwoPi * h.turns, 1e-9);
  }
}

TEST(Helix, NegativePitchDescends) {
  const sweep::CurveSamples curve = sweep::evaluate_helix(1.0, -0.5, 3.0, 20);
  for (std::size_t i = 1; i < curve.frames.size(); ++i) {
    EXPECT_LT(curve.frames[i].V.z, curve.frames[i - 1].V.z) << i;
    EXPECT_LT(curve.frames[i].T.z, 0.0) << i;
  }
  EXPECT_NEAR(curve.frames.back().V.z, -1.5, 1e-12);
}

/// Curvature and torsion at sample i from central differences of the samples (uniform steps h in
/// the angle): kappa = |c' x c''| / |c'|^3, tau = (c' x c'') . c''' / |c' x c''|^2.
struct Estimate {
  double curvature;
  double torsion;
};
Estimate estimate_at(const std::vector<sweep::Frame>& f, std::size_t i, double h) {
  const glm::dvec3 d1 = (f[i + 1].V - f[i - 1].V) / (2.0 * h);
  const glm::dvec3 d2 = (f[i + 1].V - 2.0 * f[i].V + f[i - 1].V) / (h * h);
  const glm::dvec3 d3 = (f[i + 2].V - 2.0 * f[i + 1].V + 2.0 * f[i - 1].V - f[i - 2].V) / (2.0 * h * h * h);
  const glm::dvec3 cross = glm::cross(d1, d2);
  const double speed = glm::length(d1);
  return {glm::length(cross) / (speed * speed * speed), glm::dot(cross, d3) / glm::dot(cross, cross)};
}

TEST(Helix, CurvatureAndTorsionAreThoseOfTheHelix) {
  for (const HelixCase& h :
       {HelixCase{1.0, 0.6, 2.0, 2000}, HelixCase{2.0, -3.0, 1.5, 2000}, HelixCase{0.5, 0.0, 1.0, 2000}}) {
    const sweep::CurveSamples curve = sweep::evaluate_helix(h.radius, h.pitch, h.turns, h.steps);
    const double c = h.pitch / kTwoPi;
    const double curvature = h.radius / (h.radius * h.radius + c * c);
    const double torsion = c / (h.radius * h.radius + c * c);
    const double step = kTwoPi * h.turns / static_cast<double>(curve.frames.size() - 1);
    for (std::size_t i = 0; i < curve.frames.size(); ++i) EXPECT_NEAR(curve.curvature[i], curvature, 1e-12);
    for (std::size_t i = 2; i + 2 < curve.frames.size(); i += 97) {
      const Estimate e = estimate_at(curve.frames, i, step);
      EXPECT_NEAR(e.curvature, curvature, 1e-5 * curvature) << i;
      EXPECT_NEAR(e.torsion, torsion, 1e-4 * curvature) << i;
    }
  }
}

TEST(Helix, RotationMinimizingFramesTurnAgainstTheTorsion) {
  // Relative to the Frenet normal (towards the axis) a rotation-minimizing normal turns at minus
  // the torsion per unit length: the torsion read from the frames.
  const double a = 1.5, pitch = 2.0, turns = 2.0;
  const sweep::CurveSamples curve = sweep::evaluate_helix(a, pitch, turns, 400);
  const double c = pitch / kTwoPi;
  const double length = turns * std::hypot(kTwoPi * a, pitch);
  const auto angle_from_frenet = [](const sweep::Frame& f) {
    const glm::dvec3 frenet(-f.V.x, -f.V.y, 0.0);  // towards the axis
    return sweep::angle_about(f.T, glm::normalize(frenet), f.N);
  };
  double turned = 0.0;
  for (std::size_t i = 1; i < curve.frames.size(); ++i) {
    turned += std::remainder(angle_from_frenet(curve.frames[i]) - angle_from_frenet(curve.frames[i - 1]), kTwoPi);
  }
  EXPECT_NEAR(-turned / length, c / (a * a + c * c), 1e-6);
}

TEST(Helix, PolylineLengthConvergesToTheArcLength) {
  const double a = 1.2, pitch = 0.8, turns = 2.5;
  const double exact = turns * std::hypot(kTwoPi * a, pitch);
  double previous_error = 0.0;
  for (const int steps : {8, 16, 32, 64, 128, 256}) {
    const sweep::CurveSamples curve = sweep::evaluate_helix(a, pitch, turns, steps);
    const double length = sweep::chord_lengths(curve.frames).back();
    const double error = exact - length;
    EXPECT_GT(error, 0.0) << steps;  // chords are shorter than the arcs
    if (previous_error > 0.0) {
      EXPECT_NEAR(previous_error / error, 4.0, 0.1) << steps;  // second order
    }
    previous_error = error;
  }
  EXPECT_LT(previous_error, 1e-4 * exact);
}

TEST(Helix, FlatHelixOfWholeTurnsIsAClosedCircle) {
  const sweep::CurveSamples curve = sweep::evaluate_helix(2.0, 0.0, 1.0, 24);
  EXPECT_TRUE(curve.closed);
  EXPECT_EQ(curve.frames.front().V, curve.frames.back().V);
  EXPECT_LT(distance(curve.frames.front().N, curve.frames.back().N), 1e-12);
}

TEST(Helix, EvaluateCurveDispatchesHelixObjects) {
  sweep::Object object;
  object.set_kind(sweep::ObjectKind::Helix);
  object.as<sweep::StepsPart>().steps = 32;
  object.as<sweep::RadiusPart>().radius = 1.0;
  object.as<sweep::HelixCurve>().pitch = 0.6;
  object.as<sweep::HelixCurve>().turns = 6.0;
  const sweep::CurveSamples curve = sweep::evaluate_curve(object);
  EXPECT_EQ(static_cast<std::int64_t>(curve.frames.size()), sweep::curve_sample_count(object));
  EXPECT_NEAR(curve.frames.back().V.z, 3.6, 1e-12);
  for (const auto& f : curve.frames) EXPECT_EQ(sweep::test::frame_problem(f), "");
}

}  // namespace
