#include "app/viewer/scene_view.hpp"

#include "model/material.hpp"

#include "editor/overlay_builder.hpp"
#include "render/draw_list.hpp"

namespace sweep::viewer {
namespace {

editor::OverlayInput overlay_input(const ViewerState& s, const std::vector<bool>& visible) {
  editor::OverlayInput in;
  in.doc = &s.doc();
  in.scene = &s.session.scene();
  in.visible = visible;
  in.selected = s.selected();
  in.selected_point = s.selection.point;
  in.hovered_point = s.selection.hovered_point;
  in.curves_shown = s.display.curves != render::CurveMode::Off;
  if (s.profile_view) {
    in.grid = editor::GridView{s.camera.target, s.camera.half_height_at_target(), s.snap ? s.snap_size : 0.0};
  }
  return in;
}

}  // namespace

void SceneView::draw(ViewerState& s, glm::ivec2 framebuffer, bool fast) {
  render::DrawList list = render::draw_list(s.doc(), s.session.scene(), image_base(s.session.file()));
  list.visible = s.views.visibility(s.doc());
  list.overlay = editor::build_overlay(overlay_input(s, list.visible));
  const render::RenderTarget target{framebuffer, s.layout.pixel_ratio};
  const bool multisample = samples_ > 1 && !fast;
  if (multisample) {
    if (!target_ || target_->size() != framebuffer) {
      target_.reset();
      target_ = std::make_unique<render::OffscreenTarget>(framebuffer, samples_);
    }
    target_->bind();
  } else {
    render::bind_window_framebuffer();
  }
  renderer_.draw(list, s.camera, target, s.display);
  if (multisample) target_->resolve_to_window();
  s.stats.render = renderer_.stats();
  // Images that could not be loaded: said once in the error panel, the surface drawn in its colour.
  for (const std::string& warning : s.stats.render.warnings) {
    const std::string line = "warning: " + warning + "; drawn in its colour";
    if (s.error.find(line) == std::string::npos) s.error += (s.error.empty() ? "" : "\n") + line;
  }
}

}  // namespace sweep::viewer
