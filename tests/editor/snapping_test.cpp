// Snapping a dragged point: which targets a drag gathers (not the dragged point, its seam
// partners or a Bezier joint's own handles; not the dragged curve's samples; nothing hidden), and
// which one wins on the window (the nearest within the radius, control points before curves,
// the y axis with x and z exactly 0, a curve's sample exactly).
#include "editor/snapping.hpp"

#include "io/swp/read.hpp"
#include "support/screen_mapping_support.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <vector>

namespace sweep::editor {
namespace {

// Seen by test::ortho_mapping(): window x = 400 + 100 x, window y = 300 - 100 y.
constexpr const char* kText =
    "bez2 profile 8 7\n[0.5 -1]\n[1 -1]\n[1.5 -0.5]\n[1.5 0]\n[1.5 0.5]\n[1 1]\n[0.5 1]\n"
    "cr2 loop 8 5\n[3 0]\n[2.5 1]\n[2 0]\n[2.5 -1]\n[3 0]\n"
    "bsp3 rail 8 5\n[-3 -2 0]\n[-2 -1 0.5]\n[-2 0 0]\n[-2 1 -0.5]\n[-3 2 0]\n"
    "poly2 ghost 2\n[-1 -2.5]\n[1 -2.5]\n"
    "bez2 drop 8 7\n[-3.5 2.5]\n[-3 2.8]\n[-2 2.8]\n[-2 2.5]\n[-2 2.2]\n[-3 2.2]\n[-3.5 2.5]\n";

enum Index { kProfile, kLoop, kRail, kGhost, kDrop };

struct Fixture {
  Document doc = io::parse_swp(kText);
  Scene scene = evaluate_document(doc);
  std::vector<bool> visible = std::vector<bool>(doc.objects.size(), true);

  SnapTargets targets(int object, int point) const { return gather_snap_targets(doc, scene, visible, {object, point}); }
};

/// The window position of world (x, y) in the orthographic view.
glm::dvec2 ortho_pixel(double x, double y) {
  return {400.0 + 100.0 * x, 300.0 - 100.0 * y};
}

/// The points of `object` among the targets.
std::vector<int> target_points(const SnapTargets& targets, int object) {
  std::vector<int> points;
  for (const SnapTargets::PointRef& ref : targets.point_refs) {
    if (ref.object == object) points.push_back(ref.point);
  }
  return points;
}

bool has_curve(const SnapTargets& targets, int object) {
  return std::any_of(targets.curves.begin(), targets.curves.end(),
                     [object](const SnapTargets::CurveRange& c) { return c.object == object; });
}

TEST(Snapping, TheDraggedPointItsSeamPartnersAndItsOwnHandlesAreNoTargets) {
  const Fixture f;
  EXPECT_EQ(target_points(f.targets(kLoop, 0), kLoop), (std::vector<int>{1, 2, 3})) << "0 and its repeat 4 move";
  EXPECT_EQ(target_points(f.targets(kProfile, 3), kProfile), (std::vector<int>{0, 1, 5, 6})) << "a joint's handles";
  EXPECT_EQ(target_points(f.targets(kProfile, 2), kProfile), (std::vector<int>{0, 1, 3, 4, 5, 6}))
      << "a handle snaps to its joint";
  EXPECT_EQ(target_points(f.targets(kDrop, 6), kDrop), (std::vector<int>{2, 3, 4})) << "the closed seam's handles";
  EXPECT_EQ(target_points(f.targets(kDrop, 6), kLoop), (std::vector<int>{0, 1, 2, 3, 4})) << "other curves: all";
}

TEST(Snapping, TheDraggedCurvesSamplesAreNoTargetsOtherCurvesAre) {
  const Fixture f;
  const SnapTargets targets = f.targets(kProfile, 0);
  EXPECT_FALSE(has_curve(targets, kProfile));
  for (const int other : {int(kLoop), int(kRail), int(kGhost), int(kDrop)}) EXPECT_TRUE(has_curve(targets, other));
  EXPECT_TRUE(has_curve(f.targets(-1, -1), kProfile)) << "without a drag every curve is a target";
}

TEST(Snapping, TheNearestPointWithinTheRadiusWins) {
  const Fixture f;
  SnapOptions options;
  options.radius = 40.0;
  const auto hit = snap_target(f.targets(kProfile, 0), test::ortho_mapping(), ortho_pixel(1.5, 0.2), options);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->kind, SnapKind::Point);
  EXPECT_EQ(hit->object, kProfile);
  EXPECT_EQ(hit->point, 3) << "20 window units away; point 4 is 30";
  EXPECT_EQ(hit->position, glm::dvec3(1.5, 0.0, 0.0));
  EXPECT_NEAR(hit->distance, 20.0, 1e-9);
  EXPECT_NEAR(glm::length(hit->screen - ortho_pixel(1.5, 0.0)), 0.0, 1e-9);
}

TEST(Snapping, NothingBeyondTheRadius) {
  const Fixture f;
  EXPECT_FALSE(snap_target(f.targets(kProfile, 0), test::ortho_mapping(), ortho_pixel(1.5, 0.2), SnapOptions{}));
}

TEST(Snapping, APointWithinTheRadiusBeatsANearerCurve) {
  const Fixture f;
  const SnapTargets targets = f.targets(kProfile, 0);
  const glm::dvec2 pointer = ortho_pixel(2.0, 0.06);  // 6 units from the loop's point 2, on its curve nearly
  const auto hit = snap_target(targets, test::ortho_mapping(), pointer, SnapOptions{});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->kind, SnapKind::Point);
  EXPECT_EQ(hit->object, kLoop);
  EXPECT_EQ(hit->point, 2);
  EXPECT_EQ(hit->position, glm::dvec3(2.0, 0.0, 0.0));
  SnapOptions curves_only;
  curves_only.points = false;
  const auto curve = snap_target(targets, test::ortho_mapping(), pointer, curves_only);
  ASSERT_TRUE(curve);
  EXPECT_EQ(curve->kind, SnapKind::Curve);
  EXPECT_EQ(curve->object, kLoop);
  EXPECT_LT(curve->distance, hit->distance);
}

