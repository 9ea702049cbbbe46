// The stats panel's numbers for adaptive sampling: both ways of counting, the slider's range and
// the objects a tolerance is too small for.
#include "core/adaptive.hpp"
#include "core/swp_parser.hpp"
#include "editor/adaptive_stats.hpp"

#include <gtest/gtest.h>

#include <filesystem>

namespace sweep::editor {
namespace {

Document starter(const char* stem) {
  return load_swp_file(std::filesystem::path(SWEEP_SWP_DIR) / (std::string(stem) + ".swp"));
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
    EXPECT_EQ(counted.triangles, by_steps.triangles) << stem;
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

TEST(AdaptiveStats, ToleranceRangeRunsFromTheFloorToATenthOfTheScene) {
  const ToleranceRange range = tolerance_range(5.0);
  EXPECT_DOUBLE_EQ(range.low, kMinRelativeTolerance * 5.0);
  EXPECT_DOUBLE_EQ(range.high, 0.5);
  EXPECT_EQ(tolerance_range(0.0).high, 0.0);
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
            "vertices per surface; use a larger one");
}

}  // namespace
}  // namespace sweep::editor
