// Adaptive sampling against its references (issue 14's "near the fewest samples"): on a few
// curves of every kind at D = 1e-3 of the curve's size, the adaptive sampling keeps its bound,
// takes at most 1.2 times the samples of a greedy sampler with the same constraints (torus knots:
// a known miss, held to 1.4) and at most 1.2 times the best uniform STEPS, and well under 0.6 of
// the latter where the curvature varies; every starter file's curves at 1e-3 of the scene's size;
// and the references themselves (circle formula, joints, an exhaustive surface search).
// The references are slow (sampling_reference.hpp); the curves are kept small for the sanitizer
// build. The full tables are benchmarks/adaptive_report.cpp's (docs/adaptive-sampling.md).
#include "geometry/curves/adaptive.hpp"
#include "geometry/curves/curve.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/deviation.hpp"
#include "model/evaluation/scene.hpp"
#include "sampling/representative_curves.hpp"
#include "sampling/sampling_reference.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace sweep::sampling {

/// Names the curve in failure messages (instead of its bytes).
void PrintTo(const RepresentativeCurve& curve, std::ostream* out) {
  *out << curve.curve.name;
}

namespace {

struct Counts {
  std::size_t adaptive = 0;
  double deviation = 0.0;
  std::size_t greedy = 0;
  UniformCurve uniform;
};

Counts counts(const Object& curve, double tolerance) {
  Counts c;
  const CurveSamples samples = evaluate_curve(curve, {}, {tolerance, 0.0});
  c.adaptive = samples.frames.size();
  c.deviation = curve_deviation(curve, samples, 64);
  c.greedy = greedy_sample_count(curve, tolerance);
  c.uniform = best_uniform_steps(curve, tolerance);
  return c;
}

double ratio(std::size_t a, std::size_t b) {
  return static_cast<double>(a) / static_cast<double>(b);
}

class RepresentativeCurveTest : public ::testing::TestWithParam<RepresentativeCurve> {};

TEST_P(RepresentativeCurveTest, NearTheFewestSamplesWithinTheBound) {
  const RepresentativeCurve& param = GetParam();
  const double tolerance = 1e-3 * curve_extent(param.curve);
  const Counts c = counts(param.curve, tolerance);
  SCOPED_TRACE(param.curve.name + ": adaptive " + std::to_string(c.adaptive) + ", greedy " + std::to_string(c.greedy) +
               ", uniform " + std::to_string(c.uniform.samples) + " (STEPS " + std::to_string(c.uniform.steps) + ")");
  EXPECT_LE(c.deviation, tolerance);
  ASSERT_TRUE(c.uniform.found);
  EXPECT_LE(c.uniform.deviation, tolerance);
  // Wang's formula gives a sufficient uniform count: never fewer STEPS than the smallest.
  if (has_control_points(param.curve.kind())) {
    EXPECT_LE(c.uniform.steps, wang_uniform_steps(param.curve, tolerance));
  }
  // The greedy keeps the adaptive sampling's constraints, so it is a near lower bound.
  EXPECT_LE(ratio(c.adaptive, c.greedy), 1.2);
  EXPECT_LE(ratio(c.adaptive, c.uniform.samples), 1.2);
  if (param.varying) {
    EXPECT_LT(ratio(c.adaptive, c.uniform.samples), 0.6);
  }
}

INSTANTIATE_TEST_SUITE_P(EveryKind, RepresentativeCurveTest, ::testing::ValuesIn(representative_curves()),
                         [](const ::testing::TestParamInfo<RepresentativeCurve>& test) {
                           return test.param.curve.name;
                         });

TEST(StarterCurves, NearTheGreedyCountWithinTheBound) {
  // Every curve of every starter file at D = 1e-3 of the scene's size, as `--tolerance` uses it.
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::directory_iterator(SWEEP_SWP_DIR)) {
    if (entry.path().extension() == ".swp") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  ASSERT_GE(files.size(), 15u);
  for (const auto& file : files) {
    const Document doc = io::load_swp_file(file);
    const double tolerance = 1e-3 * document_extent(doc);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      const Object& curve = doc.objects[i];
      if (!is_curve(curve.kind())) continue;
      const Counts c = counts(curve, tolerance);
      SCOPED_TRACE(file.filename().string() + " " + display_name(doc, static_cast<int>(i)) + ": adaptive " +
                   std::to_string(c.adaptive) + ", greedy " + std::to_string(c.greedy) + ", uniform " +
                   std::to_string(c.uniform.samples));
      EXPECT_LE(c.deviation, tolerance);
      EXPECT_LE(ratio(c.adaptive, c.greedy), 1.2);
      if (ratio(c.adaptive, c.uniform.samples) > 1.2) {
        // Only a uniform sampling that turns by more than kMaxTurn between samples may be that
        // much smaller (kochanek-bartels.swp's tense curve and its 0.06 circle): with the turn
        // limit the adaptive sampling keeps, uniform sampling needs more.
        const UniformCurve limited = best_uniform_steps(curve, tolerance, true);
        EXPECT_LE(ratio(c.adaptive, limited.samples), 1.2);
        EXPECT_GT(limited.steps, c.uniform.steps);
      }
    }
  }
}

