#include "golden_support.hpp"

#include "io/swp/read.hpp"
#include "render/png_file.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string_view>

namespace sweep::test {
namespace {

// Pixels that may differ after the forgiving, of 76,800; every limit is at most half of the
// smallest mistake comparator_test.cpp makes in its mode, so each fails by twice the limit.
// Smooth: shading changes little under another rasterizer and its edges are forgiven; the noise
// test's 76 stray pixels pass (69 are left), a surface moved by 3% (1,182) fails.
constexpr std::size_t kSmoothLimit = 150;
// Wire: a dense wireframe turns a tiny change into scattered pixels (weird-wire has 190 against
// its golden after a change since it was rendered); the missing normals (4,216) fail.
constexpr std::size_t kWireLimit = 400;
// Frames: thin curves and frames; a curve moved by 0.1 (718 pixels), missing control points
// (727) and missing frames (915) fail.
constexpr std::size_t kFramesLimit = 150;

}  // namespace

LoadedScene load_starter(const std::string& stem, const EvaluationOptions& options) {
  LoadedScene loaded;
  const std::filesystem::path file = std::filesystem::path(SWEEP_SWP_DIR) / (stem + ".swp");
  loaded.doc = io::load_swp_file(file);
  loaded.folder = file.parent_path();
  loaded.scene = evaluate_document(loaded.doc, options);
  return loaded;
}

render::Camera golden_camera(const Scene& scene) {
  render::Camera camera;
  camera.reset(render::scene_bounds(scene), double(kGoldenWidth) / double(kGoldenHeight));
  return camera;
}

headless::HeadlessRenderer& shared_renderer() {
  static headless::HeadlessRenderer renderer("osmesa");
  return renderer;
}

render::Image render_golden_picture(const LoadedScene& loaded, GoldenMode mode) {
  return render_golden_picture(loaded, settings_for(mode));
}

render::Image render_golden_picture(const LoadedScene& loaded, const render::DisplaySettings& settings) {
  return shared_renderer().render(loaded.doc, loaded.scene, golden_camera(loaded.scene), {kGoldenWidth, kGoldenHeight},
                                  settings, loaded.folder);
}

render::Image load_golden(const std::string& name) {
  return render::load_png_file(std::filesystem::path(SWEEP_GOLDEN_DIR) / (name + ".png"));
}

snapshot::DiffOptions golden_options() {
  return {};
}

snapshot::DiffLimits limits_for(GoldenMode mode) {
  snapshot::DiffLimits limits;
  switch (mode) {
    case GoldenMode::Smooth:
      limits.max_diff_pixels = kSmoothLimit;
      break;
    case GoldenMode::Wire:
      limits.max_diff_pixels = kWireLimit;
      break;
    case GoldenMode::Frames:
      limits.max_diff_pixels = kFramesLimit;
      break;
  }
  limits.max_diff_ratio = 1.0;  // the goldens all have one size: the pixel count says it
  return limits;
}

::testing::AssertionResult matches_golden(const render::Image& actual, const std::string& name,
                                          const snapshot::DiffLimits& limits) {
  namespace fs = std::filesystem;
  const fs::path golden = fs::path(SWEEP_GOLDEN_DIR) / (name + ".png");
  const char* update = std::getenv("SWEEP_UPDATE_GOLDEN");
  if (update != nullptr && std::string_view(update) == "1") {
    render::save_png_file(golden, actual);
    return ::testing::AssertionSuccess() << "updated " << golden;
  }
  if (!fs::exists(golden)) {
    return ::testing::AssertionFailure() << "no golden " << golden
                                         << "; render it with SWEEP_UPDATE_GOLDEN=1 and look at it before committing";
  }
  const render::Image expected = render::load_png_file(golden);
  const snapshot::ImageDiff diff = snapshot::diff_images(actual, expected, golden_options());
  if (diff.passes(limits)) return ::testing::AssertionSuccess() << diff.summary();

  const fs::path out_dir = fs::path(SWEEP_GOLDEN_OUTPUT_DIR);
  fs::create_directories(out_dir);
  const fs::path actual_path = out_dir / (name + "-actual.png");
  const fs::path diff_path = out_dir / (name + "-diff.png");
  render::save_png_file(actual_path, actual);
  if (diff.same_size) render::save_png_file(diff_path, snapshot::heat_map(diff, expected));
  char allowed[96];
  std::snprintf(allowed, sizeof allowed, "allowed: %zu pixels, %.2f%% of the pixels", limits.max_diff_pixels,
                100.0 * limits.max_diff_ratio);
  return ::testing::AssertionFailure() << name << " differs from " << golden.string() << ": " << diff.summary() << " ("
                                       << allowed << ")\n  actual: " << actual_path.string()
                                       << "\n  diff:   " << diff_path.string();
}

}  // namespace sweep::test
