// Appearance in pictures: the two artifact models (materials, a texture and a bump), every colour
// mode on a torus, and a flat bump image that must change nothing. Goldens as in golden_test.cpp
// (looked at before committing; regenerate with SWEEP_UPDATE_GOLDEN=1).
#include "golden_support.hpp"
#include "io/swp/read.hpp"
#include "render/png_file.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace sweep::test {
namespace {

render::DisplaySettings smooth_without_curves() {
  render::DisplaySettings settings = settings_for(GoldenMode::Smooth);
  settings.curves = render::CurveMode::Off;
  return settings;
}

TEST(AppearanceGolden, ChessQueenIsTexturedBumpedAndGilded) {
  const LoadedScene loaded = load_starter("artifacts/chess-queen");
  EXPECT_TRUE(matches_golden(render_golden_picture(loaded, smooth_without_curves()), "artifact-chess-queen",
                             limits_for(GoldenMode::Smooth)));
}

TEST(AppearanceGolden, TrefoilBraidShowsItsTwistInTheChecker) {
  const LoadedScene loaded = load_starter("artifacts/trefoil-braid");
  EXPECT_TRUE(matches_golden(render_golden_picture(loaded, smooth_without_curves()), "artifact-trefoil-braid",
                             limits_for(GoldenMode::Smooth)));
}

class ColorModeGolden : public ::testing::TestWithParam<render::ColorMode> {};

TEST_P(ColorModeGolden, TorusMatchesGolden) {
  EvaluationOptions options;
  options.texture_coordinates = render::texture_coordinates_drawn(GetParam());
  const LoadedScene loaded = load_starter("tor", options);
  render::DisplaySettings settings = smooth_without_curves();
  settings.color = GetParam();
  const std::string name = "colors-tor-" + std::string(render::name_of(GetParam()));
  EXPECT_TRUE(matches_golden(render_golden_picture(loaded, settings), name, limits_for(GoldenMode::Smooth)));
}

INSTANTIATE_TEST_SUITE_P(Modes, ColorModeGolden,
                         ::testing::Values(render::ColorMode::Gaussian, render::ColorMode::Mean,
                                           render::ColorMode::Normals, render::ColorMode::Uv),
                         [](const auto& test_info) { return std::string(render::name_of(test_info.param)); });

TEST(Appearance, AFlatBumpImageRendersExactlyLikeNoBump) {
  // A uniform grey height image has no gradient: the bumped normal is the normal itself.
  const ScratchFolder folder("sweep-flat-bump");
  const std::filesystem::path& dir = folder.path();
  const std::filesystem::path grain = std::filesystem::path(SWEEP_SWP_DIR) / "artifacts" / "grain.png";
  std::filesystem::copy_file(grain, dir / "grain.png", std::filesystem::copy_options::overwrite_existing);
  render::Image flat_image;  // a uniform grey height image
  flat_image.width = flat_image.height = 8;
  flat_image.rgba.assign(8 * 8 * 4, 128);
  render::save_png_file(dir / "flat.png", flat_image);
  const auto picture = [&dir](const std::string& material) {
    LoadedScene loaded;
    loaded.doc =
        io::parse_swp(material + "\ncirc c 24 1\ncirc s 48 3\ngcyl t c s material m\n", (dir / "t.swp").string());
    loaded.scene = evaluate_document(loaded.doc);
    loaded.folder = dir;
    return render_golden_picture(loaded, settings_for(GoldenMode::Smooth));
  };
  const render::Image plain = picture("material m checker 4");
  const render::Image flat = picture("material m checker 4 bump flat.png 0.5");
  const render::Image bumped = picture("material m checker 4 bump grain.png 0.05");
  EXPECT_EQ(flat.rgba, plain.rgba) << "a flat height image changed the picture";
  EXPECT_NE(bumped.rgba, plain.rgba) << "a real height image changed nothing";
}

TEST(Appearance, AnImageGoneWhenDrawingFallsBackToTheColourWithAWarning) {
  // The image was there when the file was read and is gone when the surface is drawn.
  const ScratchFolder folder("sweep-gone-image");
  const std::filesystem::path& dir = folder.path();
  std::filesystem::copy_file(std::filesystem::path(SWEEP_SWP_DIR) / "artifacts" / "wood.png", dir / "gone.png",
                             std::filesystem::copy_options::overwrite_existing);
  LoadedScene loaded;
  loaded.doc = io::parse_swp(
      "material m color 0.2 0.6 0.3 texture gone.png\ncirc c 24 1\ncirc s 48 3\ngcyl t c s "
      "material m\n",
      (dir / "t.swp").string());
  loaded.scene = evaluate_document(loaded.doc);
  loaded.folder = dir;
  std::filesystem::remove(dir / "gone.png");
  headless::HeadlessRenderer renderer;  // its own, so no texture is cached from another test
  const render::Image picture = renderer.render(loaded.doc, loaded.scene, golden_camera(loaded.scene),
                                                {kGoldenWidth, kGoldenHeight}, settings_for(GoldenMode::Smooth), dir);
  ASSERT_EQ(renderer.renderer().stats().warnings.size(), 1u);
  EXPECT_NE(renderer.renderer().stats().warnings[0].find("gone.png"), std::string::npos);
  // Drawn in its colour: the same picture as the material without a texture.
  LoadedScene plain = loaded;
  plain.doc.objects[0].as<sweep::MaterialLook>().texture.clear();
  plain.scene = evaluate_document(plain.doc);
  const render::Image expected = renderer.render(plain.doc, plain.scene, golden_camera(plain.scene),
                                                 {kGoldenWidth, kGoldenHeight}, settings_for(GoldenMode::Smooth), dir);
  EXPECT_EQ(picture.rgba, expected.rgba);
}

}  // namespace
}  // namespace sweep::test
