// The stats panel's numbers for adaptive sampling: both ways of counting, the slider's range and
// the objects a tolerance is too small for.
#include "editor/adaptive_stats.hpp"
#include "geometry/curves/adaptive.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string_view>

namespace sweep::editor {
namespace {

Document starter(const char* stem) {
  return io::load_swp_file(std::filesystem::path(SWEEP_SWP_DIR) / (std::string(stem) + ".swp"));
}

TEST(AdaptiveStats, StepsCountsEqualAnEvaluationByStepsOfEveryStarterFile) {
  for (const char* stem : {"tor", "weird", "wineglass", "flircle", "corners", "helix", "knots", "catmull-rom"}) {
    const Document doc = starter(stem);
    const SamplingCounts by_steps = scene_counts(evaluate_document(doc));
    EvaluationOptions adaptive;
    adaptive.tolerance = 1e-2 * document_extent(doc);
    // Counted on the adaptive scene: the formulas need only the curves' closedness from it.
    const SamplingCounts counted = steps_counts(doc, evaluate_document(doc, adaptive));
    EXPECT_EQ(counted.vertices, by_steps.vertices) << stem;
    // The formulas count the triangles of no area that corners.swp's tubes leave out (16,
    // surface_test.cpp's worked counts): for the stats panel an upper bound.
    const std::int64_t left_out = std::string_view(stem) == "corners" ? 16 : 0;
    EXPECT_EQ(counted.triangles, by_steps.triangles + left_out) << stem;
    EXPECT_EQ(counted.curve_samples, by_steps.curve_samples) << stem;
  }
}

TEST(AdaptiveStats, AdaptiveWeirdIsSmallerThanBySteps) {
  const Document doc = starter("weird");
  EvaluationOptions options;
  options.tolerance = 1e-2 * document_extent(doc);
  const Scene scene = evaluate_document(doc, options);
  EXPECT_LT(scene_counts(scene).triangles, steps_counts(doc, scene).triangles);
  EXPECT_GT(scene_counts(scene).triangles, 0);
}

TEST(AdaptiveStats, HiddenObjectsAreLeftOutOfBothCounts) {
  const Document doc = starter("wineglass");  // a profile curve and its surface of revolution
  const int surface = doc.find("wineglass");
  const int profile = doc.find("profile");
  ASSERT_GE(surface, 0);
  ASSERT_GE(profile, 0);
  EvaluationOptions options;
  options.tolerance = 1e-2 * document_extent(doc);
  const Scene scene = evaluate_document(doc, options);
  const SamplingCounts all_adaptive = scene_counts(scene);
  const SamplingCounts all_steps = steps_counts(doc, scene);

  std::vector<bool> visible(doc.objects.size(), true);
  visible[std::size_t(surface)] = false;
  EXPECT_EQ(scene_counts(scene, visible).vertices, 0);
  EXPECT_EQ(steps_counts(doc, scene, visible).vertices, 0);
  EXPECT_EQ(scene_counts(scene, visible).curve_samples, all_adaptive.curve_samples);
  EXPECT_EQ(steps_counts(doc, scene, visible).curve_samples, all_steps.curve_samples);

  // A hidden profile still shapes its visible surface: the surface's counts stay.
  visible.assign(doc.objects.size(), true);
  visible[std::size_t(profile)] = false;
  EXPECT_EQ(steps_counts(doc, scene, visible).vertices, all_steps.vertices);
  EXPECT_EQ(steps_counts(doc, scene, visible).triangles, all_steps.triangles);
  EXPECT_EQ(scene_counts(scene, visible).vertices, all_adaptive.vertices);
  EXPECT_EQ(steps_counts(doc, scene, visible).curve_samples, 0);
}

TEST(AdaptiveStats, AdaptiveMeansTheViewersToleranceOrACurvesClause) {
  Document doc = starter("tor");
  EXPECT_FALSE(any_adaptive(doc, {}));
  EvaluationOptions options;
  options.tolerance = 0.01;
  EXPECT_TRUE(any_adaptive(doc, options));
  doc.objects[0].as<sweep::TolerancePart>().tolerance = 0.01;
  EXPECT_TRUE(any_adaptive(doc, {}));
}

TEST(AdaptiveStats, SummaryByStepsIsTheSampledCountWithoutATolerance) {
  const Document doc = starter("weird");
  const Scene scene = evaluate_document(doc);
  const SamplingSummary summary = sampling_summary(doc, scene, {});
  EXPECT_FALSE(summary.adaptive);
  EXPECT_EQ(summary.sampled.vertices, summary.by_steps.vertices);
  EXPECT_TRUE(summary.over_limit.empty());
}

TEST(AdaptiveStats, SummaryWithAToleranceCountsBothWays) {
  const Document doc = starter("weird");
  EvaluationOptions options;
  options.tolerance = 1e-3 * document_extent(doc);
  const SamplingSummary summary = sampling_summary(doc, evaluate_document(doc, options), options);
  EXPECT_TRUE(summary.adaptive);
  EXPECT_EQ(summary.by_steps.vertices, scene_counts(evaluate_document(doc)).vertices);
  EXPECT_NE(summary.sampled.vertices, summary.by_steps.vertices);
  EXPECT_TRUE(summary.over_limit.empty());
}

TEST(AdaptiveStats, SummaryLineShowsByStepsOnlyWhenAdaptive) {
  SamplingSummary summary;
  summary.sampled = {120, 200, 31};
  summary.by_steps = {480, 900, 65};
  EXPECT_EQ(summary_line(summary), "vertices 120 triangles 200 curve samples 31");
  summary.adaptive = true;
  EXPECT_EQ(summary_line(summary),
            "vertices 120 (by STEPS 480) triangles 200 (by STEPS 900) curve samples 31 (by STEPS 65)");
}

TEST(AdaptiveStats, ShareIsAWholePercentage) {
  EXPECT_EQ(share_text(120, 480), "25 %");
  EXPECT_EQ(share_text(2, 3), "67 %");
  EXPECT_EQ(share_text(500, 400), "125 %");
  EXPECT_EQ(share_text(2050, 100), "21x");
  EXPECT_EQ(share_text(5, 0), "-");
}

TEST(AdaptiveStats, ToleranceRangeRunsFromTheFloorToATenthOfTheScene) {
  const ToleranceRange range = tolerance_range(5.0);
  EXPECT_DOUBLE_EQ(range.low, kMinRelativeTolerance * 5.0);
  EXPECT_DOUBLE_EQ(range.high, 0.5);
  EXPECT_EQ(tolerance_range(0.0).high, 0.0);
  EXPECT_DOUBLE_EQ(default_tolerance(5.0), 5e-3);
  EXPECT_EQ(default_tolerance(0.0), 0.0);
}

TEST(AdaptiveStats, TheSliderRunsLogarithmicallyOverTheRange) {
  const ToleranceRange range = tolerance_range(5.0);  // 5e-6 to 0.5: five decades
  EXPECT_DOUBLE_EQ(tolerance_at(range, 0.0), 5e-6);
  EXPECT_DOUBLE_EQ(tolerance_at(range, 1.0), 0.5);
  EXPECT_DOUBLE_EQ(tolerance_at(range, 0.6), 5e-3);  // three decades of five
  EXPECT_DOUBLE_EQ(tolerance_at(range, -1.0), 5e-6);
  EXPECT_DOUBLE_EQ(tolerance_at(range, 2.0), 0.5);
  EXPECT_NEAR(slider_position(range, 5e-3), 0.6, 1e-12);
  EXPECT_EQ(slider_position(range, 1e-9), 0.0);
  EXPECT_EQ(slider_position(range, 7.0), 1.0);
  // Every value the slider gives is what it shows, and goes back to the same place.
  for (int i = 0; i <= 100; ++i) {
    const double d = tolerance_at(range, i / 100.0);
    EXPECT_EQ(std::strtod(tolerance_text(d).c_str(), nullptr), d) << i;
    EXPECT_EQ(tolerance_at(range, slider_position(range, d)), d) << i;
  }
}

TEST(AdaptiveStats, TheSliderShowsWhatItUsesForAnyScene) {
  for (double extent : {5.574845289333149, 0.0123456, 7654.321}) {
    const ToleranceRange range = tolerance_range(extent);
    for (int i = 0; i <= 200; ++i) {
      const double d = tolerance_at(range, i / 200.0);
      EXPECT_GE(d, range.low) << extent << " " << i;
      EXPECT_LE(d, range.high) << extent << " " << i;
      EXPECT_EQ(std::strtod(tolerance_text(d).c_str(), nullptr), d) << extent << " " << i;
    }
  }
}

TEST(AdaptiveStats, ToleranceTextHasThreeSignificantDigits) {
  EXPECT_EQ(tolerance_text(0.0055748452), "5.57e-03");
  EXPECT_EQ(tolerance_text(12.0), "1.20e+01");
}

TEST(AdaptiveStats, OverLimitObjectsAreNamed) {
  const Document doc = starter("tor");
  Scene scene = evaluate_document(doc);
  EXPECT_TRUE(over_limit_messages(doc, scene, 0.0).empty());
  scene.objects[1].over_limit = true;  // as evaluate_document marks a curve past the sample cap
  const std::vector<std::string> messages = over_limit_messages(doc, scene, 1e-9);
  ASSERT_EQ(messages.size(), 1u);
  EXPECT_EQ(messages[0],
            "tolerance 1e-09 is too small for 'sweep': it needs more than 10000000 samples per curve or 50000000 "
            "vertices per surface; use a larger one (sampled by STEPS instead)");
  scene.objects[1].over_limit = false;
  scene.objects[2].over_limit = true;  // a surface: built on its curves' samples instead
  const std::vector<std::string> surface = over_limit_messages(doc, scene, 1e-9);
  ASSERT_EQ(surface.size(), 1u);
  EXPECT_NE(surface[0].find("too small for '" + display_name(doc, 2) + "'"), std::string::npos) << surface[0];
  EXPECT_NE(surface[0].find("(meshed on its curves' own samples instead, not within it)"), std::string::npos)
      << surface[0];
}

}  // namespace
}  // namespace sweep::editor
