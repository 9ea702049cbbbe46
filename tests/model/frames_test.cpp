// Frames along every curve of every starter file: orthonormal, right-handed, finite, positioned
// on the curve; the 2D and 3D conventions of the format.
#include "geometry/curves/curve.hpp"
#include "io/swp/read.hpp"

#include "model/evaluation/curve_evaluation.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <optional>

namespace {

using sweep::test::distance;

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Expects every frame of `curve` to be finite, orthonormal and right-handed (B = T x N).
void expect_orthonormal_frames(const sweep::CurveSamples& curve, const std::string& what) {
  for (std::size_t i = 0; i < curve.frames.size(); ++i) {
    const sweep::Frame& f = curve.frames[i];
    ASSERT_TRUE(finite(f.V) && finite(f.T) && finite(f.N) && finite(f.B)) << what << " sample " << i;
    EXPECT_NEAR(glm::length(f.T), 1.0, 1e-9) << what << " sample " << i;
    EXPECT_NEAR(glm::length(f.N), 1.0, 1e-9) << what << " sample " << i;
    EXPECT_NEAR(glm::length(f.B), 1.0, 1e-9) << what << " sample " << i;
    EXPECT_NEAR(glm::dot(f.T, f.N), 0.0, 1e-9) << what << " sample " << i;
    EXPECT_NEAR(glm::dot(f.T, f.B), 0.0, 1e-9) << what << " sample " << i;
    EXPECT_NEAR(glm::dot(f.N, f.B), 0.0, 1e-9) << what << " sample " << i;
    EXPECT_LT(distance(f.B, glm::cross(f.T, f.N)), 1e-9) << what << " sample " << i;
  }
}

/// The position a sample of `object` must have, from the textbook formulas.
/// Where sample `sample` of `object` lies, straight from the definition; nullopt for a sample of
/// a Catmull-Rom or Kochanek-Bartels curve between its points (their own tests check those).
std::optional<glm::dvec3> expected_position(const sweep::Object& object, std::size_t sample) {
  const auto steps = static_cast<std::size_t>(object.as<sweep::StepsPart>().steps);
  constexpr double kTwoPi = 2.0 * std::numbers::pi;
  if (object.kind() == sweep::ObjectKind::Helix) {
    const double count = static_cast<double>(sweep::curve_sample_count(object) - 1);
    const double angle = kTwoPi * object.as<sweep::HelixCurve>().turns * static_cast<double>(sample) / count;
    return glm::dvec3(object.as<sweep::RadiusPart>().radius * std::cos(angle),
                      object.as<sweep::RadiusPart>().radius * std::sin(angle),
                      object.as<sweep::HelixCurve>().pitch * angle / kTwoPi);
  }
  if (object.kind() == sweep::ObjectKind::TorusKnot) {
    const double t = kTwoPi * static_cast<double>(sample % steps) / static_cast<double>(steps);
    const double ring = object.as<sweep::TorusKnotCurve>().major_radius +
                        object.as<sweep::RadiusPart>().radius * std::cos(object.as<sweep::TorusKnotCurve>().knot_q * t);
    return glm::dvec3(ring * std::cos(object.as<sweep::TorusKnotCurve>().knot_p * t),
                      ring * std::sin(object.as<sweep::TorusKnotCurve>().knot_p * t),
                      object.as<sweep::RadiusPart>().radius * std::sin(object.as<sweep::TorusKnotCurve>().knot_q * t));
  }
  if (sweep::is_interpolating(object.kind())) {
    if (sample % steps != 0) return std::nullopt;
    return object.as<sweep::PointsPart>().points[sample / steps];
  }
  if (object.kind() == sweep::ObjectKind::Circle) {
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(sample % steps) / static_cast<double>(steps);
    return object.as<sweep::RadiusPart>().radius * glm::dvec3(std::cos(angle), std::sin(angle), 0.0);
  }
  const auto pieces = static_cast<std::size_t>(
      sweep::piece_count(object.kind(), static_cast<std::int64_t>(object.as<sweep::PointsPart>().points.size())));
  const std::size_t piece = std::min(sample / steps, pieces - 1);
  const double t = static_cast<double>(sample - piece * steps) / static_cast<double>(steps);
  const bool bezier = object.kind() == sweep::ObjectKind::Bezier2 || object.kind() == sweep::ObjectKind::Bezier3;
  return bezier ? sweep::test::direct_bezier(object.as<sweep::PointsPart>().points, piece, t)
                : sweep::test::direct_bspline(object.as<sweep::PointsPart>().points, piece, t);
}

class StarterCurves : public ::testing::TestWithParam<sweep::FrameMethod> {};

TEST_P(StarterCurves, FramesAreOrthonormalRightHandedFiniteAndOnTheCurve) {
  const auto files = sweep::test::starter_files();
  ASSERT_FALSE(files.empty()) << "no starter files in " << SWEEP_SWP_DIR;
  int curves = 0;
  for (const auto& file : files) {
    const sweep::Document doc = sweep::io::load_swp_file(file);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      const sweep::Object& object = doc.objects[i];
      if (!sweep::is_curve(object.kind())) continue;
      ++curves;
      const std::string what = file.filename().string() + " " + sweep::display_name(doc, static_cast<int>(i));
      const sweep::CurveSamples curve = sweep::evaluate_curve(object, {GetParam()});
      ASSERT_EQ(static_cast<std::int64_t>(curve.frames.size()), sweep::curve_sample_count(object)) << what;
      expect_orthonormal_frames(curve, what);
      double size = 1.0;
      for (const auto& p : sweep::points_of(object)) size = std::max(size, glm::length(p));
      if (const auto* knot = object.find<sweep::TorusKnotCurve>())
        size = std::max(size, knot->major_radius + knot->radius);
      if (const auto* helix = object.find<sweep::HelixCurve>())
        size = std::max(size, std::abs(helix->pitch * helix->turns));
      for (std::size_t s = 0; s < curve.frames.size(); ++s) {
        const std::optional<glm::dvec3> expected = expected_position(object, s);
        if (expected) {
          EXPECT_LT(distance(curve.frames[s].V, *expected), 1e-12 * size) << what << " sample " << s;
        }
      }
    }
  }
  EXPECT_GT(curves, 0);
}

