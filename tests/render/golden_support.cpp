#include "golden_support.hpp"

#include "io/swp_parser.hpp"
#include "render/png_file.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string_view>

namespace sweep::test {

std::string name_of(GoldenMode mode) {
  switch (mode) {
    case GoldenMode::Smooth:
      return "smooth";
    case GoldenMode::Wire:
      return "wire";
    case GoldenMode::Frames:
      return "frames";
  }
  return "?";
}

render::DisplaySettings settings_for(GoldenMode mode) {
  render::DisplaySettings settings;
  switch (mode) {
    case GoldenMode::Smooth:
      settings.surface = render::SurfaceMode::Smooth;
      settings.curves = render::CurveMode::Curves;
      break;
    case GoldenMode::Wire:
      settings.surface = render::SurfaceMode::WireNormals;
      settings.curves = render::CurveMode::Curves;
      break;
    case GoldenMode::Frames:
      settings.surface = render::SurfaceMode::Off;
      settings.curves = render::CurveMode::Frames;
      settings.control_points = true;
      break;
  }
  return settings;
}

LoadedScene load_starter(const std::string& stem, const EvaluationOptions& options) {
  LoadedScene loaded;
  const std::filesystem::path file = std::filesystem::path(SWEEP_SWP_DIR) / (stem + ".swp");
  loaded.doc = load_swp_file(file);
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

::testing::AssertionResult matches_golden(const render::Image& actual, const std::string& name,
                                          const Tolerance& tolerance) {
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
  const Comparison comparison = compare_images(actual, expected, tolerance);
  if (comparison.passes(tolerance)) return ::testing::AssertionSuccess() << comparison.summary();

  const fs::path out_dir = fs::path(SWEEP_GOLDEN_OUTPUT_DIR);
  fs::create_directories(out_dir);
  const fs::path actual_path = out_dir / (name + "-actual.png");
  const fs::path diff_path = out_dir / (name + "-diff.png");
  render::save_png_file(actual_path, actual);
  if (comparison.same_size) render::save_png_file(diff_path, difference_image(actual, expected, tolerance));
  char allowed[96];
  std::snprintf(allowed, sizeof allowed, "allowed: %.2f%% of pixels over channel difference %d",
                100.0 * tolerance.max_differing_share, tolerance.channel_threshold);
  return ::testing::AssertionFailure() << name << " differs from " << golden.string() << ": " << comparison.summary()
                                       << " (" << allowed << ")\n  actual: " << actual_path.string()
                                       << "\n  diff:   " << diff_path.string();
}

}  // namespace sweep::test
