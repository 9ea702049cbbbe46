// When the viewer draws: a few fast frames after an event and one still frame when events stop,
// nothing at all when idle; while something animates (riders playing) a fast frame every
// kAnimationInterval, and the still frame once it stops.
#include "editor/redraw_schedule.hpp"

#include <gtest/gtest.h>

namespace sweep::editor {
namespace {

/// Draws frames at `now` while they are due (at most `limit`); returns how many.
int draw_due(RedrawSchedule& schedule, double now, int limit = 100) {
  int frames = 0;
  while (frames < limit && schedule.due(now)) {
    schedule.drawn(schedule.fast(now), now);
    ++frames;
  }
  return frames;
}

TEST(RedrawSchedule, IdleItWaitsForeverAndDrawsNothing) {
  RedrawSchedule schedule;
  EXPECT_LT(schedule.wait_time(0.0), 0.0);
  EXPECT_FALSE(schedule.due(0.0));
  EXPECT_FALSE(schedule.due(1000.0));
}

TEST(RedrawSchedule, AnEventDrawsFastFramesThenOneStillFrame) {
  RedrawSchedule schedule;
  schedule.input(1.0);
  EXPECT_EQ(schedule.wait_time(1.0), 0.0);
  EXPECT_TRUE(schedule.fast(1.0));
  EXPECT_EQ(draw_due(schedule, 1.0), RedrawSchedule::kSettleFrames);
  EXPECT_NEAR(schedule.wait_time(1.1), RedrawSchedule::kStillDelay - 0.1, 1e-12) << "until the still frame";
  EXPECT_FALSE(schedule.due(1.1));
  const double later = 1.0 + RedrawSchedule::kStillDelay;
  EXPECT_TRUE(schedule.due(later));
  EXPECT_FALSE(schedule.fast(later));
  EXPECT_EQ(draw_due(schedule, later), 1);
  EXPECT_LT(schedule.wait_time(later + 5.0), 0.0) << "then idle";
  EXPECT_FALSE(schedule.due(later + 5.0));
}

TEST(RedrawSchedule, AnimatingDrawsFastFramesAtMostEveryInterval) {
  RedrawSchedule schedule;
  schedule.set_animating(true);
  EXPECT_TRUE(schedule.animating());
  EXPECT_EQ(schedule.wait_time(10.0), 0.0);
  EXPECT_TRUE(schedule.due(10.0));
  EXPECT_TRUE(schedule.fast(10.0)) << "moving frames, as while the view moves";
  EXPECT_EQ(draw_due(schedule, 10.0), 1);
  EXPECT_NEAR(schedule.wait_time(10.0), RedrawSchedule::kAnimationInterval, 1e-12);
  EXPECT_FALSE(schedule.due(10.0 + 0.5 * RedrawSchedule::kAnimationInterval));
  int frames = 0;
  const double step = RedrawSchedule::kAnimationInterval + 1e-9;  // clear of rounding
  for (int k = 1; k <= 60; ++k) frames += draw_due(schedule, 10.0 + k * step);
  EXPECT_EQ(frames, 60) << "a second of frames";
}

TEST(RedrawSchedule, WhenTheAnimationStopsOneStillFrameFollowsThenNothing) {
  RedrawSchedule schedule;
  schedule.set_animating(true);
  draw_due(schedule, 5.0);
  schedule.set_animating(false);
  EXPECT_GE(schedule.wait_time(5.01), 0.0) << "the still frame is owed";
  EXPECT_TRUE(schedule.due(5.01)) << "no input for long: the still frame at once";
  EXPECT_FALSE(schedule.fast(5.01));
  EXPECT_EQ(draw_due(schedule, 5.01), 1);
  EXPECT_LT(schedule.wait_time(6.0), 0.0) << "paused: idle";
  EXPECT_FALSE(schedule.due(60.0));
}

}  // namespace
}  // namespace sweep::editor
