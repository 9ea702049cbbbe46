// What the viewer's camera commands do (actions.hpp, View): reset, preset views, framing the
// selection or everything in the part of the window the panels leave free, the profile view.
#include "app/viewer/actions.hpp"

#include <cmath>
#include <vector>

namespace sweep::viewer {
namespace {

/// Frames `bounds` in the part of the window the panels and the status bar leave free,
/// keeping the camera's orientation and projection.
void frame_bounds(ViewerState& s, const render::Bounds& bounds) {
  s.camera.frame(bounds, s.layout.aspect, s.layout.height_share);
}

/// Front, orthographic, framed on the planar curves (all curves if there are none).
void frame_profile_view(ViewerState& s) {
  render::Bounds bounds;
  for (bool planar_only : {true, false}) {
    for (std::size_t i = 0; i < s.doc().objects.size(); ++i) {
      const ObjectKind kind = s.doc().objects[i].kind();
      if (!is_curve(kind) || (planar_only && !is_planar_curve(kind))) continue;
      for (const Frame& f : s.session.scene().objects[i].curve.frames) bounds.add(f.V);
    }
    if (!bounds.empty()) break;
  }
  if (bounds.empty()) bounds = render::scene_bounds(s.session.scene());
  s.camera.set_view(render::ViewPreset::Front);
  s.camera.projection = render::Projection::Orthographic;
  frame_bounds(s, bounds);
}

}  // namespace

void reset_camera(ViewerState& s) {
  if (s.profile_view) {
    frame_profile_view(s);
    return;
  }
  const render::Projection projection = s.camera.projection;
  s.camera.reset(render::scene_bounds(s.session.scene()), s.layout.aspect, s.layout.height_share);
  s.camera.projection = projection;
}

void set_view(ViewerState& s, render::ViewPreset preset) {
  s.camera.set_view(preset);
  frame_bounds(s, render::scene_bounds(s.session.scene()));
}

void frame_all(ViewerState& s) {
  render::Bounds bounds = render::scene_bounds(s.session.scene(), s.views.visibility(s.doc()));
  if (bounds.empty()) bounds = render::scene_bounds(s.session.scene());
  frame_bounds(s, bounds);
}

void frame_selection(ViewerState& s) {
  const int selected = s.selected();
  render::Bounds bounds;
  if (selected >= 0) {
    std::vector<bool> only(s.doc().objects.size(), false);
    only[std::size_t(selected)] = true;
    bounds = render::scene_bounds(s.session.scene(), only);
    // Its handles too: a B-spline's control points lie off the curve.
    if (const auto* points = s.doc().objects[std::size_t(selected)].find<PointsPart>()) {
      for (const glm::dvec3& p : points->points) {
        if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) bounds.add(p);
      }
    }
  }
  if (bounds.empty()) {  // nothing selected, or nothing to see of it (a material)
    frame_all(s);
    return;
  }
  frame_bounds(s, bounds);
}

void set_profile_view(ViewerState& s, bool on) {
  if (on == s.profile_view) return;
  s.profile_view = on;
  if (on) {
    s.camera_before_profile = s.camera;
    frame_profile_view(s);
  } else {
    s.camera = s.camera_before_profile;
  }
}

}  // namespace sweep::viewer
