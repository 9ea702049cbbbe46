// Overlay batches: the selected curve's highlight and handles (the selected point with its seam
// partners, the hovered one), hidden objects, the profile view's grid, the 3D view's ground grid
// and axes, the highlighted surface, fold marks, nice_step.
#include "editor/overlay_builder.hpp"

#include "model/edit/edit.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <limits>
#include <set>
#include <vector>

namespace sweep::editor {
namespace {

// 0: an open B-spline, 1: its surface of revolution, 2: a closed B-spline (its last three points
// repeat the first three), 3: a circle.
constexpr const char* kText =
    "bsp2 arc 4 6\n[-1 1]\n[-1.2 0.5]\n[-0.8 0]\n[-1 -0.5]\n[-1 -1]\n[-0.5 -1.2]\n"
    "srev vase 8 arc\n"
    "bsp2 loop 5 7\n[1 0]\n[0 1]\n[-1 0]\n[0 -2]\n[1 0]\n[0 1]\n[-1 0]\n"
    "circ ring 16 0.5\n";

struct Fixture {
  Document doc = io::parse_swp(kText);
  Scene scene = evaluate_document(doc);
  OverlayInput input() const {
    OverlayInput in;
    in.doc = &doc;
    in.scene = &scene;
    return in;
  }
};

/// The batches of one colour and primitive.
std::vector<OverlayBatch> with(const std::vector<OverlayBatch>& overlay, const glm::vec3& color,
                               OverlayBatch::Primitive primitive = OverlayBatch::Primitive::Points) {
  std::vector<OverlayBatch> out;
  for (const OverlayBatch& b : overlay) {
    if (b.color == color && b.primitive == primitive) out.push_back(b);
  }
  return out;
}

std::size_t count(const std::vector<OverlayBatch>& batches) {
  std::size_t n = 0;
  for (const OverlayBatch& b : batches) n += b.positions.size();
  return n;
}

TEST(OverlayBuilder, NothingSelectedAndNoGridDrawsNothing) {
  const Fixture f;
  EXPECT_TRUE(build_overlay(f.input()).empty());
}

TEST(OverlayBuilder, TheSelectedCurveIsHighlightedWithAHandlePerControlPoint) {
  const Fixture f;
  OverlayInput in = f.input();
  in.selected = 0;
  const std::vector<OverlayBatch> overlay = build_overlay(in);
  const auto strips = with(overlay, kHighlightColor, OverlayBatch::Primitive::LineStrip);
  ASSERT_EQ(strips.size(), 1u);
  const std::vector<Frame>& samples = f.scene.objects[0].curve.frames;
  ASSERT_EQ(strips[0].positions.size(), samples.size());
  EXPECT_EQ(std::int64_t(samples.size()), curve_sample_count(f.doc.objects[0]));
  for (std::size_t i = 0; i < samples.size(); ++i) EXPECT_EQ(strips[0].positions[i], glm::vec3(samples[i].V));

  const std::vector<glm::dvec3>& points = f.doc.objects[0].as<sweep::PointsPart>().points;
  EXPECT_EQ(count(with(overlay, kHandleColor)), points.size()) << "every point a plain handle";
  EXPECT_EQ(count(with(overlay, kHandleHoveredColor)), 0u);
  EXPECT_EQ(count(with(overlay, kHandleSelectedColor)), 0u);
  const auto polygon = with(overlay, kHandleColor * 0.7f, OverlayBatch::Primitive::LineStrip);
  ASSERT_EQ(polygon.size(), 1u);
  ASSERT_EQ(polygon[0].positions.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(polygon[0].positions[i], glm::vec3(points[i]));
  for (const OverlayBatch& b : overlay) EXPECT_TRUE(b.on_top);
}

// Issue 61, item 4: a Bezier's joints and handles differ in shape and size, not only colour;
// a B-spline's points (no handles) stay discs.
TEST(OverlayBuilder, ABeziersJointsAreLargerSquaresAndItsHandlesSmallerDiscs) {
  Document doc = io::parse_swp("bez2 b 8 7\n[0 0]\n[1 1]\n[2 1]\n[3 0]\n[4 -1]\n[5 -1]\n[6 0]\n");
  const Scene scene = evaluate_document(doc);
  OverlayInput in;
  in.doc = &doc;
  in.scene = &scene;
  in.selected = 0;
  const auto plain = with(build_overlay(in), kHandleColor);
  ASSERT_EQ(plain.size(), 2u);
  const auto joints = std::find_if(plain.begin(), plain.end(), [](const OverlayBatch& b) { return !b.round; });
  const auto handles = std::find_if(plain.begin(), plain.end(), [](const OverlayBatch& b) { return b.round; });
  ASSERT_NE(joints, plain.end());
  ASSERT_NE(handles, plain.end());
  EXPECT_EQ(joints->positions, (std::vector<glm::vec3>{{0, 0, 0}, {3, 0, 0}, {6, 0, 0}}));
  EXPECT_EQ(handles->positions.size(), 4u);
  EXPECT_GT(joints->point_size, handles->point_size);

  const Fixture f;
  OverlayInput bspline = f.input();
  bspline.selected = 0;
  for (const OverlayBatch& b : with(build_overlay(bspline), kHandleColor)) EXPECT_TRUE(b.round);
}

TEST(OverlayBuilder, TheSelectedPointAndItsSeamPartnersAreChosenAndTheHoveredOneStandsOut) {
  const Fixture f;
  OverlayInput in = f.input();
  in.selected = 2;
  in.selected_point = 5;
  in.hovered_point = 3;
  const std::vector<OverlayBatch> overlay = build_overlay(in);
  const Object& loop = f.doc.objects[2];
  const std::vector<int> partners = seam_partners(loop, 5);
  ASSERT_EQ(partners, (std::vector<int>{5, 1})) << "the closed loop's seam";

  const auto chosen = with(overlay, kHandleSelectedColor);
  ASSERT_EQ(chosen.size(), 1u);
  ASSERT_EQ(chosen[0].positions.size(), partners.size());
  for (const glm::vec3& p : chosen[0].positions) EXPECT_EQ(p, glm::vec3(loop.as<sweep::PointsPart>().points[1]));
  EXPECT_EQ(chosen[0].point_size, kHandleBigSize);
  const auto hovered = with(overlay, kHandleHoveredColor);
  ASSERT_EQ(hovered.size(), 1u);
  EXPECT_EQ(hovered[0].positions, std::vector<glm::vec3>{glm::vec3(loop.as<sweep::PointsPart>().points[3])});
  EXPECT_EQ(count(with(overlay, kHandleColor)), loop.as<sweep::PointsPart>().points.size() - 3);
  EXPECT_EQ(count(with(overlay, kHandleColor)) + count(hovered) + count(chosen),
            loop.as<sweep::PointsPart>().points.size());
}

TEST(OverlayBuilder, PointsSelectedTogetherAreAllChosen) {
  const Fixture f;
  OverlayInput in = f.input();
  in.selected = 2;
  in.selected_point = 3;
  in.selected_points = {2, 3};
  const std::vector<OverlayBatch> overlay = build_overlay(in);
  const Object& loop = f.doc.objects[2];
  const auto& points = loop.as<sweep::PointsPart>().points;
  std::vector<glm::vec3> expected;  // both points with their seam partners, in index order
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (int selected : {2, 3}) {
      const std::vector<int> partners = seam_partners(loop, selected);
      if (std::find(partners.begin(), partners.end(), int(i)) != partners.end()) {
        expected.emplace_back(points[i]);
        break;
      }
    }
  }
  ASSERT_GE(expected.size(), 2u);
  const auto chosen = with(overlay, kHandleSelectedColor);
  ASSERT_EQ(chosen.size(), 1u);
  EXPECT_EQ(chosen[0].positions, expected);
  EXPECT_EQ(count(with(overlay, kHandleColor)), points.size() - expected.size());
}

TEST(OverlayBuilder, AHiddenOrMissingSelectionDrawsNothing) {
  const Fixture f;
  OverlayInput in = f.input();
  in.selected = 2;
  in.visible = {true, true, false};
  EXPECT_TRUE(build_overlay(in).empty()) << "the selected curve is hidden";
  in.visible = {false, false, true};
  EXPECT_FALSE(build_overlay(in).empty()) << "hiding other objects does not hide it";
  in.visible.clear();
  in.selected = 4;
  EXPECT_TRUE(build_overlay(in).empty()) << "an index past the end";
}

TEST(OverlayBuilder, ACircleHasAHighlightButNoHandlesAndASurfaceNeither) {
  const Fixture f;
  OverlayInput in = f.input();
  in.selected = 3;
  const std::vector<OverlayBatch> overlay = build_overlay(in);
  ASSERT_EQ(overlay.size(), 1u);
  EXPECT_EQ(overlay[0].color, kHighlightColor);
  EXPECT_EQ(overlay[0].positions.size(), f.scene.objects[3].curve.frames.size());
  in.selected = 1;
  EXPECT_TRUE(build_overlay(in).empty());
}

/// The distinct x coordinates of the grid's lines, sorted.
std::vector<double> grid_xs(const OverlayBatch& grid) {
  std::set<double> xs;
  for (std::size_t i = 0; i < grid.positions.size(); i += 4) xs.insert(double(grid.positions[i].x));
  return {xs.begin(), xs.end()};
}

/// The spacing of the grid's first two lines.
double grid_step(const OverlayBatch& grid) {
  const std::vector<double> xs = grid_xs(grid);
  return xs.size() < 2 ? 0.0 : xs[1] - xs[0];
}

TEST(OverlayBuilder, TheGridLiesInTheXyPlaneBehindTheSceneWithANiceStep) {
  const Fixture f;
  OverlayInput in = f.input();
  in.grid = GridView{{0.3, -0.2, 0.0}, 2.0, 0.0};
  const std::vector<OverlayBatch> overlay = build_overlay(in);
  ASSERT_EQ(overlay.size(), 3u) << "the grid, the x axis and the y axis";
  for (const OverlayBatch& b : overlay) {
    EXPECT_EQ(b.primitive, OverlayBatch::Primitive::Lines);
    EXPECT_FALSE(b.on_top);
    EXPECT_EQ(b.positions.size() % 2, 0u);
    for (const glm::vec3& p : b.positions) EXPECT_EQ(p.z, 0.0f);
  }
  for (const glm::vec3& p : overlay[1].positions) EXPECT_EQ(p.y, 0.0f);
  for (const glm::vec3& p : overlay[2].positions) EXPECT_EQ(p.x, 0.0f);

  const std::vector<double> xs = grid_xs(overlay[0]);
  ASSERT_GE(xs.size(), 2u);
  EXPECT_LE(xs.front(), 0.3 - 2.0 * 2.0) << "covers a wide window";
  EXPECT_GE(xs.back(), 0.3 + 2.0 * 2.0);
  for (std::size_t i = 1; i < xs.size(); ++i) EXPECT_NEAR(xs[i] - xs[i - 1], nice_step(2.0 / 5.0), 1e-5);
  for (double x : xs) EXPECT_NEAR(x / 0.5, std::round(x / 0.5), 1e-5) << "lines at multiples of the step";

  in.grid->snap = 0.1;  // snapping step shown when it is not too dense
  EXPECT_NEAR(grid_step(build_overlay(in)[0]), 0.1, 1e-5);
  in.grid->snap = 0.01;  // too dense: the nice step
  EXPECT_NEAR(grid_step(build_overlay(in)[0]), 0.5, 1e-5);
}

/// The distinct z coordinates of the ground grid's lines along x, sorted.
std::vector<double> grid_zs(const OverlayBatch& grid) {
  std::set<double> zs;
  for (std::size_t i = 2; i < grid.positions.size(); i += 4) zs.insert(double(grid.positions[i].z));
  return {zs.begin(), zs.end()};
}

TEST(OverlayBuilder, TheGroundGridLiesInTheXzPlaneWithAStepFromTheSceneSize) {
  const Fixture f;
  OverlayInput in = f.input();
  in.ground = GroundGrid{{-3.0, 1.0, -2.0}, {5.0, 9.0, 2.0}};  // radius sqrt(64+64+16)/2 = 6
  const std::vector<OverlayBatch> overlay = build_overlay(in);
  ASSERT_EQ(overlay.size(), 4u) << "the grid and the x, z and y axes";
  for (const OverlayBatch& b : overlay) {
    EXPECT_EQ(b.primitive, OverlayBatch::Primitive::Lines);
    EXPECT_FALSE(b.on_top) << "hidden by nearer surfaces";
    EXPECT_EQ(b.positions.size() % 2, 0u);
  }
  EXPECT_EQ(overlay[0].color, kGridColor);
  EXPECT_EQ(ground_height(*in.ground), 0.0);
  for (const glm::vec3& p : overlay[0].positions) EXPECT_EQ(p.y, 0.0f) << "y is up: the scene stands on y = 0";

  const double step = ground_step(*in.ground);
  EXPECT_DOUBLE_EQ(step, nice_step(6.0 / 5.0));
  EXPECT_DOUBLE_EQ(step, 1.0);
  const std::vector<double> xs = grid_xs(overlay[0]);
  const std::vector<double> zs = grid_zs(overlay[0]);
  ASSERT_GE(xs.size(), 2u);
  EXPECT_EQ(xs.size(), zs.size()) << "a square";
  for (std::size_t i = 1; i < xs.size(); ++i) EXPECT_NEAR(xs[i] - xs[i - 1], step, 1e-5);
  for (double x : xs) EXPECT_NEAR(x, std::round(x), 1e-5) << "lines at multiples of the step";
  EXPECT_NEAR(xs.front(), -xs.back(), 1e-5) << "around the origin";
  EXPECT_GE(xs.back(), 1.25 * 6.0) << "past the box and its radius";
  EXPECT_LE(xs.back(), 1.25 * 6.0 + step) << "a limited extent";
  EXPECT_NEAR(zs.front(), xs.front(), 1e-5);
}

TEST(OverlayBuilder, TheAxesAreRedGreenBlueOnTheGroundUnderTheScene) {
  const Fixture f;
  OverlayInput in = f.input();
  in.ground = GroundGrid{{-3.0, -1.0, -2.0}, {5.0, 9.0, 2.0}};
  const std::vector<OverlayBatch> overlay = build_overlay(in);
  ASSERT_EQ(overlay.size(), 4u);
  EXPECT_EQ(ground_height(*in.ground), -1.0) << "the scene reaches below y = 0: the grid at its lowest point";
  for (const glm::vec3& p : overlay[0].positions) EXPECT_EQ(p.y, -1.0f);
  const std::vector<double> xs = grid_xs(overlay[0]);
  const float reach = float(xs.back());
  const std::vector<OverlayBatch> x = with(overlay, kXAxisColor, OverlayBatch::Primitive::Lines);
  const std::vector<OverlayBatch> y = with(overlay, kYAxisColor, OverlayBatch::Primitive::Lines);
  const std::vector<OverlayBatch> z = with(overlay, kZAxisColor, OverlayBatch::Primitive::Lines);
  ASSERT_EQ(x.size(), 1u);
  ASSERT_EQ(y.size(), 1u);
  ASSERT_EQ(z.size(), 1u);
  EXPECT_EQ(x[0].positions, (std::vector<glm::vec3>{{-reach, -1.0f, 0.0f}, {reach, -1.0f, 0.0f}}));
  EXPECT_EQ(z[0].positions, (std::vector<glm::vec3>{{0.0f, -1.0f, -reach}, {0.0f, -1.0f, reach}}));
  EXPECT_EQ(y[0].positions, (std::vector<glm::vec3>{{0.0f, -1.0f, 0.0f}, {0.0f, 10.0f, 0.0f}}))
      << "from the grid to a step above the scene's top";
  EXPECT_GT(kXAxisColor.r, kXAxisColor.g + 0.2f);
  EXPECT_GT(kYAxisColor.g, kYAxisColor.r + 0.2f);
  EXPECT_GT(kZAxisColor.b, kZAxisColor.r + 0.2f);
}

TEST(OverlayBuilder, AnEmptySceneHasAUnitGroundGrid) {
  const Fixture f;
  OverlayInput in = f.input();
  const double inf = std::numeric_limits<double>::infinity();
  in.ground = GroundGrid{glm::dvec3(inf), glm::dvec3(-inf)};  // render::Bounds before anything is added
  const std::vector<OverlayBatch> overlay = build_overlay(in);
  ASSERT_EQ(overlay.size(), 4u);
  EXPECT_DOUBLE_EQ(ground_step(*in.ground), 0.2);
  const std::vector<double> xs = grid_xs(overlay[0]);
  EXPECT_NEAR(xs.back(), 1.4, 1e-5);
  for (const OverlayBatch& b : overlay) {
    for (const glm::vec3& p : b.positions) EXPECT_TRUE(std::isfinite(p.x + p.y + p.z));
  }
  EXPECT_EQ(ground_height(*in.ground), 0.0);
  in.ground = GroundGrid{{1.0, 1.0, 1.0}, {1.0, 1.0, 1.0}};  // a point
  EXPECT_DOUBLE_EQ(ground_step(*in.ground), 0.2);
}

TEST(OverlayBuilder, OnlyASelectedVisibleSurfaceIsHighlighted) {
  const Fixture f;
  OverlayInput in = f.input();
  EXPECT_EQ(highlighted_surface(in), -1) << "nothing selected";
  in.selected = 1;  // the surface of revolution
  EXPECT_EQ(highlighted_surface(in), 1);
  in.visible = {true, false};
  EXPECT_EQ(highlighted_surface(in), -1) << "hidden";
  in.visible.clear();
  for (int curve : {0, 2, 3}) {
    in.selected = curve;
    EXPECT_EQ(highlighted_surface(in), -1) << "a curve is highlighted by the overlay, not the shading";
  }
  in.selected = 9;
  EXPECT_EQ(highlighted_surface(in), -1);
}

TEST(OverlayBuilder, TheSelectedCurveIsDrawnOnTopOfWhatHidesIt) {
  const Fixture f;
  OverlayInput in = f.input();
  in.selected = 0;  // the profile inside its surface of revolution
  in.ground = GroundGrid{};
  const std::vector<OverlayBatch> overlay = build_overlay(in);
  const auto strips = with(overlay, kHighlightColor, OverlayBatch::Primitive::LineStrip);
  ASSERT_EQ(strips.size(), 1u);
  EXPECT_TRUE(strips[0].on_top);
  EXPECT_EQ(overlay.front().color, kGridColor) << "the grid first, under everything";
}

TEST(OverlayBuilder, NiceStep) {
  EXPECT_DOUBLE_EQ(nice_step(0.37), 0.5);
  EXPECT_DOUBLE_EQ(nice_step(3.0), 2.0);
  EXPECT_DOUBLE_EQ(nice_step(7.6), 10.0);
  EXPECT_DOUBLE_EQ(nice_step(1.0), 1.0);
  EXPECT_DOUBLE_EQ(nice_step(140.0), 100.0);
  EXPECT_DOUBLE_EQ(nice_step(0.0021), 0.002);
  for (double bad : {0.0, -2.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    EXPECT_EQ(nice_step(bad), 1.0) << bad;
  }
}

TEST(OverlayBuilder, FoldsAreMarkedWithTheCurves) {
  const Document doc = test::load_starter("flircle.swp");
  const Scene scene = evaluate_document(doc);
  const int tube = doc.find("flircle");
  ASSERT_GE(tube, 0);
  const EvaluatedObject& evaluated = scene.objects[std::size_t(tube)];
  ASSERT_FALSE(evaluated.diagnostics.folds.empty()) << "flircle.swp folds (README, Frames)";
  const std::vector<Frame>& sweep =
      scene.objects[std::size_t(doc.objects[std::size_t(tube)].as<sweep::CylinderSurface>().sweep)].curve.frames;
  std::vector<glm::vec3> expected;
  for (const FoldRange& r : evaluated.diagnostics.folds) {
    for (int k = r.first_sample; k <= r.last_sample; ++k) expected.emplace_back(sweep[std::size_t(k)].V);
  }

  OverlayInput in;
  in.doc = &doc;
  in.scene = &scene;
  const auto folds = with(build_overlay(in), kFoldColor);
  ASSERT_EQ(folds.size(), 1u);
  EXPECT_EQ(folds[0].positions, expected);

  in.curves_shown = false;
  EXPECT_TRUE(build_overlay(in).empty()) << "no fold marks without the curves";
  in.curves_shown = true;
  in.visible.assign(doc.objects.size(), true);
  in.visible[std::size_t(tube)] = false;
  EXPECT_TRUE(build_overlay(in).empty()) << "no fold marks on a hidden tube";
}

}  // namespace
}  // namespace sweep::editor
