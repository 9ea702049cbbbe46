// The viewport layout: what the panels leave free for the scene, the lens shift that centres the
// picture there and the aspect to frame it with, on plain, HiDPI and narrow windows.
#include "editor/viewport_layout.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace sweep::editor {
namespace {

TEST(ViewportLayout, WithoutUiTheWholeWindowIsFree) {
  const ViewportLayout layout = compute_layout({1280, 800}, {1280, 800}, 1.0f, false);
  EXPECT_EQ(layout.window, glm::dvec2(1280.0, 800.0));
  EXPECT_EQ(layout.pixel_ratio, 1.0f);
  EXPECT_EQ(layout.panel_width, 0.0f);
  EXPECT_EQ(layout.edit_width, 0.0f);
  EXPECT_EQ(layout.free_origin, glm::dvec2(0.0, 0.0));
  EXPECT_EQ(layout.free_size, glm::dvec2(1280.0, 800.0));
  EXPECT_EQ(layout.lens_shift, glm::dvec2(0.0, 0.0));
  EXPECT_DOUBLE_EQ(layout.aspect, 1280.0 / 800.0);
}

TEST(ViewportLayout, TheFramebuffersAspectIsUsedWithoutUi) {
  const ViewportLayout layout = compute_layout({1000, 500}, {2000, 1000}, 2.0f, false);
  EXPECT_EQ(layout.pixel_ratio, 2.0f);
  EXPECT_EQ(layout.free_size, glm::dvec2(1000.0, 500.0)) << "screen units";
  EXPECT_DOUBLE_EQ(layout.aspect, 2.0);
}

TEST(ViewportLayout, ThePanelsLeaveTheMiddleFree) {
  const ViewportLayout layout = compute_layout({1280, 800}, {1280, 800}, 1.0f, true);
  EXPECT_EQ(layout.margin, 8.0f);
  EXPECT_GT(layout.panel_width, 0.0f);
  EXPECT_GT(layout.edit_width, 0.0f);
  const double left = layout.margin + layout.panel_width;
  const double right = 1280.0 - layout.margin - layout.edit_width;
  EXPECT_DOUBLE_EQ(layout.free_left(), left);
  EXPECT_DOUBLE_EQ(layout.free_right(), right);
  EXPECT_DOUBLE_EQ(layout.free_origin.y, 0.0);
  EXPECT_EQ(layout.status_height, kStatusBarHeight) << "the status bar along the bottom";
  EXPECT_DOUBLE_EQ(layout.free_size.y, 800.0 - kStatusBarHeight);
  const double panel_share = left / 1280.0;
  const double edit_share = (1280.0 - right) / 1280.0;
  EXPECT_DOUBLE_EQ(layout.lens_shift.x, panel_share - edit_share);
  EXPECT_DOUBLE_EQ(layout.lens_shift.y, kStatusBarHeight / 800.0) << "the picture's centre moves up by half the bar";
  EXPECT_DOUBLE_EQ(layout.aspect, (right - left) / 800.0);
  EXPECT_DOUBLE_EQ(layout.height_share, 1.0 - kStatusBarHeight / 800.0);
}

TEST(ViewportLayout, TheStatusBarScalesWithTheUiAndTakesAtMostATenthOfTheHeight) {
  EXPECT_EQ(compute_layout({1280, 800}, {1280, 800}, 2.0f, true).status_height, 2.0f * kStatusBarHeight);
  const ViewportLayout low = compute_layout({1280, 100}, {1280, 100}, 1.0f, true);
  EXPECT_FLOAT_EQ(low.status_height, 10.0f);
  EXPECT_DOUBLE_EQ(low.free_size.y, 90.0);
  EXPECT_EQ(compute_layout({1280, 800}, {1280, 800}, 1.0f, false).status_height, 0.0f) << "no bar without the UI";
}

TEST(ViewportLayout, OnHiDpiTheSharesStayAndTheAspectComesFromPixels) {
  const ViewportLayout plain = compute_layout({1280, 800}, {1280, 800}, 1.0f, true);
  const ViewportLayout hidpi = compute_layout({1280, 800}, {2560, 1600}, 1.0f, true);
  EXPECT_EQ(hidpi.pixel_ratio, 2.0f);
  EXPECT_DOUBLE_EQ(hidpi.free_left(), plain.free_left());
  EXPECT_DOUBLE_EQ(hidpi.free_right(), plain.free_right());
  EXPECT_DOUBLE_EQ(hidpi.lens_shift.x, plain.lens_shift.x);
  EXPECT_DOUBLE_EQ(hidpi.aspect, plain.aspect);
  EXPECT_DOUBLE_EQ(hidpi.aspect, hidpi.free_size.x * hidpi.pixel_ratio / 1600.0);
}

TEST(ViewportLayout, TheUiScaleWidensThePanelsButNeverShrinksThem) {
  const ViewportLayout plain = compute_layout({2560, 1600}, {2560, 1600}, 1.0f, true);
  const ViewportLayout scaled = compute_layout({2560, 1600}, {2560, 1600}, 2.0f, true);
  EXPECT_EQ(scaled.margin, 2.0f * plain.margin);
  EXPECT_EQ(scaled.panel_width, 2.0f * plain.panel_width);
  EXPECT_EQ(scaled.edit_width, 2.0f * plain.edit_width);
  EXPECT_DOUBLE_EQ(scaled.free_left(), scaled.margin + scaled.panel_width);
  const ViewportLayout small = compute_layout({2560, 1600}, {2560, 1600}, 0.5f, true);
  EXPECT_EQ(small.panel_width, plain.panel_width);
  EXPECT_EQ(small.free_origin, plain.free_origin);
}

TEST(ViewportLayout, OnANarrowWindowThePanelSharesAreCapped) {
  const ViewportLayout layout = compute_layout({600, 400}, {600, 400}, 1.0f, true);
  ASSERT_GT((layout.margin + layout.panel_width) / 600.0, 0.6) << "the panels would cover the window";
  EXPECT_DOUBLE_EQ(layout.free_left(), 0.6 * 600.0);
  EXPECT_DOUBLE_EQ(layout.free_right(), (1.0 - 0.35) * 600.0);
  EXPECT_NEAR(layout.free_size.x, 0.05 * 600.0, 1e-9);
  EXPECT_NEAR(layout.lens_shift.x, 0.6 - 0.35, 1e-12);
  EXPECT_NEAR(layout.aspect, 0.05 * 600.0 / 400.0, 1e-12);
}

TEST(ViewportLayout, AMinimisedWindowGivesAFiniteLayout) {
  const ViewportLayout layout = compute_layout({0, 0}, {0, 0}, 1.0f, true);
  EXPECT_EQ(layout.window, glm::dvec2(1.0, 1.0));
  EXPECT_EQ(layout.pixel_ratio, 1.0f);
  EXPECT_EQ(layout.aspect, 1.0);
  EXPECT_TRUE(std::isfinite(layout.lens_shift.x));
  EXPECT_GE(layout.free_size.x, 0.0);
}

TEST(ViewportLayout, TheTimelineStripTakesItsRowsAndAMarginFromTheBottomOfTheFreePart) {
  const ViewportLayout plain = compute_layout({1280, 800}, {1280, 800}, 1.0f, true);
  const ViewportLayout strip = compute_layout({1280, 800}, {1280, 800}, 1.0f, true, true);
  EXPECT_EQ(plain.timeline_height, 0.0f) << "no strip unless asked (no riders)";
  EXPECT_FLOAT_EQ(strip.timeline_height, kTimelineHeight);
  const double taken = kTimelineHeight + strip.margin;
  EXPECT_DOUBLE_EQ(strip.free_size.y, plain.free_size.y - taken);
  EXPECT_EQ(strip.free_size.x, plain.free_size.x) << "as wide as without";
  EXPECT_DOUBLE_EQ(strip.lens_shift.y, (kStatusBarHeight + taken) / 800.0) << "centred above the strip";
  EXPECT_DOUBLE_EQ(strip.height_share, 1.0 - (kStatusBarHeight + taken) / 800.0);
  EXPECT_EQ(strip.ui_scale, 1.0f);
  const ViewportLayout scaled = compute_layout({2560, 1600}, {2560, 1600}, 2.0f, true, true);
  EXPECT_FLOAT_EQ(scaled.timeline_height, 2.0f * kTimelineHeight);
  EXPECT_EQ(scaled.ui_scale, 2.0f);
  const ViewportLayout low = compute_layout({1280, 200}, {1280, 200}, 1.0f, true, true);
  EXPECT_FLOAT_EQ(low.timeline_height + low.margin, 40.0f) << "at most a fifth of the height";
  EXPECT_EQ(compute_layout({1280, 800}, {1280, 800}, 1.0f, false, true).timeline_height, 0.0f) << "none without UI";
}

TEST(ViewportLayout, PointerPositionsInTheFreePartAreRelativeToItsOrigin) {
  const ViewportLayout layout = compute_layout({1280, 800}, {1280, 800}, 1.0f, true);
  const glm::dvec2 pointer{500.0, 321.0};
  EXPECT_EQ(layout.in_free_part(pointer), pointer - layout.free_origin);
  EXPECT_EQ(layout.in_free_part(layout.free_origin), glm::dvec2(0.0, 0.0));
  const ViewportLayout bare = compute_layout({1280, 800}, {1280, 800}, 1.0f, false);
  EXPECT_EQ(bare.in_free_part(pointer), pointer);
}

}  // namespace
}  // namespace sweep::editor