TEST(Snapping, TheAxisGivesXAndZExactlyZero) {
  const Fixture f;
  const SnapTargets targets = f.targets(kProfile, 0);
  const auto ortho = snap_target(targets, test::ortho_mapping(), ortho_pixel(0.05, 0.5), SnapOptions{});
  ASSERT_TRUE(ortho);
  EXPECT_EQ(ortho->kind, SnapKind::Axis);
  EXPECT_EQ(ortho->object, -1);
  EXPECT_EQ(ortho->position.x, 0.0);
  EXPECT_EQ(ortho->position.z, 0.0);
  EXPECT_NEAR(ortho->position.y, 0.5, 1e-9);
  EXPECT_NEAR(ortho->distance, 5.0, 1e-9);

  const ScreenMapping perspective = test::perspective_mapping();
  const auto on_axis = to_screen(perspective, {0.0, 0.3, 0.0});
  ASSERT_TRUE(on_axis);
  const auto hit = snap_target(targets, perspective, *on_axis + glm::dvec2(3.0, 0.0), SnapOptions{});
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->kind, SnapKind::Axis);
  EXPECT_EQ(hit->position.x, 0.0);
  EXPECT_EQ(hit->position.z, 0.0);
  EXPECT_NEAR(hit->position.y, 0.3, 0.01);
  EXPECT_NEAR(hit->distance, 3.0, 1e-3) << "the axis point nearest the ray: a hair from the nearest on the window";

  SnapOptions no_axis;
  no_axis.axis = false;
  EXPECT_FALSE(snap_target(targets, test::ortho_mapping(), ortho_pixel(0.05, 0.5), no_axis));
}

TEST(Snapping, HiddenObjectsAreNoTargets) {
  Fixture f;
  const glm::dvec2 pointer = ortho_pixel(0.3, -2.52);
  const auto shown = snap_target(f.targets(kProfile, 0), test::ortho_mapping(), pointer, SnapOptions{});
  ASSERT_TRUE(shown);
  EXPECT_EQ(shown->kind, SnapKind::Curve);
  EXPECT_EQ(shown->object, kGhost);
  EXPECT_NEAR(glm::length(shown->position - glm::dvec3(0.3, -2.5, 0.0)), 0.0, 1e-9);
  f.visible[kGhost] = false;
  const SnapTargets targets = f.targets(kProfile, 0);
  EXPECT_TRUE(target_points(targets, kGhost).empty());
  EXPECT_FALSE(has_curve(targets, kGhost));
  EXPECT_FALSE(snap_target(targets, test::ortho_mapping(), pointer, SnapOptions{}));
}

TEST(Snapping, AProfileEndDraggedOntoARailSampleTakesItsExactPosition) {
  const Fixture f;
  const SnapTargets targets = f.targets(kProfile, 6);
  const std::vector<Frame>& rail = f.scene.objects[kRail].curve.frames;
  ASSERT_GT(rail.size(), 12u);
  // First in the orthographic view, then (the same targets, projected again) in perspective.
  for (const ScreenMapping& mapping : {test::ortho_mapping(), test::perspective_mapping()}) {
    for (const std::size_t sample : {std::size_t(5), std::size_t(12)}) {
      const auto pixel = to_screen(mapping, rail[sample].V);
      ASSERT_TRUE(pixel);
      const auto hit = snap_target(targets, mapping, *pixel, SnapOptions{});
      ASSERT_TRUE(hit);
      EXPECT_EQ(hit->kind, SnapKind::Curve);
      EXPECT_EQ(hit->object, kRail);
      EXPECT_EQ(hit->position, rail[sample].V) << "bit for bit, sample " << sample;
    }
  }
}

TEST(Snapping, ACurveTargetBetweenSamplesLandsUnderItsMarkerInPerspective) {
  const Fixture f;
  const SnapTargets targets = f.targets(kProfile, 6);
  const ScreenMapping mapping = test::perspective_mapping();
  const std::vector<Frame>& rail = f.scene.objects[kRail].curve.frames;
  const glm::dvec3 a = rail[7].V, b = rail[8].V;
  const glm::dvec2 sa = *to_screen(mapping, a), sb = *to_screen(mapping, b);
  const glm::dvec2 along = glm::normalize(sb - sa);
  const glm::dvec2 pointer = 0.3 * sa + 0.7 * sb + 2.0 * glm::dvec2(-along.y, along.x);
  SnapOptions options;
  options.points = false;
  const auto hit = snap_target(targets, mapping, pointer, options);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->kind, SnapKind::Curve);
  EXPECT_NEAR(hit->distance, 2.0, 1e-6);
  const glm::dvec3 ab = b - a;
  const double u = glm::dot(hit->position - a, ab) / glm::dot(ab, ab);
  EXPECT_GT(u, 0.0);
  EXPECT_LT(u, 1.0);
  EXPECT_NEAR(glm::length(hit->position - (a + u * ab)), 0.0, 1e-12) << "on the segment between the samples";
  EXPECT_NEAR(glm::length(*to_screen(mapping, hit->position) - hit->screen), 0.0, 1e-6) << "under the marker";
}

}  // namespace
}  // namespace sweep::editor
