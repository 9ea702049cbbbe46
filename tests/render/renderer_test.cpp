// The renderer through the OSMesa provider: it draws what its DrawList holds (visibility, control
// polygons, overlay), GPU copies follow revisions (only what changed is uploaded again), modes
// draw something, providers are chosen by name.
#include "editor/curvature_comb.hpp"
#include "editor/overlay_builder.hpp"
#include "headless/headless_renderer.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"
#include "render/draw_list.hpp"
#include "render/gl_context.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace sweep {
namespace {

struct Loaded {
  Document doc;
  Scene scene;
};

Loaded load(const char* stem) {
  Loaded loaded;
  loaded.doc = io::load_swp_file(std::filesystem::path(SWEEP_SWP_DIR) / (std::string(stem) + ".swp"));
  loaded.scene = evaluate_document(loaded.doc);
  return loaded;
}

/// Pixels that are not the background colour.
std::size_t foreground_pixels(const render::Image& image, const render::DisplaySettings& settings) {
  const auto bg = glm::ivec3(glm::round(settings.background * 255.0f));
  std::size_t count = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (std::abs(p[0] - bg.r) + std::abs(p[1] - bg.g) + std::abs(p[2] - bg.b) > 6) ++count;
    }
  }
  return count;
}

/// Pixels within `tolerance` (sum over the channels) of `color`.
std::size_t pixels_of_color(const render::Image& image, const glm::vec3& color, int tolerance = 12) {
  const auto c = glm::ivec3(glm::round(color * 255.0f));
  std::size_t count = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (std::abs(p[0] - c.r) + std::abs(p[1] - c.g) + std::abs(p[2] - c.b) <= tolerance) ++count;
    }
  }
  return count;
}

/// Orange pixels: red well above blue (the default material and background are blue-grey).
std::size_t orange_pixels(const render::Image& image) {
  std::size_t count = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[0] > p[2] + 60 && p[0] > p[1]) ++count;
    }
  }
  return count;
}

/// Pixels whose channel `c` (0 red, 1 green, 2 blue) exceeds both others by more than `margin`:
/// the axes, which are thin and antialiased, so not of one exact colour.
std::size_t dominant_pixels(const render::Image& image, int c, int margin = 20) {
  std::size_t count = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      const int v = p[c];
      if (v > p[(c + 1) % 3] + margin && v > p[(c + 2) % 3] + margin) ++count;
    }
  }
  return count;
}

std::size_t object_index(const Document& doc, const std::string& name) {
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    if (doc.objects[i].name == name) return i;
  }
  throw std::invalid_argument("no object " + name);
}

class RendererTest : public ::testing::Test {
 protected:
  static headless::HeadlessRenderer& renderer() {
    static headless::HeadlessRenderer instance("osmesa");
    return instance;
  }
  render::Image draw(const Loaded& loaded, const render::DisplaySettings& settings, glm::ivec2 size = {160, 120}) {
    render::Camera camera;
    camera.reset(render::scene_bounds(loaded.scene), double(size.x) / double(size.y));
    return renderer().render(loaded.doc, loaded.scene, camera, size, settings);
  }
  render::Image draw(const render::DrawList& list, const render::DisplaySettings& settings,
                     glm::ivec2 size = {160, 120}) {
    render::Camera camera;
    camera.reset(render::scene_bounds(*list.scene), double(size.x) / double(size.y));
    return renderer().render(list, camera, size, settings);
  }
};

TEST_F(RendererTest, UploadsOnlyWhatChanged) {
  Loaded loaded = load("weird");  // profile, sweep, gcyl
  render::DisplaySettings settings;
  draw(loaded, settings);
  const std::uint64_t after_first = renderer().renderer().upload_count();
  draw(loaded, settings);
  EXPECT_EQ(renderer().renderer().upload_count(), after_first) << "nothing changed, nothing uploaded";

  // New STEPS for the profile: the profile and the cylinder change, the sweep does not.
  loaded.doc.objects[0].as<StepsPart>().steps = 4;
  io::validate_document(loaded.doc);
  const std::vector<int> changed = reevaluate(loaded.scene, loaded.doc, 0);
  ASSERT_EQ(changed, (std::vector<int>{0, 2}));
  draw(loaded, settings);
  EXPECT_EQ(renderer().renderer().upload_count(), after_first + 2) << "profile strip + cylinder mesh";
}

TEST_F(RendererTest, DecorationsAreBuiltOnFirstUseOnly) {
  const Loaded loaded = load("core");
  render::DisplaySettings settings;
  draw(loaded, settings);
  const std::uint64_t plain = renderer().renderer().upload_count();
  settings.curves = render::CurveMode::Frames;
  settings.control_points = true;
  draw(loaded, settings);
  const std::uint64_t decorated = renderer().renderer().upload_count();
  EXPECT_EQ(decorated, plain + 8) << "frames and control polygons of 4 curves";
  draw(loaded, settings);
  EXPECT_EQ(renderer().renderer().upload_count(), decorated);
}

