#pragma once
// The riders' clock in the viewer: the time shown, whether it runs, and how fast. The viewer
// ticks it with the real time before each frame; while it runs the redraw schedule draws
// continuously, and while it is paused nothing moves, so nothing is drawn. No GL, no window.
namespace sweep::editor {

class Playback {
 public:
  /// The speed factor's range (times real time).
  static constexpr double kMinSpeed = 0.1;
  static constexpr double kMaxSpeed = 4.0;

  /// The time shown, in seconds: in [0, loop] (loop itself only when scrubbed there).
  double time() const { return time_; }
  bool playing() const { return playing_; }
  double speed() const { return speed_; }

  /// Starts or stops the clock. Starting forgets the last tick, so the time between a pause and
  /// the next start is not played.
  void play();
  void pause();
  void toggle();
  /// The speed factor, clamped to [kMinSpeed, kMaxSpeed] (a non-finite one is ignored).
  void set_speed(double speed);
  /// Sets the time (a slider dragged), clamped to [0, loop] (0 when loop <= 0). Playing goes on
  /// from there.
  void scrub(double time, double loop);

  /// Moves the time on by `dt` seconds of real time times the speed, wrapping at `loop` (the
  /// riders' longest loop: model/evaluation/riders.hpp). Paused, or dt <= 0: nothing. Without a loop
  /// (loop <= 0: no riders) the time goes back to 0 and the clock stops.
  void advance(double dt, double loop);
  /// Once per frame at `now` seconds (a monotonic clock): advances by the time since the last
  /// tick while playing. The first tick after play() only starts counting.
  void tick(double now, double loop);

 private:
  double time_ = 0.0;
  bool playing_ = false;
  double speed_ = 1.0;
  double last_tick_ = -1.0;  // < 0: none since play()
};

}  // namespace sweep::editor
