// Image regression: every starter SWP file in three modes at a fixed camera, compared with the
// PNGs in tests/golden/. Regenerate with SWEEP_UPDATE_GOLDEN=1 (then look at every picture).
#include "golden_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <tuple>

namespace sweep::test {
namespace {

const char* const kStarterFiles[] = {
    "birail", "bspline-patch", "catmull-rom",      "circles",  "core",   "corners",     "flircle", "florus", "gentorus",
    "helix",  "knots",         "kochanek-bartels", "norm",     "solids", "subdivision", "taper",   "teapot", "tor",
    "vase",   "weird",         "weirder",          "wineglass"};

class GoldenTest : public ::testing::TestWithParam<std::tuple<const char*, GoldenMode>> {};

TEST_P(GoldenTest, MatchesGolden) {
  const auto& [stem, mode] = GetParam();
  const LoadedScene loaded = load_starter(stem);
  const render::Image image = render_golden_picture(loaded, mode);
  EXPECT_TRUE(matches_golden(image, std::string(stem) + "-" + name_of(mode), limits_for(mode)));
}

INSTANTIATE_TEST_SUITE_P(StarterFiles, GoldenTest,
                         ::testing::Combine(::testing::ValuesIn(kStarterFiles),
                                            ::testing::Values(GoldenMode::Smooth, GoldenMode::Wire,
                                                              GoldenMode::Frames)),
                         [](const auto& test_info) {
                           // Test names are letters, digits and '_': "catmull-rom" becomes catmull_rom.
                           std::string stem = std::get<0>(test_info.param);
                           std::replace(stem.begin(), stem.end(), '-', '_');
                           return stem + "_" + name_of(std::get<1>(test_info.param));
                         });

}  // namespace
}  // namespace sweep::test