TEST_F(RendererTest, EveryModeDrawsAndOffDrawsNothing) {
  const Loaded loaded = load("tor");
  render::DisplaySettings settings;
  settings.curves = render::CurveMode::Off;
  for (auto mode : {render::SurfaceMode::Smooth, render::SurfaceMode::Wireframe}) {
    settings.surface = mode;
    EXPECT_GT(foreground_pixels(draw(loaded, settings), settings), 500u) << render::name_of(mode);
  }
  settings.surface = render::SurfaceMode::Off;
  EXPECT_EQ(foreground_pixels(draw(loaded, settings), settings), 0u);
  settings.curves = render::CurveMode::Curves;
  EXPECT_GT(foreground_pixels(draw(loaded, settings), settings), 50u);
}

TEST_F(RendererTest, NoGlErrorsInAnyMode) {
  const Loaded loaded = load("weird");
  renderer().description();  // creates the context (and makes it current) before any GL call
  render::take_gl_error();
  for (auto surface : {render::SurfaceMode::Smooth, render::SurfaceMode::Wireframe, render::SurfaceMode::Off}) {
    for (auto curves : {render::CurveMode::Curves, render::CurveMode::Frames, render::CurveMode::Off}) {
      for (bool points : {false, true}) {
        for (bool ortho : {false, true}) {
          render::DisplaySettings settings;
          settings.surface = surface;
          settings.curves = curves;
          settings.control_points = points;
          render::Camera camera;
          camera.reset(render::scene_bounds(loaded.scene), 4.0 / 3.0);
          if (ortho) camera.projection = render::Projection::Orthographic;
          renderer().render(loaded.doc, loaded.scene, camera, {64, 48}, settings);
          EXPECT_EQ(render::take_gl_error(), 0u) << render::name_of(surface) << " " << render::name_of(curves);
        }
      }
    }
  }
}

TEST_F(RendererTest, HiddenObjectsAreNotDrawn) {
  const Loaded loaded = load("tor");
  render::DisplaySettings settings;
  settings.curves = render::CurveMode::Off;
  render::DrawList list = render::draw_list(loaded.doc, loaded.scene);
  EXPECT_GT(foreground_pixels(draw(list, settings), settings), 500u);
  list.visible = {true, true, false};  // the cylinder
  EXPECT_EQ(foreground_pixels(draw(list, settings), settings), 0u);
  EXPECT_EQ(renderer().renderer().stats().triangles, 0u);
  list.visible = {true, true};  // objects past the end are visible
  EXPECT_GT(foreground_pixels(draw(list, settings), settings), 500u);
}

TEST_F(RendererTest, DrawsTheOverlayOfTheListOverTheScene) {
  const Loaded loaded = load("tor");
  render::DisplaySettings settings;
  const glm::vec3 magenta{1.0f, 0.0f, 1.0f};
  render::DrawList list = render::draw_list(loaded.doc, loaded.scene);
  const render::Image plain = draw(list, settings);
  ASSERT_EQ(pixels_of_color(plain, magenta), 0u);

  OverlayBatch empty;  // no positions: nothing to draw
  empty.color = magenta;
  list.overlay = {empty};
  EXPECT_EQ(draw(list, settings).rgba, plain.rgba) << "an empty batch draws nothing";

  OverlayBatch handle;  // on top of the cylinder, which hides the centre of the scene
  handle.positions = {glm::vec3(render::scene_bounds(loaded.scene).center())};
  handle.color = magenta;
  handle.point_size = 10.0f;
  list.overlay = {handle};
  const std::size_t dot = pixels_of_color(draw(list, settings), magenta);
  EXPECT_GT(dot, 40u) << "a point of 10 pixels across";
  EXPECT_LT(dot, 120u);

  list.overlay.clear();
  EXPECT_EQ(draw(list, settings).rgba, plain.rgba) << "no overlay, nothing extra";
}

TEST_F(RendererTest, DrawsTheControlPolygonsOfTheListWhenAsked) {
  const Loaded loaded = load("core");  // four control-point curves
  render::DisplaySettings settings;
  settings.curves = render::CurveMode::Off;
  render::DrawList list = render::draw_list(loaded.doc, loaded.scene);
  ASSERT_EQ(list.control_polygons.size(), 4u);
  EXPECT_EQ(pixels_of_color(draw(list, settings), settings.control_color), 0u) << "control points off";

  settings.control_points = true;
  EXPECT_GT(pixels_of_color(draw(list, settings), settings.control_color), 100u) << "16 round points";

  list.control_polygons.assign(4, {});  // the list has none to show
  EXPECT_EQ(foreground_pixels(draw(list, settings), settings), 0u);
}

