#include "editor/snapping.hpp"

#include "base/precondition.hpp"
#include "model/edit/edit.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace sweep::editor {
namespace {

/// Window units within which a place on a segment is taken to be the sample at its end, so a
/// pointer on a sample snaps to that sample's position bit for bit.
constexpr double kAtSample = 1e-6;

/// The points a drag of `point` of `object` moves or owns: its seam partners and, for a Bezier
/// joint, the handles beside it and beside its partners (a Hermite point's handle is no target:
/// tangents never are).
std::vector<int> own_points(const Object& object, int point) {
  std::vector<int> own = seam_partners(object, point);
  if (!point_layout(object.kind()).has_joints() || point % 3 != 0) return own;
  const int count = static_cast<int>(points_of(object).size());
  const std::size_t partners = own.size();
  for (std::size_t i = 0; i < partners; ++i) {
    for (const int handle : {own[i] - 1, own[i] + 1}) {
      if (handle >= 0 && handle < count) own.push_back(handle);
    }
  }
  return own;
}

void gather_points(const Object& object, int index, DraggedPoint dragged, SnapTargets& targets) {
  const std::span<const glm::dvec3> points = points_of(object);
  const PointLayout& layout = point_layout(object.kind());
  std::vector<int> left_out;
  if (index == dragged.object) left_out = own_points(object, dragged.point);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const int point = static_cast<int>(i);
    if (!layout.is_position(i)) continue;  // a tangent is not a place to snap to
    if (std::find(left_out.begin(), left_out.end(), point) != left_out.end()) continue;
    targets.points.push_back(points[i]);
    targets.point_refs.push_back({index, point});
  }
}

void gather_samples(const CurveSamples& curve, int index, SnapTargets& targets) {
  if (curve.frames.empty()) return;
  targets.curves.push_back({index, targets.samples.size(), curve.frames.size()});
  for (const Frame& frame : curve.frames) targets.samples.push_back(frame.V);
}

/// Projects the targets for `mapping` unless they already are.
void ensure_projected(const SnapTargets& targets, const ScreenMapping& mapping) {
  SnapTargets::Projection& cache = targets.projection;
  if (cache.valid && cache.view_projection == mapping.view_projection && cache.window_size == mapping.window_size) {
    return;
  }
  cache.points.resize(targets.points.size());
  for (std::size_t i = 0; i < targets.points.size(); ++i) cache.points[i] = project(mapping, targets.points[i]);
  cache.samples.resize(targets.samples.size());
  for (std::size_t i = 0; i < targets.samples.size(); ++i) cache.samples[i] = project(mapping, targets.samples[i]);
  cache.view_projection = mapping.view_projection;
  cache.window_size = mapping.window_size;
  cache.valid = true;
}

std::optional<SnapHit> nearest_point(const SnapTargets& targets, const glm::dvec2& handle, double radius) {
  const std::vector<ScreenPoint>& screen = targets.projection.points;
  std::optional<std::size_t> best;
  double best_distance = radius;
  for (std::size_t i = 0; i < screen.size(); ++i) {
    if (!(screen[i].w > 0.0)) continue;
    const double d = glm::length(screen[i].xy - handle);
    if (d < best_distance || (d == best_distance && !best)) {
      best_distance = d;
      best = i;
    }
  }
  if (!best) return std::nullopt;
  const SnapTargets::PointRef ref = targets.point_refs[*best];
  return SnapHit{targets.points[*best], SnapKind::Point, ref.object, ref.point, screen[*best].xy, best_distance};
}

std::optional<SnapHit> nearest_curve(const SnapTargets& targets, const glm::dvec2& handle, double radius) {
  std::optional<SnapHit> best;
  for (const SnapTargets::CurveRange& curve : targets.curves) {
    const std::span<const ScreenPoint> screen(targets.projection.samples.data() + curve.first, curve.count);
    const double within = best ? best->distance : radius;
    const std::optional<PolylineHit> hit = nearest_on_polyline(screen, handle, within);
    if (!hit || (best && hit->distance >= best->distance)) continue;  // the first curve keeps a tie
    const std::size_t a = curve.first + hit->segment;
    const std::size_t b = curve.count > 1 ? a + 1 : a;
    const double u = hit->fraction;
    // (1 - u) a + u b is a bit for bit at u = 0 and b at u = 1.
    const glm::dvec3 position = (1.0 - u) * targets.samples[a] + u * targets.samples[b];
    best = SnapHit{position, SnapKind::Curve, curve.object, -1, hit->screen, hit->distance};
  }
  return best;
}

