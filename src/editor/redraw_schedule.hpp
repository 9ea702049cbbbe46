#pragma once
// When the viewer draws, so that it uses no CPU when nothing changes and stays fluid without a
// GPU: an event (input, a resize, a drop) asks for a few frames at once, drawn fast (without
// multisampling) while events keep coming; once they stop for kStillDelay one full-quality
// frame is drawn, then the viewer sleeps until the next event. While something animates (the
// riders playing) a fast frame is due every kAnimationInterval; when it stops, the still frame
// follows as after input.
namespace sweep::editor {

class RedrawSchedule {
 public:
  /// Frames drawn after an event, so ImGui's hover and layout settle.
  static constexpr int kSettleFrames = 3;
  /// Seconds without events after which the still (full-quality) frame is drawn.
  static constexpr double kStillDelay = 0.25;
  /// Seconds between the frames of an animation (at most 60 a second).
  static constexpr double kAnimationInterval = 1.0 / 60.0;

  /// An event arrived at time `now` (seconds).
  void input(double now);
  /// Something changed without an event (the first frame, a scripted step): draw it, still.
  void request();
  /// Whether something animates: while it does, frames are drawn continuously (fast ones, at
  /// most one every kAnimationInterval). Set before wait_time and due are asked.
  void set_animating(bool on) { animating_ = on; }
  bool animating() const { return animating_; }
  /// How long the loop may wait for events: 0 to draw now, < 0 for as long as it takes.
  double wait_time(double now) const;
  /// Whether a frame is due at `now`.
  bool due(double now) const;
  /// Whether the frame drawn at `now` should be a fast one (events came in the last kStillDelay,
  /// or something animates).
  bool fast(double now) const;
  /// A frame was drawn at `now`, fast or not.
  void drawn(bool fast, double now);

 private:
  int frames_left_ = 0;
  double last_input_ = -1e300;
  double last_drawn_ = -1e300;
  bool still_owed_ = false;  // the last frame was fast: a still one follows once events stop
  bool animating_ = false;
};

}  // namespace sweep::editor
