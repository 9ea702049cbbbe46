#pragma once
// What scripted runs and measurements ask of the viewer, kept out of the main loop: a fixed
// frame count (--frame-count), a screenshot of the last frame (--screenshot), the selected
// curve's handle positions and where the widgets the GUI drivers click ended up, once the layout
// settles, and the sampling counts whenever they change (--select), and frame times (--frame-time).
#include "app/viewer/item_positions.hpp"
#include "app/viewer/viewer.hpp"
#include "app/viewer/viewer_state.hpp"

#include <glm/vec2.hpp>

#include <chrono>
#include <deque>
#include <map>
#include <string>
#include <vector>

namespace sweep::viewer {

class ScriptHooks {
 public:
  /// With --select, gives `s` the registry the panels mark widget positions in
  /// (s.item_positions). `s` must outlive the hooks' use of it: the viewer owns both.
  ScriptHooks(const ViewerOptions& options, ViewerState& s);
  // The state points at positions_: a copy or move would leave it pointing at the old one.
  ScriptHooks(const ScriptHooks&) = delete;
  ScriptHooks& operator=(const ScriptHooks&) = delete;

  /// Draw every frame without waiting for events (a frame count or a measurement).
  bool continuous() const { return options_.frame_count > 0 || options_.print_frame_time; }
  /// More frames are needed although nothing happened (handles not printed yet).
  bool wants_frame() const { return !options_.select.empty() && !handles_printed_; }
  /// The frame count is reached: stop after this frame.
  bool last_frame() const { return options_.frame_count > 0 && frames_ >= options_.frame_count; }

  /// After the scene and UI are drawn, before they are shown: a Save PNG of the window asked for
  /// (s.pending_screenshot with panels, once its frames_to_wait are drawn), the handles once the
  /// edit panel's lower edge has stayed put for 3 frames, then the widgets that appeared or moved
  /// ("item X Y NAME"), the counts, with --select every new status and error line ("status LINE",
  /// "error LINE"), then the --screenshot of the last frame.
  /// Returns false when the --screenshot cannot be written (the error is in the state).
  bool after_draw(ViewerState& s, glm::ivec2 framebuffer);
  /// Counts a finished frame that took `ms`, of which `update_ms` went to input, the panels and
  /// the edits they made (what a re-mesh on the drawing thread would lengthen), fast or still.
  void frame_done(ViewerState& s, double ms, double update_ms, bool fast);
  /// --frame-time: prints frame and re-mesh statistics on exit.
  void print_summary(const ViewerState& s) const;

 private:
  void print_handles(ViewerState& s, glm::ivec2 framebuffer);
  /// The status and error, a line each, and the selected object ("selection NAME"), whenever
  /// they change.
  void print_messages(const ViewerState& s);
  /// "counts " + editor::summary_line (what the stats panel shows), when it changed.
  void print_counts(const ViewerState& s);
  /// "item X Y NAME" for every widget marked this frame that is new or has moved since printed.
  void print_items();

  ViewerOptions options_;
  int frames_ = 0;
  bool handles_printed_ = false;
  int stable_frames_ = 0;
  float last_edit_bottom_ = -1.0f;
  ItemPositions positions_;  // this frame's marks, while s.item_positions points here
  std::string last_counts_;
  std::map<std::string, glm::vec2, std::less<>> printed_items_;  // where print_items last saw each
  std::string last_status_;
  std::string last_selection_;
  std::string last_error_;
  std::chrono::steady_clock::time_point last_frame_end_;
  double longest_gap_ms_ = 0.0;  // between the ends of consecutive frames, after the first two
  double longest_update_ms_ = 0.0;
  double longest_busy_gap_ms_ = 0.0;  // the same, while an evaluation or task ran in the background
  static constexpr std::size_t kEndFrames = 200;
  std::vector<double> first_ms_;  // the first kEndFrames frames' times
  std::deque<double> last_ms_;    // the last kEndFrames frames' times
  std::vector<double> fast_ms_;
  std::vector<double> still_ms_;
};

}  // namespace sweep::viewer