std::optional<SnapHit> nearest_axis(const ScreenMapping& mapping, const glm::dvec2& handle, double radius) {
  // The axis point nearest the ray through the handle lands nearest the handle on the window.
  const std::optional<glm::dvec3> on_axis =
      closest_on_line(pointer_ray(mapping, handle), glm::dvec3(0.0), glm::dvec3(0.0, 1.0, 0.0));
  if (!on_axis) return std::nullopt;  // looking along the axis: no line on the window
  const glm::dvec3 position(0.0, on_axis->y, 0.0);
  const std::optional<glm::dvec2> screen = to_screen(mapping, position);
  if (!screen) return std::nullopt;
  const double d = glm::length(*screen - handle);
  if (!(d <= radius)) return std::nullopt;
  return SnapHit{position, SnapKind::Axis, -1, -1, *screen, d};
}

}  // namespace

ScreenPoint project(const ScreenMapping& mapping, const glm::dvec3& world) {
  const std::optional<glm::dvec2> screen = to_screen(mapping, world);
  if (!screen) return {};
  return {*screen, (mapping.view_projection * glm::dvec4(world, 1.0)).w};
}

std::optional<PolylineHit> nearest_on_polyline(std::span<const ScreenPoint> points, const glm::dvec2& pointer,
                                               double radius) {
  std::optional<PolylineHit> best;
  double best_distance = radius;
  if (points.size() == 1 && points[0].w > 0.0) {
    const double d = glm::length(points[0].xy - pointer);
    if (d <= radius) return PolylineHit{0, 0.0, points[0].xy, d};
    return std::nullopt;
  }
  for (std::size_t i = 0; i + 1 < points.size(); ++i) {
    const ScreenPoint& a = points[i];
    const ScreenPoint& b = points[i + 1];
    if (!(a.w > 0.0 && b.w > 0.0)) continue;
    const glm::dvec2 ab = b.xy - a.xy;
    const double length2 = glm::dot(ab, ab);
    double f = length2 > 0.0 ? std::clamp(glm::dot(pointer - a.xy, ab) / length2, 0.0, 1.0) : 0.0;
    const glm::dvec2 place = a.xy + f * ab;
    if (glm::length(place - a.xy) < kAtSample) f = 0.0;
    if (glm::length(b.xy - place) < kAtSample) f = 1.0;
    const glm::dvec2 on = f == 0.0 ? a.xy : f == 1.0 ? b.xy : place;
    const double d = glm::length(on - pointer);
    if (d < best_distance || (d == best_distance && !best)) {
      best_distance = d;
      // The screen fraction f is a world fraction of f wa / ((1 - f) wb + f wa) (clip w's).
      const double world = f == 0.0 || f == 1.0 ? f : f * a.w / ((1.0 - f) * b.w + f * a.w);
      best = PolylineHit{i, world, on, d};
    }
  }
  return best;
}

SnapTargets gather_snap_targets(const Document& doc, const Scene& scene, const std::vector<bool>& visible,
                                DraggedPoint dragged) {
  SWEEP_EXPECTS(scene.objects.size() == doc.objects.size(), "the scene evaluates this document");
  SWEEP_EXPECTS(visible.size() == doc.objects.size(), "one visibility per object");
  SWEEP_EXPECTS(
      dragged.object < 0 || (static_cast<std::size_t>(dragged.object) < doc.objects.size() && dragged.point >= 0 &&
                             static_cast<std::size_t>(dragged.point) <
                                 points_of(doc.objects[static_cast<std::size_t>(dragged.object)]).size()),
      "the dragged point exists");
  SnapTargets targets;
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    if (!visible[i]) continue;
    const Object& object = doc.objects[i];
    const int index = static_cast<int>(i);
    if (has_editable_points(object.kind())) gather_points(object, index, dragged, targets);
    if (is_curve(object.kind()) && index != dragged.object) gather_samples(scene.objects[i].curve, index, targets);
  }
  return targets;
}

std::optional<SnapHit> snap_target(const SnapTargets& targets, const ScreenMapping& mapping, const glm::dvec2& handle,
                                   const SnapOptions& options) {
  SWEEP_EXPECTS(options.radius >= 0.0, "a radius of 0 or more");
  ensure_projected(targets, mapping);
  if (options.points) {
    if (std::optional<SnapHit> point = nearest_point(targets, handle, options.radius)) return point;
  }
  std::optional<SnapHit> curve = options.curves ? nearest_curve(targets, handle, options.radius) : std::nullopt;
  std::optional<SnapHit> axis = options.axis ? nearest_axis(mapping, handle, options.radius) : std::nullopt;
  if (axis && (!curve || axis->distance < curve->distance)) return axis;
  return curve;
}

}  // namespace sweep::editor
