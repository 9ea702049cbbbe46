// The golden comparison must pass rasterizer noise and fail on the mistakes it exists to catch:
// a flipped normal, a missing draw mode, a moved object. Each mistake is made on purpose here
// and compared against the real golden.
#include "golden_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
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

Tolerance smooth_tolerance() {
  return Tolerance{};
}

/// Fails by a margin, not by a hair: at least twice the allowed share of pixels differ.
void expect_clear_failure(const Comparison& c, const Tolerance& tolerance, const std::string& what) {
  EXPECT_FALSE(c.passes(tolerance)) << what << ": " << c.summary();
  EXPECT_GT(c.differing_share, 2.0 * tolerance.max_differing_share) << what << ": " << c.summary();
  std::printf("%s: %s\n", what.c_str(), c.summary().c_str());
}

Comparison compare_with_golden(const render::Image& image, const std::string& name, const Tolerance& tolerance) {
  return compare_images(image, load_golden(name), tolerance);
}

TEST(GoldenComparator, IdenticalImagesPass) {
  const render::Image golden = load_golden("weird-smooth");
  const Comparison c = compare_images(golden, golden, smooth_tolerance());
  EXPECT_TRUE(c.passes(smooth_tolerance()));
  EXPECT_EQ(c.max_channel_difference, 0);
  EXPECT_EQ(c.differing_pixels, 0u);
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
  const Comparison c = compare_images(noisy, golden, smooth_tolerance());
  EXPECT_TRUE(c.passes(smooth_tolerance())) << c.summary();
  EXPECT_GT(c.max_channel_difference, 100);  // the stray pixels are reported
}

TEST(GoldenComparator, SizeMismatchFails) {
  const render::Image golden = load_golden("tor-smooth");
  render::Image cropped = golden;
  cropped.height -= 1;
  cropped.rgba.resize(std::size_t(cropped.width) * std::size_t(cropped.height) * 4);
  EXPECT_FALSE(compare_images(cropped, golden, smooth_tolerance()).passes(smooth_tolerance()));
}

TEST(GoldenComparator, FreshRenderPasses) {
  const LoadedScene loaded = load_starter("weird");
  const Comparison c =
      compare_with_golden(render_golden_picture(loaded, GoldenMode::Smooth), "weird-smooth", smooth_tolerance());
  EXPECT_TRUE(c.passes(smooth_tolerance())) << c.summary();
}

TEST(GoldenComparator, FlippedNormalsFail) {
  for (const char* stem : {"weird", "wineglass", "tor"}) {
    LoadedScene loaded = load_starter(stem);
    for (EvaluatedObject& object : loaded.scene.objects) {
      for (glm::vec3& n : object.mesh.normals) n = -n;
      object.revision = altered_revision();
    }
    const Comparison c = compare_with_golden(render_golden_picture(loaded, GoldenMode::Smooth),
                                             std::string(stem) + "-smooth", smooth_tolerance());
    expect_clear_failure(c, smooth_tolerance(), std::string("flipped normals, ") + stem);
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
  expect_clear_failure(compare_images(flipped, reference, smooth_tolerance()), smooth_tolerance(),
                       "flipped normals, one-sided, gentorus");
}

TEST(GoldenComparator, MissingModeFails) {
  const Tolerance tolerance;
  {
    // Frames missing: plain curves (with control points) against the frames golden.
    const LoadedScene loaded = load_starter("core");
    render::DisplaySettings settings = settings_for(GoldenMode::Frames);
    settings.curves = render::CurveMode::Curves;
    const Comparison c =
        compare_with_golden(shared_renderer().render(loaded.doc, loaded.scene, golden_camera(loaded.scene),
                                                     {kGoldenWidth, kGoldenHeight}, settings),
                            "core-frames", tolerance);
    expect_clear_failure(c, tolerance, "frames missing, core");
  }
  {
    // Control points missing.
    const LoadedScene loaded = load_starter("core");
    render::DisplaySettings settings = settings_for(GoldenMode::Frames);
    settings.control_points = false;
    const Comparison c =
        compare_with_golden(shared_renderer().render(loaded.doc, loaded.scene, golden_camera(loaded.scene),
                                                     {kGoldenWidth, kGoldenHeight}, settings),
                            "core-frames", tolerance);
    expect_clear_failure(c, tolerance, "control points missing, core");
  }
  {
    // Normal segments missing from the wireframe.
    const LoadedScene loaded = load_starter("wineglass");
    render::DisplaySettings settings = settings_for(GoldenMode::Wire);
    settings.normal_length = 0.0f;
    const Comparison c =
        compare_with_golden(shared_renderer().render(loaded.doc, loaded.scene, golden_camera(loaded.scene),
                                                     {kGoldenWidth, kGoldenHeight}, settings),
                            "wineglass-wire", tolerance);
    expect_clear_failure(c, tolerance, "normals missing, wineglass");
  }
  {
    // Wireframe instead of smooth shading.
    const LoadedScene loaded = load_starter("norm");
    const Comparison c =
        compare_with_golden(render_golden_picture(loaded, GoldenMode::Wire), "norm-smooth", smooth_tolerance());
    expect_clear_failure(c, smooth_tolerance(), "wireframe instead of smooth, norm");
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
  const Comparison c =
      compare_with_golden(shared_renderer().render(loaded.doc, loaded.scene, camera, {kGoldenWidth, kGoldenHeight},
                                                   settings_for(GoldenMode::Smooth)),
                          "weird-smooth", smooth_tolerance());
  expect_clear_failure(c, smooth_tolerance(), "surface moved by 3% of the scene radius, weird");

  // A curve moved in the frames picture.
  LoadedScene curves = load_starter("circles");
  const render::Camera curve_camera = golden_camera(curves.scene);
  for (Frame& f : curves.scene.objects[0].curve.frames) f.V.y += 0.1;
  curves.scene.objects[0].revision = altered_revision();
  const Comparison moved_curve =
      compare_with_golden(shared_renderer().render(curves.doc, curves.scene, curve_camera,
                                                   {kGoldenWidth, kGoldenHeight}, settings_for(GoldenMode::Frames)),
                          "circles-frames", Tolerance{});
  expect_clear_failure(moved_curve, Tolerance{}, "curve moved by 0.1, circles");
}

}  // namespace
}  // namespace sweep::test
