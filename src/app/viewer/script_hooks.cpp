#include "app/viewer/script_hooks.hpp"

#include "app/viewer/actions.hpp"
#include "app/viewer/input.hpp"
#include "editor/adaptive_stats.hpp"
#include "render/offscreen_target.hpp"
#include "render/png_file.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <exception>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace sweep::viewer {
namespace {

constexpr std::size_t kFrameTimeWindow = 120;  // frames averaged for the stats panel

/// Writes the PNG of the window asked for in `s.pending_screenshot` (its back buffer as drawn,
/// panels and all) and says so with its full path.
void write_window_png(ViewerState& s, glm::ivec2 framebuffer) {
  const ScreenshotRequest request = s.pending_screenshot;
  s.pending_screenshot = {};
  try {
    const render::Image image = render::read_window_framebuffer(framebuffer);
    render::save_png_file(request.path, image);
    s.status = "saved PNG of the window " + request.path.string() + " (" + std::to_string(image.width) + " x " +
               std::to_string(image.height) + " pixels)";
    s.error.clear();
  } catch (const std::exception& e) {  // save_png_file names the path and the cause
    s.error = std::string("PNG of the window failed: ") + e.what();
  }
}

bool save_screenshot(ViewerState& s, const std::string& path, glm::ivec2 framebuffer) {
  try {
    render::save_png_file(path, render::read_window_framebuffer(framebuffer));
    s.status = "saved " + path;
    return true;
  } catch (const std::exception& e) {
    s.error = std::string("screenshot failed: ") + e.what();
    return false;
  }
}

/// The mean of `values`. Precondition: not empty.
double mean(const std::vector<double>& values) {
  return std::accumulate(values.begin(), values.end(), 0.0) / double(values.size());
}

/// The median of `values` (sorted in place). Precondition: not empty.
double median(std::vector<double>& values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

/// "WHAT frames N, mean M ms, median D ms", nothing for no frames.
void print_times(const char* what, std::vector<double> ms) {
  if (ms.empty()) return;
  std::printf("%s frames %zu, mean %.2f ms, median %.2f ms\n", what, ms.size(), mean(ms), median(ms));
}

}  // namespace

ScriptHooks::ScriptHooks(const ViewerOptions& options, ViewerState& s) : options_(options) {
  if (!options_.select.empty()) s.item_positions = &positions_;
}

bool ScriptHooks::after_draw(ViewerState& s, glm::ivec2 framebuffer) {
  if (wants_frame()) {
    // 0 when the edit panel is hidden (no UI): the handles are printed all the same.
    const float edit_bottom = positions_.position("edit", glm::vec2(0.0f)).y;
    stable_frames_ = edit_bottom == last_edit_bottom_ ? stable_frames_ + 1 : 0;
    last_edit_bottom_ = edit_bottom;
    if (stable_frames_ >= 3) print_handles(s, framebuffer);
  }
  if (!options_.select.empty() && handles_printed_) {
    print_items();
    print_counts(s);
  }
  positions_.clear();  // the next frame marks what it shows
  ScreenshotRequest& request = s.pending_screenshot;
  if (!request.path.empty() && request.with_panels && request.frames_to_wait-- <= 0) write_window_png(s, framebuffer);
  if (!options_.select.empty()) print_messages(s);
  if (options_.frame_count > 0 && frames_ + 1 >= options_.frame_count && !options_.screenshot.empty()) {
    return save_screenshot(s, options_.screenshot, framebuffer);
  }
  return true;
}

void ScriptHooks::frame_done(ViewerState& s, double ms, double update_ms, bool fast) {
  ++frames_;
  const auto now = std::chrono::steady_clock::now();
  const auto previous = std::exchange(last_frame_end_, now);
  if (frames_ <= 2) return;  // the first frames include start-up and the uploads
  // Drawing continuously (--frame-time), the time from one frame's end to the next is how long
  // the window could not answer: the frame, and anything the loop did between frames.
  const double gap = std::chrono::duration<double, std::milli>(now - previous).count();
  longest_gap_ms_ = std::max(longest_gap_ms_, gap);
  longest_update_ms_ = std::max(longest_update_ms_, update_ms);
  // While work runs in the background, the window must keep answering (issue 29: under 100 ms).
  if (s.session.evaluating() || s.task) longest_busy_gap_ms_ = std::max(longest_busy_gap_ms_, gap);
  // The frame time at the start and at the end of a long run (issue 29: they must agree).
  if (first_ms_.size() < kEndFrames) first_ms_.push_back(ms);
  last_ms_.push_back(ms);
  if (last_ms_.size() > kEndFrames) last_ms_.pop_front();
  (fast ? fast_ms_ : still_ms_).push_back(ms);
  s.stats.frame_ms.push_back(ms);
  if (s.stats.frame_ms.size() > kFrameTimeWindow) s.stats.frame_ms.pop_front();
}

void ScriptHooks::print_summary(const ViewerState& s) const {
  if (!options_.print_frame_time) return;
  std::vector<double> all = still_ms_;
  all.insert(all.end(), fast_ms_.begin(), fast_ms_.end());
  if (!all.empty()) {
    std::printf("frames %zu, mean frame time %.2f ms, median %.2f ms, triangles %zu, vertices %zu\n", all.size(),
                mean(all), median(all), s.stats.render.triangles, s.stats.render.vertices);
  }
  print_times("moving (no multisampling):", fast_ms_);
  print_times("still:", still_ms_);
  if (!all.empty()) {
    std::printf("longest gap between frames %.1f ms, longest input+UI+edits part of a frame %.1f ms\n", longest_gap_ms_,
                longest_update_ms_);
    std::printf("longest gap between frames while work ran in the background %.1f ms\n", longest_busy_gap_ms_);
    std::vector<double> first = first_ms_;
    std::vector<double> last(last_ms_.begin(), last_ms_.end());
    std::printf("median frame time of the first %zu frames %.2f ms, of the last %zu %.2f ms\n", first.size(),
                median(first), last.size(), median(last));
  }
  const std::vector<double>& remesh = s.stats.remesh_ms;
  if (remesh.empty()) return;
  std::printf("edits %zu, mean re-mesh %.3f ms, max %.3f ms\n", remesh.size(), mean(remesh),
              *std::max_element(remesh.begin(), remesh.end()));
}

void ScriptHooks::print_handles(ViewerState& s, glm::ivec2 framebuffer) {
  const auto positions = handle_positions(s, screen_mapping(s, framebuffer));
  const int selected = s.selected();
  std::printf("selected %s, %zu handles\n", selected >= 0 ? display_name(s.doc(), selected).c_str() : "nothing",
              positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (positions[i]) std::printf("handle %zu %.2f %.2f\n", i, positions[i]->x, positions[i]->y);
  }
  // The edit panel's left edge comes from the layout it is placed by; its lower edge from
  // where ImGui ended up (it is as tall as its contents). -1 -1: that checkbox is not shown.
  const double edit_left = s.layout.window.x - double(s.layout.margin + s.layout.edit_width);
  const glm::vec2 edit = positions_.position("edit", glm::vec2(0.0f));
  const glm::vec2 adaptive = positions_.position("adaptive", glm::vec2(-1.0f));
  const glm::vec2 caps = positions_.position("caps", glm::vec2(-1.0f));
  std::printf("edit %.2f %.2f\n", edit_left, double(edit.y));
  std::printf("panel %.2f\n", double(s.layout.margin + s.layout.panel_width));
  std::printf("adaptive %.2f %.2f\n", double(adaptive.x), double(adaptive.y));
  std::printf("caps %.2f %.2f\n", double(caps.x), double(caps.y));
  std::fflush(stdout);
  handles_printed_ = true;
}

void ScriptHooks::print_items() {
  bool printed = false;
  for (const auto& [name, at] : positions_.all()) {
    const auto shown = printed_items_.find(name);
    if (shown != printed_items_.end() && shown->second == at) continue;
    printed_items_.insert_or_assign(name, at);
    std::printf("item %.2f %.2f %s\n", double(at.x), double(at.y), name.c_str());
    printed = true;
  }
  if (printed) std::fflush(stdout);
}

void ScriptHooks::print_messages(const ViewerState& s) {
  const auto print_lines = [](const char* what, const std::string& text) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) std::printf("%s %s\n", what, line.c_str());
    std::fflush(stdout);
  };
  if (s.status != last_status_) print_lines("status", s.status);
  const std::string selection = s.selected() >= 0 ? display_name(s.doc(), s.selected()) : std::string("nothing");
  if (selection != last_selection_) print_lines("selection", selection);
  last_selection_ = selection;
  if (s.error != last_error_) print_lines("error", s.error);
  last_status_ = s.status;
  last_error_ = s.error;
}

void ScriptHooks::print_counts(const ViewerState& s) {
  const std::string line = editor::summary_line(
      editor::sampling_summary(s.doc(), s.session.scene(), s.session.evaluation(), s.views.visibility(s.doc())));
  if (line == last_counts_) return;
  last_counts_ = line;
  std::printf("counts %s\n", line.c_str());
  std::fflush(stdout);
}

}  // namespace sweep::viewer
