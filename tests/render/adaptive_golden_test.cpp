// Image regression of adaptive sampling (--tolerance): the wireframes show the samples gathering
// where the curves turn and thinning out where they run straight. A coarse tolerance (1 % of the
// scene's size) keeps the triangles big enough to see at the goldens' size.
#include "geometry/curves/adaptive.hpp"
#include "golden_support.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <gtest/gtest.h>

#include <string>

namespace sweep::test {
namespace {

class AdaptiveGoldenTest : public ::testing::TestWithParam<const char*> {};

TEST_P(AdaptiveGoldenTest, MatchesGolden) {
  const std::string stem = GetParam();
  const LoadedScene uniform = load_starter(stem);
  EvaluationOptions options;
  options.tolerance = 1e-2 * document_extent(uniform.doc);
  const LoadedScene loaded = load_starter(stem, options);
  EXPECT_TRUE(matches_golden(render_golden_picture(loaded, GoldenMode::Wire), stem + "-adaptive-wire",
                             limits_for(GoldenMode::Wire)));
}

INSTANTIATE_TEST_SUITE_P(StarterFiles, AdaptiveGoldenTest, ::testing::Values("weird", "wineglass", "flircle"));

}  // namespace
}  // namespace sweep::test
