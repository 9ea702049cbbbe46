#pragma once
// Where the panels go and what is left for the 3D view, computed once per frame from the
// window's size before anything is drawn (never read back from the panels afterwards).
#include <glm/vec2.hpp>

namespace sweep::editor {

/// The status bar's height in screen units at a UI scale of 1: one line of ImGui's default font.
inline constexpr float kStatusBarHeight = 22.0f;
/// The timeline strip's height in screen units at a UI scale of 1: two rows of widgets.
inline constexpr float kTimelineHeight = 62.0f;

struct ViewportLayout {
  glm::dvec2 window{1.0};    // window size in screen units (pointer positions come in these)
  float pixel_ratio = 1.0f;  // framebuffer pixels per screen unit
  float ui_scale = 1.0f;     // what the panels' sizes are multiplied by (>= 1)
  float margin = 8.0f;       // between the panels and the window's edges, screen units
  // The main panel on the left and the edit panel on the right (screen units); 0 wide without UI.
  float panel_width = 0.0f;
  float edit_width = 0.0f;
  float status_height = 0.0f;  // the status bar along the bottom (screen units); 0 without UI
  /// The timeline strip (riders), a margin above the status bar, from the main panel to the
  /// window's right edge (the edit panel ends above it), screen units; 0 without UI or riders.
  float timeline_height = 0.0f;
  // The part of the window the panels leave free, where the scene is centred and dragged.
  glm::dvec2 free_origin{0.0};
  glm::dvec2 free_size{1.0};
  glm::dvec2 lens_shift{0.0};  // for Camera::lens_shift: centres the picture in the free part
  double aspect = 1.0;         // the free part's width / the window's height, for framing
  double height_share = 1.0;   // the free part's height / the window's height (the status bar's rest)

  /// The free part's left and right edges in screen units.
  double free_left() const { return free_origin.x; }
  double free_right() const { return free_origin.x + free_size.x; }
  /// A pointer position relative to the free part (for the arcball).
  glm::dvec2 in_free_part(const glm::dvec2& pointer) const { return pointer - free_origin; }
};

/// The layout for a window of `window` screen units and `framebuffer` pixels whose UI is drawn
/// at `ui_scale` (the monitor's content scale, >= 1 in effect), with or without the panels.
/// Panels cover at most 60 % (main) and 35 % (edit) of the width; the status bar, the bottom
/// kStatusBarHeight (times the scale), at most 10 % of the height. With `timeline` (and the UI),
/// the timeline strip takes kTimelineHeight (times the scale) and a margin above the status bar,
/// at most 20 % of the height, from the free part.
ViewportLayout compute_layout(glm::ivec2 window, glm::ivec2 framebuffer, float ui_scale, bool show_ui,
                              bool timeline = false);

}  // namespace sweep::editor
