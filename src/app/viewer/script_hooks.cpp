#include "app/viewer/script_hooks.hpp"

#include "app/viewer/input.hpp"
#include "render/offscreen_target.hpp"
#include "render/png_file.hpp"

#include <algorithm>
#include <cstdio>
#include <exception>

namespace sweep::viewer {
namespace {

constexpr std::size_t kFrameTimeWindow = 120;  // frames averaged for the stats panel

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

/// "N frames, mean M ms, median D ms" of `ms` (sorted in place).
void print_times(const char* what, std::vector<double>& ms) {
  if (ms.empty()) return;
  double sum = 0.0;
  for (double t : ms) sum += t;
  std::sort(ms.begin(), ms.end());
  std::printf("%s frames %zu, mean %.2f ms, median %.2f ms\n", what, ms.size(), sum / double(ms.size()),
              ms[ms.size() / 2]);
}

}  // namespace

bool ScriptHooks::after_draw(ViewerState& s, glm::ivec2 framebuffer, float edit_bottom) {
  if (wants_frame()) {
    stable_frames_ = edit_bottom == last_edit_bottom_ ? stable_frames_ + 1 : 0;
    last_edit_bottom_ = edit_bottom;
    if (stable_frames_ >= 3) print_handles(s, framebuffer, edit_bottom);
  }
  if (!s.pending_screenshot.empty()) {
    save_screenshot(s, s.pending_screenshot, framebuffer);
    s.pending_screenshot.clear();
  }
  if (options_.frame_count > 0 && frames_ + 1 >= options_.frame_count && !options_.screenshot.empty()) {
    return save_screenshot(s, options_.screenshot, framebuffer);
  }
  return true;
}

void ScriptHooks::frame_done(ViewerState& s, double ms, bool fast) {
  ++frames_;
  if (frames_ <= 2) return;  // the first frames include start-up and the uploads
  (fast ? fast_ms_ : still_ms_).push_back(ms);
  s.stats.frame_ms.push_back(ms);
  if (s.stats.frame_ms.size() > kFrameTimeWindow) s.stats.frame_ms.pop_front();
}

void ScriptHooks::print_summary(const ViewerState& s) const {
  if (!options_.print_frame_time) return;
  std::vector<double> all = still_ms_;
  all.insert(all.end(), fast_ms_.begin(), fast_ms_.end());
  if (!all.empty()) {
    double sum = 0.0;
    for (double ms : all) sum += ms;
    std::sort(all.begin(), all.end());
    std::printf("frames %zu, mean frame time %.2f ms, median %.2f ms, triangles %zu, vertices %zu\n", all.size(),
                sum / double(all.size()), all[all.size() / 2], s.stats.render.triangles, s.stats.render.vertices);
  }
  std::vector<double> fast = fast_ms_;
  std::vector<double> still = still_ms_;
  print_times("moving (no multisampling):", fast);
  print_times("still:", still);
  const std::vector<double>& remesh = s.stats.remesh_ms;
  if (remesh.empty()) return;
  double sum = 0.0;
  for (double ms : remesh) sum += ms;
  std::printf("edits %zu, mean re-mesh %.3f ms, max %.3f ms\n", remesh.size(), sum / double(remesh.size()),
              *std::max_element(remesh.begin(), remesh.end()));
}

void ScriptHooks::print_handles(const ViewerState& s, glm::ivec2 framebuffer, float edit_bottom) {
  const auto positions = handle_positions(s, screen_mapping(s, framebuffer));
  const int selected = s.selected();
  std::printf("selected %s, %zu handles\n", selected >= 0 ? display_name(s.doc(), selected).c_str() : "nothing",
              positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (positions[i]) std::printf("handle %zu %.2f %.2f\n", i, positions[i]->x, positions[i]->y);
  }
  const double edit_left = s.layout.window.x - double(s.layout.margin + s.layout.edit_width);
  std::printf("edit %.2f %.2f\n", edit_left, double(edit_bottom));
  std::printf("panel %.2f\n", double(s.layout.margin + s.layout.panel_width));
  std::fflush(stdout);
  handles_printed_ = true;
}

}  // namespace sweep::viewer
