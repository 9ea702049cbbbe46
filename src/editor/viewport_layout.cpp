#include "editor/viewport_layout.hpp"

#include <glm/common.hpp>

#include <algorithm>

namespace sweep::editor {

ViewportLayout compute_layout(glm::ivec2 window, glm::ivec2 framebuffer, float ui_scale, bool show_ui, bool timeline) {
  ViewportLayout layout;
  const float scale = std::max(ui_scale, 1.0f);
  layout.ui_scale = scale;
  layout.window = glm::max(glm::dvec2(window), glm::dvec2(1.0));
  layout.pixel_ratio = window.x > 0 ? float(framebuffer.x) / float(window.x) : 1.0f;
  layout.margin = 8.0f * scale;
  double panel_share = 0.0;
  double edit_share = 0.0;
  double status_share = 0.0;
  double timeline_share = 0.0;  // the strip and the margin under it
  if (show_ui) {
    layout.panel_width = 360.0f * scale;
    layout.edit_width = 350.0f * scale;
    panel_share = std::clamp(double(layout.margin + layout.panel_width) / layout.window.x, 0.0, 0.6);
    edit_share = std::clamp(double(layout.margin + layout.edit_width) / layout.window.x, 0.0, 0.35);
    status_share = std::clamp(double(kStatusBarHeight * scale) / layout.window.y, 0.0, 0.1);
    layout.status_height = float(status_share * layout.window.y);
    if (timeline) {
      timeline_share = std::clamp(double((kTimelineHeight + 8.0f) * scale) / layout.window.y, 0.0, 0.2);
      layout.timeline_height = float(timeline_share * layout.window.y) - layout.margin;
      if (layout.timeline_height <= 0.0f) {
        timeline_share = 0.0;
        layout.timeline_height = 0.0f;
      }
    }
  }
  const double bottom_share = status_share + timeline_share;
  layout.free_origin = {panel_share * layout.window.x, 0.0};
  layout.free_size = {(1.0 - panel_share - edit_share) * layout.window.x, (1.0 - bottom_share) * layout.window.y};
  // In normalized device coordinates (2 across the window): the free part's centre.
  layout.lens_shift = {panel_share - edit_share, bottom_share};
  const double width = (1.0 - panel_share - edit_share) * double(framebuffer.x);
  layout.aspect = framebuffer.y > 0 && width > 0.0 ? width / double(framebuffer.y) : 1.0;
  layout.height_share = 1.0 - bottom_share;
  return layout;
}

}  // namespace sweep::editor
