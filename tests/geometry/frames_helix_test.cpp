// Accuracy of the frame methods on a helix, whose exact rotation-minimizing frame is known in
// closed form: the end-frame error must fall at about fourth order in the step size for double
// reflection (Wang, Juttler, Zheng, Liu 2008) and at first to second order for the projection update.
#include "geometry/curves/frames.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <vector>

namespace {

// The helix (a cos u, a sin u, b u), u in [0, turns * 2 pi].
constexpr double kA = 1.0;
constexpr double kB = 0.4;
constexpr double kTurns = 1.5;

glm::dvec3 helix_point(double u) {
  return {kA * std::cos(u), kA * std::sin(u), kB * u};
}
glm::dvec3 helix_tangent(double u) {
  return glm::normalize(glm::dvec3(-kA * std::sin(u), kA * std::cos(u), kB));
}
/// Frenet normal and binormal.
glm::dvec3 frenet_normal(double u) {
  return {-std::cos(u), -std::sin(u), 0.0};
}
glm::dvec3 frenet_binormal(double u) {
  return glm::cross(helix_tangent(u), frenet_normal(u));
}

/// The exact rotation-minimizing normal at u for the frame whose normal at 0 is n0: in the Frenet
/// frame it turns at minus the torsion per unit arc length (r' parallel to T gives phi' = -tau),
/// and a helix has constant torsion tau = b / (a^2 + b^2) and speed sqrt(a^2 + b^2).
glm::dvec3 exact_rmf_normal(double u, const glm::dvec3& n0) {
  const double speed = std::sqrt(kA * kA + kB * kB);
  const double torsion = kB / (kA * kA + kB * kB);
  const double phi0 = std::atan2(glm::dot(n0, frenet_binormal(0.0)), glm::dot(n0, frenet_normal(0.0)));
  const double phi = phi0 - torsion * speed * u;
  return std::cos(phi) * frenet_normal(u) + std::sin(phi) * frenet_binormal(u);
}

/// Distance between the computed and the exact end normal with `steps` samples intervals.
double end_normal_error(int steps, sweep::FrameMethod method) {
  const double end = kTurns * 2.0 * std::numbers::pi;
  std::vector<sweep::Frame> samples(static_cast<std::size_t>(steps) + 1);
  for (int i = 0; i <= steps; ++i) {
    const double u = end * i / steps;
    samples[static_cast<std::size_t>(i)].V = helix_point(u);
    samples[static_cast<std::size_t>(i)].T = helix_tangent(u);
  }
  sweep::compute_frames(samples, false, {method});
  return glm::length(samples.back().N - exact_rmf_normal(end, samples.front().N));
}

/// Least-squares slope of log(error) against log(step size): the observed order.
double observed_order(sweep::FrameMethod method, const std::vector<int>& step_counts) {
  double sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
  const auto n = static_cast<double>(step_counts.size());
  for (const int steps : step_counts) {
    const double x = std::log(1.0 / steps);
    const double y = std::log(end_normal_error(steps, method));
    sx += x;
    sy += y;
    sxx += x * x;
    sxy += x * y;
  }
  return (n * sxy - sx * sy) / (n * sxx - sx * sx);
}

const std::vector<int> kStepCounts{24, 48, 96, 192, 384};

TEST(HelixConvergence, DoubleReflectionIsFourthOrderAndProjectionFirstToSecond) {
  for (const int steps : kStepCounts) {
    std::printf("helix, %4d steps: end-normal error %.3e (double reflection), %.3e (projection)\n", steps,
                end_normal_error(steps, sweep::FrameMethod::RotationMinimizing),
                end_normal_error(steps, sweep::FrameMethod::Projection));
  }
  const double rmf = observed_order(sweep::FrameMethod::RotationMinimizing, kStepCounts);
  const double projection = observed_order(sweep::FrameMethod::Projection, kStepCounts);
  std::printf("observed order: double reflection %.2f, projection %.2f\n", rmf, projection);
  RecordProperty("order_double_reflection", std::to_string(rmf));
  RecordProperty("order_projection", std::to_string(projection));
  EXPECT_GT(rmf, 3.5);
  EXPECT_LT(rmf, 4.5);
  EXPECT_GT(projection, 0.5);
  EXPECT_LT(projection, 2.5);
  // And at every step size double reflection is the more accurate.
  for (const int steps : kStepCounts) {
    EXPECT_LT(end_normal_error(steps, sweep::FrameMethod::RotationMinimizing),
              end_normal_error(steps, sweep::FrameMethod::Projection))
        << steps;
  }
}

TEST(HelixConvergence, ExactFrameIsRotationMinimizing) {
  // The reference itself: its derivative has no component along the binormal direction that
  // would turn it about T (r' is parallel to T), checked by finite differences.
  const glm::dvec3 n0 = frenet_normal(0.0);
  for (double u = 0.0; u < 9.0; u += 0.7) {
    const double h = 1e-5;
    const glm::dvec3 derivative = (exact_rmf_normal(u + h, n0) - exact_rmf_normal(u - h, n0)) / (2.0 * h);
    const glm::dvec3 r = exact_rmf_normal(u, n0);
    EXPECT_NEAR(glm::dot(derivative, glm::cross(helix_tangent(u), r)), 0.0, 1e-8) << u;
    EXPECT_NEAR(glm::dot(r, helix_tangent(u)), 0.0, 1e-12) << u;
  }
}

}  // namespace