INSTANTIATE_TEST_SUITE_P(BothMethods, StarterCurves,
                         ::testing::Values(sweep::FrameMethod::Projection, sweep::FrameMethod::RotationMinimizing));

TEST(Frames2D, NormalIsLeftOfTravelAndBinormalIsZ) {
  for (const auto& file : sweep::test::starter_files()) {
    const sweep::Document doc = sweep::io::load_swp_file(file);
    for (const sweep::Object& object : doc.objects) {
      if (!sweep::is_planar_curve(object.kind())) continue;
      for (const sweep::Frame& f : sweep::evaluate_curve(object).frames) {
        EXPECT_EQ(f.B, glm::dvec3(0, 0, 1)) << file;
        EXPECT_GT(glm::cross(f.T, f.N).z, 0.0) << file;
        EXPECT_LT(distance(f.N, glm::cross(glm::dvec3(0, 0, 1), f.T)), 1e-12) << file;
        EXPECT_EQ(f.V.z, 0.0) << file;
      }
    }
  }
}

TEST(Frames2D, CircleNormalsPointAtTheCenter) {
  for (int steps : {3, 8, 50}) {
    const sweep::CurveSamples circle = sweep::evaluate_circle(3.0, steps);
    for (const sweep::Frame& f : circle.frames) EXPECT_LT(distance(f.N, -f.V / 3.0), 1e-12) << steps;
  }
}

TEST(Frames2D, ClockwiseCurveHasNormalsPointingOutward) {
  // A clockwise closed B-spline: left of travel is outside.
  const std::vector<glm::dvec3> square{{1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {-1, 1, 0},
                                       {1, 1, 0}, {1, -1, 0}, {-1, -1, 0}};
  for (const sweep::Frame& f : sweep::evaluate_bspline(square, 6, true).frames) EXPECT_GT(glm::dot(f.N, f.V), 0.0);
}

TEST(Frames3D, FirstFrameHasBinormalZ) {
  // B_0 = +z, N_0 = normalize(B_0 x T_0) whenever T_0 is not along z.
  for (const auto& file : sweep::test::starter_files()) {
    const sweep::Document doc = sweep::io::load_swp_file(file);
    for (const sweep::Object& object : doc.objects) {
      if (!sweep::is_curve(object.kind()) || sweep::is_planar_curve(object.kind())) continue;
      for (auto method : {sweep::FrameMethod::Projection, sweep::FrameMethod::RotationMinimizing}) {
        const sweep::Frame f = sweep::evaluate_curve(object, {method}).frames.front();
        ASSERT_GT(glm::length(glm::cross(glm::dvec3(0, 0, 1), f.T)), 0.1) << file;
        EXPECT_LT(distance(f.N, glm::normalize(glm::cross(glm::dvec3(0, 0, 1), f.T))), 1e-12) << file;
        EXPECT_LT(distance(f.B, glm::cross(f.T, f.N)), 1e-12) << file;
      }
    }
  }
}

TEST(Frames3D, DegenerateCurvesStillGetOrthonormalFrames) {
  const std::vector<std::vector<glm::dvec3>> curves{
      {{0, 0, 0}, {0, 0, 1}, {0, 0, 2}, {0, 0, 3}},                                   // along +z: no B_0 x T_0
      {{1, 1, 1}, {1, 1, 1}, {1, 1, 1}, {1, 1, 1}},                                   // a single point
      {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {1, 0, 1}, {1, 0, 1}, {1, 1, 1}, {1, 1, 1}},  // sharp corners
      {{0, 0, 0}, {2, 0, 0}, {-1, 0, 0}, {1, 0, 0}},                                  // cusps: reverses on a line
  };
  for (std::size_t c = 0; c < curves.size(); ++c) {
    for (int steps : {1, 2, 7}) {
      for (auto method : {sweep::FrameMethod::Projection, sweep::FrameMethod::RotationMinimizing}) {
        const std::string what = "curve " + std::to_string(c) + " steps " + std::to_string(steps);
        expect_orthonormal_frames(sweep::evaluate_bezier(curves[c], steps, false, {method}), "Bezier " + what);
        expect_orthonormal_frames(sweep::evaluate_bspline(curves[c], steps, false, {method}), "B-spline " + what);
      }
    }
  }
}

TEST(Frames3D, RotationMinimizingFramesDoNotTwistAroundAStraightLine) {
  // Along a straight line the rotation-minimizing normal is constant.
  const std::vector<glm::dvec3> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}};
  const sweep::CurveSamples curve = sweep::evaluate_bezier(line, 20, false, {sweep::FrameMethod::RotationMinimizing});
  for (const sweep::Frame& f : curve.frames) EXPECT_LT(distance(f.N, curve.frames.front().N), 1e-12);
}

}  // namespace
