#include "editor/playback.hpp"

#include <algorithm>
#include <cmath>

namespace sweep::editor {

void Playback::play() {
  playing_ = true;
  last_tick_ = -1.0;
}

void Playback::pause() {
  playing_ = false;
  last_tick_ = -1.0;
}

void Playback::toggle() {
  if (playing_) {
    pause();
  } else {
    play();
  }
}

void Playback::set_speed(double speed) {
  if (std::isfinite(speed)) speed_ = std::clamp(speed, kMinSpeed, kMaxSpeed);
}

void Playback::scrub(double time, double loop) {
  if (!(loop > 0.0) || !std::isfinite(time)) {
    time_ = 0.0;
    return;
  }
  time_ = std::clamp(time, 0.0, loop);
}

void Playback::advance(double dt, double loop) {
  if (!(loop > 0.0)) {
    time_ = 0.0;
    pause();
    return;
  }
  if (!playing_ || !(dt > 0.0) || !std::isfinite(dt)) return;
  time_ = std::fmod(time_ + dt * speed_, loop);
  if (!(time_ >= 0.0)) time_ = 0.0;  // guards a loop of denormal size
}

void Playback::tick(double now, double loop) {
  advance(playing_ && last_tick_ >= 0.0 ? now - last_tick_ : 0.0, loop);
  last_tick_ = playing_ ? now : -1.0;
}

}  // namespace sweep::editor