TEST_F(RendererTest, DrawingTheSameListTwiceUploadsNothing) {
  const Loaded loaded = load("weird");
  render::DisplaySettings settings;
  settings.surface = render::SurfaceMode::Wireframe;
  settings.curves = render::CurveMode::Frames;
  settings.control_points = true;
  render::DrawList list = render::draw_list(loaded.doc, loaded.scene);
  OverlayBatch grid;
  grid.primitive = OverlayBatch::Primitive::Lines;
  grid.positions = {glm::vec3(-1.0f, 0.0f, 0.0f), glm::vec3(1.0f, 0.0f, 0.0f)};
  grid.on_top = false;
  list.overlay = {grid};
  const render::Image first = draw(list, settings);
  const std::uint64_t uploads = renderer().renderer().upload_count();
  const render::Image second = draw(list, settings);
  EXPECT_EQ(renderer().renderer().upload_count(), uploads);
  EXPECT_EQ(second.rgba, first.rgba);
}

TEST_F(RendererTest, TheHighlightedSurfaceAloneTurnsTheHighlightColour) {
  const Loaded loaded = load("catmull-rom");  // the surface of revolution "vase" and the tube "ring"
  const std::size_t vase = object_index(loaded.doc, "vase");
  const std::size_t ring = object_index(loaded.doc, "ring");
  render::DisplaySettings settings;
  settings.curves = render::CurveMode::Off;
  render::DrawList list = render::draw_list(loaded.doc, loaded.scene);
  const render::Image plain = draw(list, settings, {320, 240});
  ASSERT_EQ(orange_pixels(plain), 0u);
  const std::uint64_t uploads = renderer().renderer().upload_count();

  list.highlighted = int(vase);
  list.highlight_color = editor::kHighlightColor;
  const std::size_t lit = orange_pixels(draw(list, settings, {320, 240}));
  EXPECT_GT(lit, 60u) << "the vase's rim turns orange";
  EXPECT_EQ(renderer().renderer().upload_count(), uploads) << "a highlight uploads nothing";
  list.visible.assign(loaded.scene.objects.size(), true);
  list.visible[vase] = false;
  EXPECT_EQ(orange_pixels(draw(list, settings, {320, 240})), 0u) << "the ring is not highlighted";
  list.visible[vase] = true;
  list.visible[ring] = false;
  EXPECT_GT(orange_pixels(draw(list, settings, {320, 240})), 60u);

  settings.surface = render::SurfaceMode::Wireframe;  // the wireframe takes the colour
  EXPECT_GT(pixels_of_color(draw(list, settings, {320, 240}), editor::kHighlightColor), 100u);
  list.highlighted = -1;
  EXPECT_EQ(pixels_of_color(draw(list, settings, {320, 240}), editor::kHighlightColor), 0u);
}

// Issue 59, item 2: the normals are a toggle of their own, with either surface mode, in a colour
// no other mark uses; `--surface wire` (show_surface) still means the wireframe with them.
TEST_F(RendererTest, NormalsAreAToggleOfTheirOwnInTheirOwnColour) {
  const Loaded loaded = load("tor");
  const render::DrawList list = render::draw_list(loaded.doc, loaded.scene);
  render::DisplaySettings settings;
  settings.curves = render::CurveMode::Off;
  for (const render::SurfaceMode mode : {render::SurfaceMode::Smooth, render::SurfaceMode::Wireframe}) {
    settings.surface = mode;
    settings.normals = false;
    EXPECT_EQ(pixels_of_color(draw(list, settings, {320, 240}), settings.normal_color), 0u) << name_of(mode);
    settings.normals = true;
    EXPECT_GT(pixels_of_color(draw(list, settings, {320, 240}), settings.normal_color), 100u) << name_of(mode);
  }
  render::show_surface(settings, render::SurfaceMode::Wireframe);
  EXPECT_TRUE(settings.normals);
  render::show_surface(settings, render::SurfaceMode::Smooth);
  EXPECT_FALSE(settings.normals);
  for (const glm::vec3 other :
       {editor::kHighlightColor, editor::kHandleColor, editor::kHandleSelectedColor, editor::kFoldColor,
        editor::kCombColor, settings.wire_color, glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)}) {
    EXPECT_GT(glm::distance(other, settings.normal_color), 0.3f);
  }
}

