#include "editor/overlay_builder.hpp"

#include "model/edit/edit.hpp"
#include "model/edit/shown_points.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace sweep::editor {
namespace {

bool visible(const OverlayInput& in, std::size_t i) {
  return i >= in.visible.size() || in.visible[i];
}

/// The sweep samples of every visible generalized cylinder where its tube folds over itself.
void add_folds(const OverlayInput& in, std::vector<OverlayBatch>& overlay) {
  OverlayBatch folds;
  folds.color = kFoldColor;
  folds.point_size = 5.0f;
  const Document& doc = *in.doc;
  const Scene& scene = *in.scene;
  for (std::size_t i = 0; i < doc.objects.size() && i < scene.objects.size(); ++i) {
    const Object& object = doc.objects[i];
    if (object.kind() != ObjectKind::GeneralizedCylinder || !visible(in, i)) continue;
    const std::vector<Frame>& sweep = scene.objects[std::size_t(object.as<CylinderSurface>().sweep)].curve.frames;
    for (const FoldRange& range : scene.objects[i].diagnostics.folds) {
      for (int k = std::max(0, range.first_sample); k <= range.last_sample && k < int(sweep.size()); ++k) {
        folds.positions.emplace_back(sweep[std::size_t(k)].V);
      }
    }
  }
  if (!folds.positions.empty()) overlay.push_back(std::move(folds));
}

OverlayBatch lines(const glm::vec3& color) {
  OverlayBatch batch;
  batch.primitive = OverlayBatch::Primitive::Lines;
  batch.color = color;
  batch.on_top = false;
  return batch;
}

/// Lines `step` apart in the plane of the world axes `u` and `v` (0 x, 1 y, 2 z) through
/// `centre`, covering at least `reach` either side of it, from a multiple of `step` (at most 400
/// lines each way).
OverlayBatch grid_lines(const glm::dvec3& centre, int u, int v, double step, double reach) {
  constexpr double kRounding = 1e-9;  // a reach of whole steps stays whole despite rounding
  const double u0 = std::floor((centre[u] - reach) / step + kRounding) * step;
  const double v0 = std::floor((centre[v] - reach) / step + kRounding) * step;
  const int count = std::min(400, int(std::ceil(2.0 * reach / step - kRounding)) + 1);
  const double u1 = u0 + double(count - 1) * step;
  const double v1 = v0 + double(count - 1) * step;
  const auto at = [&](double a, double b) {
    glm::dvec3 p = centre;
    p[u] = a;
    p[v] = b;
    return glm::vec3(p);
  };
  OverlayBatch grid = lines(kGridColor);
  for (int k = 0; k < count; ++k) {
    const double a = u0 + k * step;
    const double b = v0 + k * step;
    grid.positions.push_back(at(a, v0));
    grid.positions.push_back(at(a, v1));
    grid.positions.push_back(at(u0, b));
    grid.positions.push_back(at(u1, b));
  }
  return grid;
}

/// The line through `base` parallel to the world axis `axis` (0 x, 1 y, 2 z), from `from` to
/// `to` along it, in `color`.
OverlayBatch axis_line(const glm::dvec3& base, int axis, double from, double to, const glm::vec3& color) {
  OverlayBatch line = lines(color);
  glm::dvec3 a = base;
  glm::dvec3 b = base;
  a[axis] = from;
  b[axis] = to;
  line.positions = {glm::vec3(a), glm::vec3(b)};
  return line;
}

/// A grid in the xy-plane around the view, with the axes in colour.
void add_grid(const GridView& view, std::vector<OverlayBatch>& overlay) {
  double step = nice_step(view.half_height / 5.0);
  // The snapping grid when it is not too dense to see.
  if (view.snap > 0.0 && view.snap >= view.half_height / 60.0) step = view.snap;
  const double reach = view.half_height * 3.0;  // covers wide windows and the lens shift
  const glm::dvec3 c = view.centre;
  overlay.push_back(grid_lines({c.x, c.y, 0.0}, 0, 1, step, reach));
  overlay.push_back(axis_line(glm::dvec3(0.0), 0, c.x - reach, c.x + reach, kXAxisColor));
  overlay.push_back(axis_line(glm::dvec3(0.0), 1, c.y - reach, c.y + reach, kYAxisColor));
}

/// An empty box (render::Bounds' is +inf to -inf) or one that is not finite.
bool empty_box(const GroundGrid& g) {
  const bool ordered = g.low.x <= g.high.x && g.low.y <= g.high.y && g.low.z <= g.high.z;
  return !ordered || !std::isfinite(glm::length(g.high - g.low)) || !std::isfinite(glm::length(g.low));
}

/// Half the diagonal of the ground's box; 1 when the box is empty or a point.
double ground_radius(const GroundGrid& ground) {
  const double radius = empty_box(ground) ? 0.0 : 0.5 * glm::length(ground.high - ground.low);
  return radius > 0.0 ? radius : 1.0;
}

/// The ground grid under the origin, reaching a quarter past the box's farthest side (and at
/// least its radius), with the x and z axes across it and the y axis from it to a step above the
/// box.
void add_ground(const GroundGrid& ground, std::vector<OverlayBatch>& overlay) {
  const double step = ground_step(ground);
  const double radius = ground_radius(ground);
  const bool box = !empty_box(ground);
  double far = radius;
  if (box) {
    for (double side : {ground.low.x, ground.high.x, ground.low.z, ground.high.z}) far = std::max(far, std::abs(side));
  }
  const double reach = std::ceil(1.25 * far / step) * step;
  const glm::dvec3 foot(0.0, ground_height(ground), 0.0);
  overlay.push_back(grid_lines(foot, 0, 2, step, reach));
  overlay.push_back(axis_line(foot, 0, -reach, reach, kXAxisColor));
  overlay.push_back(axis_line(foot, 2, -reach, reach, kZAxisColor));
  const double top = box ? std::max(foot.y, ground.high.y) + step : step;
  overlay.push_back(axis_line(foot, 1, foot.y, top, kYAxisColor));
}

/// The selected curve's samples as one highlighted strip.
void add_highlight(const CurveSamples& curve, std::vector<OverlayBatch>& overlay) {
  OverlayBatch strip;
  strip.primitive = OverlayBatch::Primitive::LineStrip;
  strip.color = kHighlightColor;
  strip.positions.reserve(curve.frames.size());
  for (const Frame& f : curve.frames) strip.positions.emplace_back(f.V);
  overlay.push_back(std::move(strip));
}

/// The control polygon and its handles: plain, hovered, and the selected point with its seam partners.
void add_handles(const OverlayInput& in, const Object& object, std::vector<OverlayBatch>& overlay) {
  OverlayBatch polygon;
  polygon.primitive = OverlayBatch::Primitive::LineStrip;
  polygon.color = kHandleColor * 0.7f;
  OverlayBatch handles;
  handles.color = kHandleColor;
  handles.point_size = kHandleSize;
  OverlayBatch hovered = handles;
  hovered.color = kHandleHoveredColor;
  hovered.point_size = kHandleBigSize;
  // A curve with handles (Bezier, Hermite) shows its joints as larger squares, its handles as
  // smaller discs: told apart by shape and size, not only colour.
  const PointLayout& layout = point_layout(object.kind());
  const bool has_handles = std::any_of(layout.entries.begin(), layout.entries.begin() + layout.stride,
                                       [](EntryRole role) { return role != EntryRole::Position; });
  OverlayBatch joints = handles;
  joints.round = false;
  joints.point_size = kJointSize;
  if (has_handles) handles.point_size = kHandleSmallSize;
  OverlayBatch chosen = hovered;
  chosen.color = kHandleSelectedColor;
  std::vector<int> partners;
  const std::vector<glm::dvec3> shown = shown_points(object);
  const int count = int(shown.size());
  std::vector<int> chosen_points = in.selected_points;
  chosen_points.push_back(in.selected_point);
  for (int point : chosen_points) {
    if (point < 0 || point >= count) continue;
    const std::vector<int> seam = seam_partners(object, point);
    partners.insert(partners.end(), seam.begin(), seam.end());
  }
  for (const glm::dvec3& corner : control_polygon(object)) polygon.positions.emplace_back(corner);
  for (std::size_t i = 0; i < shown.size(); ++i) {
    const glm::vec3 p(shown[i]);
    if (std::find(partners.begin(), partners.end(), int(i)) != partners.end()) {
      chosen.positions.push_back(p);
    } else if (int(i) == in.hovered_point) {
      hovered.positions.push_back(p);
    } else if (has_handles && layout.entry(i) == EntryRole::Position) {
      joints.positions.push_back(p);
    } else {
      handles.positions.push_back(p);
    }
  }
  // A patch's or cage's net is not one polygon (PolygonStyle::None): the renderer draws it.
  for (OverlayBatch* batch : {&polygon, &joints, &handles, &hovered, &chosen}) {
    if (batch != &joints || !batch->positions.empty()) overlay.push_back(std::move(*batch));
  }
}

}  // namespace

