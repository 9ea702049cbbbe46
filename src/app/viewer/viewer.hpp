#pragma once
// The interactive viewer: a GLFW window with the shared renderer and ImGui panels.
#include "model/evaluation/scene.hpp"
#include "render/display_settings.hpp"

#include <glm/vec2.hpp>

#include <string>

namespace sweep::viewer {

struct ViewerOptions {
  std::string file;  // SWP file to open first; empty opens an empty scene
  glm::ivec2 window_size{1280, 800};
  int samples = 4;          // multisampling of still frames (0: none)
  bool live_reload = true;  // reload the file when another program changes it (--no-reload: off)
  /// Initial modes. The viewer shows the control points from the start (the original tool's
  /// users look for its yellow points); `sweep render` keeps them off by default.
  render::DisplaySettings display = [] {
    render::DisplaySettings settings;
    settings.control_points = true;
    return settings;
  }();
  std::string screenshot;         // when set: save a PNG of the window after `frame_count` frames, then quit
  int frame_count = 0;            // > 0: draw this many frames without waiting for input, then quit
  bool print_frame_time = false;  // draw continuously and print frame times on exit
  bool show_ui = true;            // ImGui panels
  EvaluationOptions evaluation;   // frame method and seam mode the scene is evaluated with
  /// For scripted tests: select this object (name or display name such as "bez2#0") at start,
  /// print its handles' window positions to stdout once the layout has settled, and report
  /// saves on stdout.
  std::string select;
  bool play = false;          // the riders start playing (--play)
  std::string ride;           // the camera rides along with this rider from the start (--ride)
  bool first_person = false;  // --ride-view first-person (else chase)
};

/// Runs the viewer until the window closes (or `frame_count` frames). Returns the exit code: 0,
/// or 1 after printing one line when there is no display, the file does not load, or the
/// window cannot be opened.
int run_viewer(const ViewerOptions& options);

}  // namespace sweep::viewer
