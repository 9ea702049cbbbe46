// What the viewer's camera commands do (actions.hpp, View): reset, preset views, framing the
// selection or everything in the part of the window the panels leave free, the profile view,
// and riding along with a rider.
#include "app/viewer/actions.hpp"

#include "base/precondition.hpp"
#include "model/edit/shown_points.hpp"
#include "model/evaluation/riders.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <string>
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

render::Camera picture_camera(const render::Camera& camera, PixelRect view, glm::ivec2 framebuffer, glm::ivec2 size) {
  SWEEP_EXPECTS(view.width > 0 && view.height > 0 && framebuffer.x > 0 && framebuffer.y > 0 && size.x > 0 && size.y > 0,
                "sizes > 0");
  // The view's centre in the window's normalized device coordinates, and how many times the
  // window is higher than the view: the picture's vertical extent shrinks by that much.
  const glm::dvec2 centre(2.0 * (view.x + 0.5 * view.width) / framebuffer.x - 1.0,
                          1.0 - 2.0 * (view.y + 0.5 * view.height) / framebuffer.y);
  const double k = double(framebuffer.y) / double(view.height);
  const double window_aspect = double(framebuffer.x) / double(framebuffer.y);
  const double picture_aspect = double(size.x) / double(size.y);
  render::Camera out = camera;
  out.vertical_fov = 2.0 * std::atan(std::tan(0.5 * camera.vertical_fov) / k);  // also the orthographic extent
  // x scales by k times the aspects' ratio (the same world width per pixel), y by k.
  out.lens_shift = glm::dvec2(k * window_aspect / picture_aspect * (camera.lens_shift.x - centre.x),
                              k * (camera.lens_shift.y - centre.y));
  return out;
}

void reset_camera(ViewerState& s) {
  stop_riding(s);
  if (s.profile_view) {
    frame_profile_view(s);
    return;
  }
  const render::Projection projection = s.camera.projection;
  s.camera.reset(render::scene_bounds(s.session.scene()), s.layout.aspect, s.layout.height_share);
  s.camera.projection = projection;
}

void set_view(ViewerState& s, render::ViewPreset preset) {
  stop_riding(s);
  s.camera.set_view(preset);
  frame_bounds(s, render::scene_bounds(s.session.scene()));
}

void frame_all(ViewerState& s) {
  stop_riding(s);
  render::Bounds bounds = render::scene_bounds(s.session.scene(), s.views.visibility(s.doc()));
  if (bounds.empty()) bounds = render::scene_bounds(s.session.scene());
  frame_bounds(s, bounds);
}

/// The box of the selected control points, grown to at least a tenth of their object's size
/// around them (a single point has no size of its own); empty when no point is selected.
render::Bounds selected_points_bounds(const ViewerState& s) {
  render::Bounds bounds;
  const int selected = s.selected();
  if (selected < 0 || s.doc().objects[std::size_t(selected)].find<PointsPart>() == nullptr) return bounds;
  // Where the points show: a Hermite tangent at its handle, not the vector it stores.
  const std::vector<glm::dvec3> points = shown_points(s.doc().objects[std::size_t(selected)]);
  render::Bounds all;
  for (const glm::dvec3& p : points) all.add(p);
  for (const int i : s.selection.points()) {
    if (i >= 0 && std::size_t(i) < points.size()) bounds.add(points[std::size_t(i)]);
  }
  if (bounds.empty() || all.empty()) return bounds;
  const glm::dvec3 centre = 0.5 * (bounds.min + bounds.max);
  const glm::dvec3 half = glm::max(0.5 * (bounds.max - bounds.min), glm::dvec3(0.05 * glm::length(all.max - all.min)));
  bounds.add(centre - half);
  bounds.add(centre + half);
  return bounds;
}

void frame_selection(ViewerState& s) {
  stop_riding(s);
  // The selected points when there are any: F frames what is being edited.
  if (const render::Bounds points = selected_points_bounds(s); !points.empty()) {
    frame_bounds(s, points);
    return;
  }
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
  if (on) stop_riding(s);
  s.profile_view = on;
  if (on) {
    s.camera_before_profile = s.camera;
    frame_profile_view(s);
  } else {
    s.camera = s.camera_before_profile;
  }
}

bool riding(const ViewerState& s) {
  return s.ride.rider != editor::kNoObject;
}

void ride_along(ViewerState& s, editor::ObjectId rider) {
  if (rider == editor::kNoObject) {
    stop_riding(s);
    return;
  }
  if (!riding(s)) {
    set_profile_view(s, false);
    s.ride.orbit = s.camera;
  }
  s.ride.rider = rider;
  follow_rider(s);
}

void stop_riding(ViewerState& s, bool keep_view) {
  if (!riding(s)) return;
  if (keep_view) {
    s.camera.projection = s.ride.orbit.projection;
  } else {
    s.camera = s.ride.orbit;
  }
  s.camera.lens_shift = s.layout.lens_shift;
  s.ride.rider = editor::kNoObject;
}

void follow_rider(ViewerState& s) {
  if (!riding(s)) return;
  const int index = s.session.index_of(s.ride.rider);
  if (index < 0 || !is_rider(s.doc().objects[std::size_t(index)].kind())) {
    stop_riding(s);
    return;
  }
  // The model's radius, measured again when its mesh changed.
  const int model = s.doc().objects[std::size_t(index)].as<RiderObject>().model;
  const std::uint64_t revision = model >= 0 ? s.session.scene().objects[std::size_t(model)].revision : 0;
  RideAlong& ride = s.ride;
  if (ride.radius_model != model || ride.radius_revision != revision) {
    ride.size = rider_size(s.doc(), s.session.scene(), index);
    ride.radius_model = model;
    ride.radius_revision = revision;
  }
  if (s.session.scene().objects[std::size_t(index)].track.frames.empty()) return;  // not evaluated yet
  const Frame frame = rider_frame(s.doc(), s.session.scene(), index, s.playback.time());
  render::ride_camera(s.camera, frame, ride.size, ride.view);
  s.camera.projection = render::Projection::Perspective;
  s.camera.lens_shift = s.layout.lens_shift;  // centred in the part the panels leave free
}

void toggle_playback(ViewerState& s) {
  s.playback.toggle();
  char text[64];
  std::snprintf(text, sizeof text, s.playback.playing() ? "playing the riders from %.2f s" : "riders paused at %.2f s",
                s.playback.time());
  s.status = text;
}

}  // namespace sweep::viewer
