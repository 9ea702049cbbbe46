// sweep_gui (libsweep_gui.so): the drawing half of `sweep view` and `sweep render`, opened by
// the `sweep` executable only when a command draws (gui_loader.cpp). Options are parsed and files
// checked in the executable, so help and error messages do not depend on this module.
#include "app/gui_module.hpp"

#include "editor/overlay_builder.hpp"
#include "headless/headless_renderer.hpp"
#include "render/draw_list.hpp"
#include "render/png_file.hpp"

#include <cstdio>
#include <exception>
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
  const render::Image image = renderer->render(list, request.camera, request.size, request.display);
  print_render_notes(renderer->renderer().stats());
  render::save_png_file(request.output, image);
  std::printf("wrote %s (%dx%d)\n", request.output.c_str(), request.size.x, request.size.y);
  return 0;
}

const GuiEntryPoints kEntryPoints{kGuiInterfaceVersion, &viewer::run_viewer, &render_picture};

}  // namespace
}  // namespace sweep::app

// The module's only exported symbol (the rest is hidden, see src/app/CMakeLists.txt).
extern "C" __attribute__((visibility("default"))) const sweep::app::GuiEntryPoints* sweep_gui_entry_points() {
  return &sweep::app::kEntryPoints;
}