TEST(GreedySampleCount, CircleNeedsTheCircleFormula) {
  // Every chord of a circle over the angle 2 pi / n strays r (1 - cos(pi / n)): the greedy steps
  // are as long as the formula's, so both count the same (the last sample repeats the first).
  Object circle;
  circle.set_kind(ObjectKind::Circle);
  circle.as<sweep::RadiusPart>().radius = 2.0;
  circle.as<sweep::StepsPart>().steps = 16;
  for (const double tolerance : {1e-2, 1e-3}) {
    EXPECT_EQ(greedy_sample_count(circle, tolerance), static_cast<std::size_t>(circle_segments(2.0, tolerance)) + 1);
  }
}

TEST(GreedySampleCount, KeepsJointsAndStraightPiecesTakeOneStep) {
  // Three straight pieces: one step each, four samples.
  Object line;
  line.set_kind(ObjectKind::Bezier2);
  line.as<sweep::StepsPart>().steps = 4;
  for (int i = 0; i <= 9; ++i) line.as<sweep::PointsPart>().points.emplace_back(i, 0.0, 0.0);
  EXPECT_EQ(greedy_sample_count(line, 1e-3), 4u);
}

TEST(BestUniformSteps, IsTheSmallestPassingSteps) {
  Object circle;
  circle.set_kind(ObjectKind::Circle);
  circle.as<sweep::RadiusPart>().radius = 1.0;
  circle.as<sweep::StepsPart>().steps = 8;
  const UniformCurve u = best_uniform_steps(circle, 1e-3);
  // A uniform circle of n segments strays 1 - cos(pi / n): the formula's n is the smallest.
  EXPECT_EQ(u.steps, circle_segments(1.0, 1e-3));
  EXPECT_EQ(u.samples, static_cast<std::size_t>(u.steps) + 1);
  EXPECT_LE(u.deviation, 1e-3);
}

TEST(BestUniformSurface, IsTheSmallestMeshOfAnExhaustiveSearch) {
  // flircle.swp at a coarse target (small meshes): every pair of STEPS up to 16 x 16, smallest
  // sweep STEPS first, gives no passing mesh with fewer triangles than the search's.
  const Document doc = io::load_swp_file(std::filesystem::path(SWEEP_SWP_DIR) / "flircle.swp");
  const int index = doc.find("flircle");
  EvaluationOptions adaptive;
  adaptive.tolerance = 1e-2 * document_extent(doc);
  const double target = surface_deviation(doc, evaluate_document(doc, adaptive), index, adaptive, 4);
  const UniformSurface found = best_uniform_surface(doc, index, target, 4);
  ASSERT_TRUE(found.found);
  EXPECT_LE(found.deviation, target);
  for (int p = 1; p <= 16; ++p) {
    for (int s = 1; s <= 16; ++s) {
      const Document uniform = uniform_surface_document(doc, index, p, s);
      const Scene scene = evaluate_document(uniform);
      if (scene.objects.back().mesh.triangle_count() >= found.triangles) break;
      const int surface = static_cast<int>(uniform.objects.size()) - 1;
      EXPECT_GT(surface_deviation(uniform, scene, surface, {}, 4), target) << "profile " << p << ", sweep " << s;
    }
  }
}

}  // namespace
}  // namespace sweep::sampling
