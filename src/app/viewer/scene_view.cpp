#include "app/viewer/scene_view.hpp"

#include "model/material.hpp"

#include "app/viewer/curve_actions.hpp"
#include "base/precondition.hpp"
#include "editor/overlay_builder.hpp"
#include "render/draw_list.hpp"

namespace sweep::viewer {
namespace {

editor::OverlayInput overlay_input(ViewerState& s, const std::vector<bool>& visible, const render::Bounds& bounds) {
  editor::OverlayInput in;
  in.doc = &s.doc();
  in.scene = &s.session.scene();
  in.visible = visible;
  in.selected = s.selected();
  in.selected_point = s.selection.point;
  in.selected_points = s.selection.points();
  in.hovered_point = s.selection.hovered_point;
  in.curves_shown = s.display.curves != render::CurveMode::Off;
  if (const editor::CurvatureComb* comb = selected_comb(s)) in.extra = editor::comb_overlay(*comb);
  if (s.profile_view) {
    in.grid = editor::GridView{s.camera.target, s.camera.half_height_at_target(), s.snap ? s.snap_size : 0.0};
  } else if (s.display.grid) {
    in.ground = editor::GroundGrid{bounds.min, bounds.max};
  }
  return in;
}

}  // namespace

const render::Bounds& SceneView::visible_bounds(const Scene& scene, const std::vector<bool>& visible) {
  bool same = bounds_revisions_.size() == scene.objects.size() && bounds_visible_ == visible;
  for (std::size_t i = 0; same && i < scene.objects.size(); ++i) {
    same = bounds_revisions_[i] == scene.objects[i].revision && scene.objects[i].revision != 0;
  }
  if (same) return bounds_;
  bounds_ = render::scene_bounds(scene, visible);
  bounds_visible_ = visible;
  bounds_revisions_.clear();
  for (const EvaluatedObject& object : scene.objects) bounds_revisions_.push_back(object.revision);
  return bounds_;
}

render::DrawList SceneView::scene_list(ViewerState& s, const SceneChoice& choice) {
  render::DrawList list = render::draw_list(s.doc(), s.session.scene(), image_base(s.session.file()));
  list.visible = s.views.visibility(s.doc());
  render::add_riders(list, s.doc(), s.session.scene(), s.playback.time());  // where the timeline is
  const bool ground = choice.grid && !s.profile_view;
  const render::Bounds none;
  // The ground reaches under what is drawn where it is: a carried model is drawn where it rides.
  std::vector<bool> placed = list.visible;
  for (std::size_t i = 0; i < placed.size() && i < list.carried.size(); ++i) placed[i] = placed[i] && !list.carried[i];
  editor::OverlayInput in = overlay_input(s, list.visible, ground ? visible_bounds(s.session.scene(), placed) : none);
  if (!choice.selection) {  // a picture for a report: what is there, not what the pointer is on
    in.selected = -1;
    in.selected_point = -1;
    in.selected_points.clear();
    in.hovered_point = -1;
    in.extra.clear();
  }
  in.curves_shown = choice.curves;
  if (!choice.grid) in.grid.reset();
  list.overlay = editor::build_overlay(in);
  list.highlighted = editor::highlighted_surface(in);
  list.highlight_color = editor::kHighlightColor;
  return list;
}

void SceneView::draw(ViewerState& s, glm::ivec2 framebuffer, bool fast) {
  const SceneChoice shown{s.display.curves != render::CurveMode::Off, s.display.grid, true};
  const render::DrawList list = scene_list(s, shown);
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

render::Image SceneView::picture(ViewerState& s, const render::Camera& camera, glm::ivec2 size,
                                 const render::DisplaySettings& display) {
  SWEEP_EXPECTS(size.x > 0 && size.y > 0, "a picture of at least one pixel");
  const SceneChoice choice{display.curves != render::CurveMode::Off, display.grid, false};
  const render::DrawList list = scene_list(s, choice);
  render::OffscreenTarget target(size, samples_);
  target.bind();
  renderer_.draw(list, camera, render::RenderTarget{size, 1.0f}, display);
  render::Image image = target.resolve_and_read();
  render::bind_window_framebuffer();
  return image;
}

}  // namespace sweep::viewer
