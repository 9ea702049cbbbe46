// sweep_gui (libsweep_gui.so): the drawing half of `sweep view` and `sweep render`, opened by
// the `sweep` executable only when a command draws (gui_loader.cpp). Options are parsed and files
// checked in the executable, so help and error messages do not depend on this module.
#include "app/gui_module.hpp"

#include "editor/overlay_builder.hpp"
#include "geometry/thread_pool.hpp"
#include "headless/headless_renderer.hpp"
#include "model/evaluation/riders.hpp"
#include "render/draw_list.hpp"
#include "render/png_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <memory>
#include <string>

namespace sweep::app {
namespace {

void print_render_notes(const render::RenderStats& stats) {
  for (const std::string& warning : stats.warnings) {
    std::fprintf(stderr, "sweep: warning: %s; drawn in its colour\n", warning.c_str());
  }
  if (stats.color_range > 0.0f) {
    std::printf("colour range: -%g (blue) to %g (red)\n", static_cast<double>(stats.color_range),
                static_cast<double>(stats.color_range));
  }
}

/// The picture at `time`: riders placed, the camera riding along if asked.
render::Image picture_at(headless::HeadlessRenderer& renderer, render::DrawList& list, const PictureRequest& request,
                         double time) {
  render::add_riders(list, *request.doc, *request.scene, time);
  render::Camera camera = request.camera;
  if (request.ride >= 0) {
    const Frame frame = rider_frame(*request.doc, *request.scene, request.ride, time);
    render::ride_camera(camera, frame, rider_size(*request.doc, *request.scene, request.ride), request.ride_view);
  }
  return renderer.render(list, camera, request.size, request.display);
}

/// DIR/frame_0000.png ... for the request's seconds at its fps, with a progress line.
int render_sequence(headless::HeadlessRenderer& renderer, render::DrawList& list, const PictureRequest& request) {
  std::filesystem::create_directories(request.sequence);
  const auto count = static_cast<int>(std::max(1.0, std::round(request.seconds * request.fps)));
  for (int k = 0; k < count; ++k) {
    const render::Image image = picture_at(renderer, list, request, k / request.fps);
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.png", k);
    render::save_png_file(request.sequence / name, image);
    std::fprintf(stderr, "\rsweep: frame %d of %d", k + 1, count);
  }
  std::fprintf(stderr, "\n");
  print_render_notes(renderer.renderer().stats());
  std::printf("wrote %d frames to %s (%dx%d, %g fps)\n", count, request.sequence.c_str(), request.size.x,
              request.size.y, request.fps);
  return 0;
}

int render_picture(const PictureRequest& request) {
  std::unique_ptr<headless::HeadlessRenderer> renderer;
  try {
    renderer = std::make_unique<headless::HeadlessRenderer>("osmesa");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: cannot render headless: %s\n", e.what());
    return 1;
  }
  render::DrawList list = render::draw_list(*request.doc, *request.scene, request.image_base);
  if (request.display.grid) {  // --grid: the viewer's ground grid and axes
    const render::Bounds bounds = render::scene_bounds(*request.scene);
    editor::OverlayInput in;
    in.doc = request.doc;
    in.scene = request.scene;
    in.ground = editor::GroundGrid{bounds.min, bounds.max};
    list.overlay = editor::build_overlay(in);
  }
  try {
    if (!request.sequence.empty()) return render_sequence(*renderer, list, request);
    const render::Image image = picture_at(*renderer, list, request, request.time);
    print_render_notes(renderer->renderer().stats());
    render::save_png_file(request.output, image);
  } catch (const std::exception& e) {  // a PNG or folder that cannot be written
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 1;
  }
  std::printf("wrote %s (%dx%d)\n", request.output.c_str(), request.size.x, request.size.y);
  return 0;
}

void set_workers(int threads) {
  set_worker_count(threads);
}

const GuiEntryPoints kEntryPoints{kGuiInterfaceVersion, &viewer::run_viewer, &render_picture, &snapshot::run_snapshots,
                                  &set_workers};

}  // namespace
}  // namespace sweep::app

// The module's only exported symbol (the rest is hidden, see src/app/CMakeLists.txt).
extern "C" __attribute__((visibility("default"))) const sweep::app::GuiEntryPoints* sweep_gui_entry_points() {
  return &sweep::app::kEntryPoints;
}
