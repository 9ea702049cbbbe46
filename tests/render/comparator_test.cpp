// The golden comparison must pass rasterizer noise and fail on the mistakes it exists to catch:
// a flipped normal, a missing draw mode, a moved object. Each mistake is made on purpose here
// and compared against the real golden.
#include "golden_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <string>

namespace sweep::test {
namespace {

/// Revisions far above the core's counter, so the renderer re-uploads each altered scene.
std::uint64_t altered_revision() {
  static std::uint64_t next = std::uint64_t{1} << 60;
  return ++next;
}

snapshot::DiffLimits smooth_limits() {
  return limits_for(GoldenMode::Smooth);
}

/// The most pixels `limits` lets differ in a picture of the goldens' size.
double allowed_pixels(const snapshot::DiffLimits& limits) {
  return std::min(double(limits.max_diff_pixels), limits.max_diff_ratio * double(kGoldenWidth * kGoldenHeight));
}

/// Fails by a margin, not by a hair: at least twice the allowed pixels differ after forgiving.
void expect_clear_failure(const snapshot::ImageDiff& d, const snapshot::DiffLimits& limits, const std::string& what) {
  EXPECT_FALSE(d.passes(limits)) << what << ": " << d.summary();
  EXPECT_GT(double(d.differing_pixels), 2.0 * allowed_pixels(limits)) << what << ": " << d.summary();
  std::printf("%s: %s\n", what.c_str(), d.summary().c_str());
}

snapshot::ImageDiff compare(const render::Image& actual, const render::Image& reference) {
  return snapshot::diff_images(actual, reference, golden_options());
}

snapshot::ImageDiff compare_with_golden(const render::Image& image, const std::string& name) {
  return compare(image, load_golden(name));
}

TEST(GoldenComparator, IdenticalImagesPass) {
  const render::Image golden = load_golden("weird-smooth");
  const snapshot::ImageDiff d = compare(golden, golden);
  EXPECT_TRUE(d.passes(smooth_limits()));
  EXPECT_EQ(d.max_distance, 0.0);
  EXPECT_EQ(d.differing_pixels, 0u);
  EXPECT_EQ(d.summary(), "identical");
}

TEST(GoldenComparator, RasterizerNoisePasses) {
  // Small changes everywhere (dithering, rounding) and a few stray pixels (edge coverage).
  const render::Image golden = load_golden("weird-smooth");
  render::Image noisy = golden;
  std::uint32_t state = 12345;
  const auto random = [&state] {
    state = state * 1664525u + 1013904223u;
    return state >> 8;
  };
  for (std::size_t i = 0; i < noisy.rgba.size(); ++i) {
    if (i % 4 == 3) continue;
    const int delta = int(random() % 17) - 8;
    noisy.rgba[i] = static_cast<std::uint8_t>(std::clamp(int(noisy.rgba[i]) + delta, 0, 255));
  }
  const std::size_t pixels = std::size_t(golden.width) * std::size_t(golden.height);
  for (std::size_t k = 0; k < pixels / 1000; ++k) {  // 0.1% of the pixels, changed a lot
    const std::size_t p = random() % pixels;
    noisy.rgba[p * 4] = static_cast<std::uint8_t>(255 - noisy.rgba[p * 4]);
  }
  const snapshot::ImageDiff d = compare(noisy, golden);
  EXPECT_TRUE(d.passes(smooth_limits())) << d.summary();
  std::printf("rasterizer noise, weird: %s\n", d.summary().c_str());
  // The stray pixels are reported: most of them differ (their red inverted is far off, nothing
  // near has their colour), the small changes everywhere do not.
  EXPECT_GT(d.differing_pixels, pixels / 2000) << d.summary();
  EXPECT_LE(d.differing_pixels, pixels / 1000) << d.summary();
  EXPECT_GT(d.max_distance, 0.3) << d.summary();
}

TEST(GoldenComparator, SizeMismatchFails) {
  const render::Image golden = load_golden("tor-smooth");
  render::Image cropped = golden;
  cropped.height -= 1;
  cropped.rgba.resize(std::size_t(cropped.width) * std::size_t(cropped.height) * 4);
  const snapshot::ImageDiff d = compare(cropped, golden);
  EXPECT_FALSE(d.passes(smooth_limits()));
  EXPECT_EQ(d.summary(), "the images differ in size (320x239 against 320x240)");
}

TEST(GoldenComparator, FreshRenderPasses) {
  const LoadedScene loaded = load_starter("weird");
  const snapshot::ImageDiff d = compare_with_golden(render_golden_picture(loaded, GoldenMode::Smooth), "weird-smooth");
  EXPECT_TRUE(d.passes(smooth_limits())) << d.summary();
}

TEST(GoldenComparator, FlippedNormalsFail) {
  for (const char* stem : {"weird", "wineglass", "tor"}) {
    LoadedScene loaded = load_starter(stem);
    for (EvaluatedObject& object : loaded.scene.objects) {
      for (glm::vec3& n : object.mesh.normals) n = -n;
      object.revision = altered_revision();
    }
    const snapshot::ImageDiff d =
        compare_with_golden(render_golden_picture(loaded, GoldenMode::Smooth), std::string(stem) + "-smooth");
    expect_clear_failure(d, smooth_limits(), std::string("flipped normals, ") + stem);
  }
}

TEST(GoldenComparator, FlippedNormalsFailWithOneSidedLighting) {
  // Also when only the lit side changes: one-sided lighting, normals flipped.
  LoadedScene loaded = load_starter("gentorus");
  render::DisplaySettings settings = settings_for(GoldenMode::Smooth);
  const render::Image reference = shared_renderer().render(loaded.doc, loaded.scene, golden_camera(loaded.scene),
                                                           {kGoldenWidth, kGoldenHeight}, settings);
  for (EvaluatedObject& object : loaded.scene.objects) {
    for (glm::vec3& n : object.mesh.normals) n = -n;
    object.revision = altered_revision();
  }
  settings.material.two_sided = false;
  const render::Image flipped = shared_renderer().render(loaded.doc, loaded.scene, golden_camera(loaded.scene),
                                                         {kGoldenWidth, kGoldenHeight}, settings);
  expect_clear_failure(compare(flipped, reference), smooth_limits(), "flipped normals, one-sided, gentorus");
}

TEST(GoldenComparator, MissingModeFails) {
  // Each against the limits its golden is checked with.
  {
    // Frames missing: plain curves (with control points) against the frames golden.
    const LoadedScene loaded = load_starter("core");
    render::DisplaySettings settings = settings_for(GoldenMode::Frames);
    settings.curves = render::CurveMode::Curves;
    const snapshot::ImageDiff d =
        compare_with_golden(shared_renderer().render(loaded.doc, loaded.scene, golden_camera(loaded.scene),
                                                     {kGoldenWidth, kGoldenHeight}, settings),
                            "core-frames");
    expect_clear_failure(d, limits_for(GoldenMode::Frames), "frames missing, core");
  }
  {
    // Control points missing.
    const LoadedScene loaded = load_starter("core");
    render::DisplaySettings settings = settings_for(GoldenMode::Frames);
    settings.control_points = false;
    const snapshot::ImageDiff d =
        compare_with_golden(shared_renderer().render(loaded.doc, loaded.scene, golden_camera(loaded.scene),
                                                     {kGoldenWidth, kGoldenHeight}, settings),
                            "core-frames");
    expect_clear_failure(d, limits_for(GoldenMode::Frames), "control points missing, core");
  }
  {
    // Normal segments missing from the wireframe.
    const LoadedScene loaded = load_starter("wineglass");
    render::DisplaySettings settings = settings_for(GoldenMode::Wire);
    settings.normal_length = 0.0f;
    const snapshot::ImageDiff d =
        compare_with_golden(shared_renderer().render(loaded.doc, loaded.scene, golden_camera(loaded.scene),
                                                     {kGoldenWidth, kGoldenHeight}, settings),
                            "wineglass-wire");
    expect_clear_failure(d, limits_for(GoldenMode::Wire), "normals missing, wineglass");
  }
  {
    // Wireframe instead of smooth shading.
    const LoadedScene loaded = load_starter("norm");
    const snapshot::ImageDiff d = compare_with_golden(render_golden_picture(loaded, GoldenMode::Wire), "norm-smooth");
    expect_clear_failure(d, smooth_limits(), "wireframe instead of smooth, norm");
  }
}

TEST(GoldenComparator, MovedObjectFails) {
  // The surface of weird.swp moved by 3% of the scene's size, everything else in place. The
  // camera stays where the golden had it.
  LoadedScene loaded = load_starter("weird");
  const render::Camera camera = golden_camera(loaded.scene);
  const auto shift = static_cast<float>(0.03 * render::scene_bounds(loaded.scene).radius());
  for (EvaluatedObject& object : loaded.scene.objects) {
    if (object.mesh.positions.empty()) continue;
    for (glm::vec3& p : object.mesh.positions) p.x += shift;
    object.revision = altered_revision();
  }
  const snapshot::ImageDiff d =
      compare_with_golden(shared_renderer().render(loaded.doc, loaded.scene, camera, {kGoldenWidth, kGoldenHeight},
                                                   settings_for(GoldenMode::Smooth)),
                          "weird-smooth");
  expect_clear_failure(d, smooth_limits(), "surface moved by 3% of the scene radius, weird");

  // A curve moved in the frames picture.
  LoadedScene curves = load_starter("circles");
  const render::Camera curve_camera = golden_camera(curves.scene);
  for (Frame& f : curves.scene.objects[0].curve.frames) f.V.y += 0.1;
  curves.scene.objects[0].revision = altered_revision();
  const snapshot::ImageDiff moved_curve =
      compare_with_golden(shared_renderer().render(curves.doc, curves.scene, curve_camera,
                                                   {kGoldenWidth, kGoldenHeight}, settings_for(GoldenMode::Frames)),
                          "circles-frames");
  expect_clear_failure(moved_curve, limits_for(GoldenMode::Frames), "curve moved by 0.1, circles");
}

}  // namespace
}  // namespace sweep::test
