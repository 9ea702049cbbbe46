#include "app/viewer/view_png.hpp"

#include "render/png_file.hpp"

#include <exception>
#include <stdexcept>
#include <string>

namespace sweep::viewer {

namespace {

/// The display settings of the picture: the view's, with the control points, curves and grid as
/// asked.
render::DisplaySettings picture_display(const ViewerState& s, const ScreenshotRequest& request) {
  render::DisplaySettings display = s.display;
  display.control_points = request.control_points;
  if (!request.curves) display.curves = render::CurveMode::Off;
  display.grid = request.grid;
  return display;
}

}  // namespace

void write_view_png(ViewerState& s, SceneView& scene, glm::ivec2 framebuffer) {
  const ScreenshotRequest request = s.pending_screenshot;
  s.pending_screenshot = {};
  try {
    const PixelRect view = view_rect(s.layout, framebuffer);
    if (view.width <= 0 || view.height <= 0) throw std::runtime_error("the panels cover the whole view");
    const glm::ivec2 size = request.size.x > 0 ? request.size : glm::ivec2(view.width, view.height);
    const render::Camera camera = picture_camera(s.camera, view, framebuffer, size);
    const render::Image image = scene.picture(s, camera, size, picture_display(s, request));
    render::save_png_file(request.path, image);
    s.status = "saved PNG of the view " + request.path.string() + " (" + std::to_string(image.width) + " x " +
               std::to_string(image.height) + " pixels)";
    s.error.clear();
  } catch (const std::exception& e) {  // save_png_file names the path and the cause
    s.error = std::string("PNG of the view failed: ") + e.what();
  }
}

}  // namespace sweep::viewer