TEST_F(RendererTest, TheSelectedProfileShowsInFrontOfTheSurfaceThatHidesIt) {
  const Loaded loaded = load("wineglass");  // the profile lies inside the glass it turns into
  render::DisplaySettings settings;
  render::DrawList list = render::draw_list(loaded.doc, loaded.scene);
  editor::OverlayInput in;
  in.doc = &loaded.doc;
  in.scene = &loaded.scene;
  in.selected = int(object_index(loaded.doc, "profile"));
  // The highlighted strip alone (the handles, also on top, would cover much of it).
  for (const OverlayBatch& batch : editor::build_overlay(in)) {
    if (batch.color == editor::kHighlightColor) list.overlay.push_back(batch);
  }
  ASSERT_EQ(list.overlay.size(), 1u);
  ASSERT_TRUE(list.overlay[0].on_top);
  const std::size_t on_top = orange_pixels(draw(list, settings, {320, 240}));
  for (OverlayBatch& batch : list.overlay) batch.on_top = false;
  const std::size_t hidden = orange_pixels(draw(list, settings, {320, 240}));
  EXPECT_GT(on_top, 200u) << "the whole profile, over the glass";
  EXPECT_GT(on_top, 3 * hidden) << "without on_top the glass hides most of it";
}

TEST_F(RendererTest, TheGroundGridAndAxesAreHiddenByNearerSurfaces) {
  const Loaded loaded = load("wineglass");
  render::DisplaySettings settings;
  settings.curves = render::CurveMode::Off;
  render::DrawList list = render::draw_list(loaded.doc, loaded.scene);
  const render::Bounds bounds = render::scene_bounds(loaded.scene);
  editor::OverlayInput in;
  in.doc = &loaded.doc;
  in.scene = &loaded.scene;
  in.ground = editor::GroundGrid{bounds.min, bounds.max};
  list.overlay = editor::build_overlay(in);
  const glm::ivec2 size{320, 240};
  const render::Image with_glass = draw(list, settings, size);
  settings.surface = render::SurfaceMode::Off;
  const render::Image grid_only = draw(list, settings, size);
  for (int axis : {0, 1, 2}) EXPECT_GT(dominant_pixels(grid_only, axis), 60u) << "red x, green y, blue z";
  const std::size_t grid_lines = pixels_of_color(grid_only, editor::kGridColor, 6);
  EXPECT_GT(grid_lines, 1000u);
  EXPECT_LT(pixels_of_color(with_glass, editor::kGridColor, 6), grid_lines - 100) << "the glass hides some";
  EXPECT_LT(dominant_pixels(with_glass, 1), dominant_pixels(grid_only, 1) / 2) << "the y axis runs inside the glass";
}

TEST_F(RendererTest, ADrawListWithoutASceneIsRefused) {
  renderer().description();  // makes the context current
  render::Renderer& r = renderer().renderer();
  try {
    r.draw(render::DrawList{}, render::Camera{}, render::RenderTarget{}, render::DisplaySettings{});
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "Renderer::draw: the draw list has no scene");
  }
}

TEST_F(RendererTest, ReportsStats) {
  const Loaded loaded = load("wineglass");
  draw(loaded, render::DisplaySettings{});
  EXPECT_EQ(renderer().renderer().stats().triangles, loaded.scene.objects[1].mesh.triangle_count());
  EXPECT_EQ(renderer().renderer().stats().vertices, loaded.scene.objects[1].mesh.vertex_count());
}

TEST_F(RendererTest, ReadsBackTopRowFirst) {
  // Top view of the wine glass: nothing; front view with the camera pushed up: the glass sits
  // in the lower half of the picture.
  const Loaded loaded = load("wineglass");
  render::Camera camera;
  camera.set_view(render::ViewPreset::Front);
  camera.frame(render::scene_bounds(loaded.scene), 1.0);
  camera.target.y += 0.6 * camera.half_height_at_target();
  render::DisplaySettings settings;
  const render::Image image = renderer().render(loaded.doc, loaded.scene, camera, {100, 100}, settings);
  render::Image top = image;
  top.height = 50;
  top.rgba.resize(100 * 50 * 4);
  render::Image bottom = image;
  bottom.rgba.erase(bottom.rgba.begin(), bottom.rgba.begin() + 100 * 50 * 4);
  bottom.height = 50;
  EXPECT_GT(foreground_pixels(bottom, settings), 2 * foreground_pixels(top, settings));
}

TEST(ContextProviders, ChosenByName) {
  headless::HeadlessRenderer renderer("osmesa");  // registers "osmesa"
  const auto names = render::context_provider_names();
  EXPECT_NE(std::find(names.begin(), names.end(), "osmesa"), names.end());
  EXPECT_THROW(render::create_context("no-such-provider", {}), std::runtime_error);
  EXPECT_NE(renderer.description().find("OpenGL"), std::string::npos);
}

}  // namespace
}  // namespace sweep
