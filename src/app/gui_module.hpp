#pragma once
// The interface between the `sweep` executable and the sweep_gui module (libsweep_gui.so) it
// opens with dlopen only for `sweep view`, `sweep render` and the plain form's viewer, so the
// other commands load no GL, OSMesa, GLFW or ImGui. Both sides are built from the same sources
// in one build, so the table passes C++ types; kGuiInterfaceVersion catches a stale install.
#include "app/viewer/viewer.hpp"
#include "model/document.hpp"
#include "model/evaluation/scene.hpp"
#include "render/camera.hpp"
#include "render/display_settings.hpp"
#include "snapshot/run_snapshots.hpp"

#include <glm/vec2.hpp>

#include <filesystem>
#include <string>

namespace sweep::app {

/// Bump when GuiEntryPoints or the structs it passes change.
inline constexpr int kGuiInterfaceVersion = 6;  // 2: grid; 3: riders, sequences; 4: --play; 5: snapshot; 6: threads

/// Everything `sweep render` has settled before it needs a GL context.
struct PictureRequest {
  const Document* doc = nullptr;
  const Scene* scene = nullptr;  // evaluated from *doc
  render::Camera camera;
  glm::ivec2 size{800, 600};
  render::DisplaySettings display;
  std::filesystem::path image_base;  // the folder the materials' images are read from
  std::string output;                // PNG file to write (a still)
  double time = 0.0;                 // riders are drawn where they are at this time (seconds)
  /// Not empty: a sequence instead of a still, DIR/frame_0000.png ... at `fps` frames a second
  /// from time 0 for `seconds` (the frame at `seconds` itself is left out, so the loop repeats).
  std::filesystem::path sequence;
  double fps = 24.0;
  double seconds = 0.0;
  int ride = -1;  // a rider's index: the camera rides along with it
  render::RideView ride_view = render::RideView::Chase;
};

struct GuiEntryPoints {
  int version = kGuiInterfaceVersion;
  /// viewer::run_viewer: the window until it closes; returns the exit code.
  int (*run_viewer)(const viewer::ViewerOptions& options) = nullptr;
  /// Renders the request through OSMesa, writes the PNG and prints what `sweep render` prints.
  int (*render_picture)(const PictureRequest& request) = nullptr;
  /// snapshot::run_snapshots: `sweep snapshot`; returns the exit code.
  int (*run_snapshots)(const snapshot::RunOptions& options) = nullptr;
  /// set_worker_count in the module (its own copy of the geometry library): --threads.
  void (*set_workers)(int threads) = nullptr;
};

/// The module's one exported symbol: extern "C" const GuiEntryPoints* sweep_gui_entry_points().
inline constexpr const char* kGuiEntrySymbol = "sweep_gui_entry_points";
using GuiEntryFunction = const GuiEntryPoints* (*)();

/// Opens the module (next to the executable, else ../lib/sweep/) once and returns its table;
/// on failure prints "sweep: cannot load the viewer (PATH): ..." and returns nullptr.
/// gui_loader.cpp
const GuiEntryPoints* load_gui_module();

}  // namespace sweep::app