double ground_height(const GroundGrid& ground) {
  return empty_box(ground) ? 0.0 : std::min(0.0, ground.low.y);
}

double ground_step(const GroundGrid& ground) {
  return nice_step(ground_radius(ground) / 5.0);
}

int highlighted_surface(const OverlayInput& in) {
  const Document& doc = *in.doc;
  if (in.selected < 0 || in.selected >= int(doc.objects.size()) || !visible(in, std::size_t(in.selected))) return -1;
  return is_surface(doc.objects[std::size_t(in.selected)].kind()) ? in.selected : -1;
}

std::vector<OverlayBatch> build_overlay(const OverlayInput& in) {
  std::vector<OverlayBatch> overlay;
  if (in.ground) add_ground(*in.ground, overlay);
  if (in.grid) add_grid(*in.grid, overlay);
  if (in.curves_shown) add_folds(in, overlay);
  const Document& doc = *in.doc;
  if (in.selected < 0 || in.selected >= int(doc.objects.size()) || !visible(in, std::size_t(in.selected))) {
    return overlay;
  }
  const Object& object = doc.objects[std::size_t(in.selected)];
  if (is_curve(object.kind())) add_highlight(in.scene->objects[std::size_t(in.selected)].curve, overlay);
  overlay.insert(overlay.end(), in.extra.begin(), in.extra.end());
  if (has_editable_points(object.kind())) add_handles(in, object, overlay);
  return overlay;
}

}  // namespace sweep::editor
