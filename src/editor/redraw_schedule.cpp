#include "editor/redraw_schedule.hpp"

#include <algorithm>

namespace sweep::editor {

void RedrawSchedule::input(double now) {
  last_input_ = now;
  frames_left_ = std::max(frames_left_, kSettleFrames);
}

void RedrawSchedule::request() {
  frames_left_ = std::max(frames_left_, 1);
}

double RedrawSchedule::wait_time(double now) const {
  if (frames_left_ > 0) return 0.0;
  if (animating_) return std::max(0.0, last_drawn_ + kAnimationInterval - now);
  if (still_owed_) return std::max(0.0, last_input_ + kStillDelay - now);
  return -1.0;
}

bool RedrawSchedule::due(double now) const {
  return frames_left_ > 0 || (animating_ && now - last_drawn_ >= kAnimationInterval) ||
         (!animating_ && still_owed_ && now - last_input_ >= kStillDelay);
}

bool RedrawSchedule::fast(double now) const {
  return animating_ || now - last_input_ < kStillDelay;
}

void RedrawSchedule::drawn(bool fast, double now) {
  if (frames_left_ > 0) --frames_left_;
  still_owed_ = fast;
  last_drawn_ = now;
}

}  // namespace sweep::editor
