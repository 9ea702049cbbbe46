// The riders' clock: it advances by real time times the speed and wraps at the loop, stands still
// when paused, scrubbing sets it, and the ticks of the frames drive it without playing the time
// spent paused.
#include "editor/playback.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace sweep::editor {
namespace {

TEST(Playback, StartsPausedAtTimeZeroAtRealSpeed) {
  const Playback p;
  EXPECT_FALSE(p.playing());
  EXPECT_EQ(p.time(), 0.0);
  EXPECT_EQ(p.speed(), 1.0);
}

TEST(Playback, AdvanceWrapsAtTheLoop) {
  Playback p;
  p.play();
  p.advance(2.5, 6.0);
  EXPECT_DOUBLE_EQ(p.time(), 2.5);
  p.advance(4.0, 6.0);
  EXPECT_NEAR(p.time(), 0.5, 1e-12) << "6.5 wraps to 0.5";
  p.advance(13.0, 6.0);
  EXPECT_NEAR(p.time(), 1.5, 1e-12) << "several loops at once";
  EXPECT_TRUE(p.playing());
}

TEST(Playback, TheSpeedScalesTheTimeAndStaysInItsRange) {
  Playback p;
  p.play();
  p.set_speed(2.0);
  p.advance(1.0, 10.0);
  EXPECT_DOUBLE_EQ(p.time(), 2.0);
  p.set_speed(0.25);
  p.advance(2.0, 10.0);
  EXPECT_DOUBLE_EQ(p.time(), 2.5);
  p.set_speed(100.0);
  EXPECT_EQ(p.speed(), Playback::kMaxSpeed);
  p.set_speed(0.0);
  EXPECT_EQ(p.speed(), Playback::kMinSpeed);
  p.set_speed(std::numeric_limits<double>::quiet_NaN());
  EXPECT_EQ(p.speed(), Playback::kMinSpeed) << "a NaN is ignored";
}

TEST(Playback, PausedTheTimeStandsStill) {
  Playback p;
  p.play();
  p.advance(1.0, 6.0);
  p.pause();
  p.advance(3.0, 6.0);
  EXPECT_DOUBLE_EQ(p.time(), 1.0);
  p.toggle();
  EXPECT_TRUE(p.playing());
  p.toggle();
  EXPECT_FALSE(p.playing());
}

TEST(Playback, ScrubbingSetsTheTimeWithinTheLoop) {
  Playback p;
  p.scrub(4.25, 6.0);
  EXPECT_DOUBLE_EQ(p.time(), 4.25);
  EXPECT_FALSE(p.playing()) << "scrubbing does not start the clock";
  p.scrub(9.0, 6.0);
  EXPECT_DOUBLE_EQ(p.time(), 6.0);
  p.scrub(-1.0, 6.0);
  EXPECT_DOUBLE_EQ(p.time(), 0.0);
  p.scrub(3.0, 0.0);
  EXPECT_DOUBLE_EQ(p.time(), 0.0) << "no riders, no time";
  p.play();
  p.scrub(5.0, 6.0);
  p.advance(2.0, 6.0);
  EXPECT_NEAR(p.time(), 1.0, 1e-12) << "playing goes on from where it was scrubbed to";
}

TEST(Playback, WithoutALoopTheClockStops) {
  Playback p;
  p.play();
  p.advance(1.0, 6.0);
  p.advance(1.0, 0.0);  // the riders were deleted
  EXPECT_FALSE(p.playing());
  EXPECT_EQ(p.time(), 0.0);
}

TEST(Playback, TicksAdvanceByTheTimeBetweenFramesAndNotByThePauses) {
  Playback p;
  p.tick(10.0, 6.0);
  EXPECT_EQ(p.time(), 0.0) << "paused";
  p.play();
  p.tick(20.0, 6.0);
  EXPECT_EQ(p.time(), 0.0) << "the first tick after play only starts counting";
  p.tick(20.5, 6.0);
  p.tick(21.0, 6.0);
  EXPECT_DOUBLE_EQ(p.time(), 1.0);
  p.pause();
  p.tick(25.0, 6.0);
  p.play();
  p.tick(100.0, 6.0);
  p.tick(100.25, 6.0);
  EXPECT_DOUBLE_EQ(p.time(), 1.25) << "the 79 s paused are not played";
  p.set_speed(4.0);
  p.tick(101.25, 6.0);
  EXPECT_DOUBLE_EQ(p.time(), 5.25);
  p.tick(101.5, 6.0);
  EXPECT_NEAR(p.time(), 0.25, 1e-12) << "wraps";
  p.tick(102.0, 0.0);
  EXPECT_FALSE(p.playing()) << "the riders went away";
  EXPECT_EQ(p.time(), 0.0);
}

}  // namespace
}  // namespace sweep::editor
