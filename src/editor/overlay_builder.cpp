#include "editor/overlay_builder.hpp"

#include "model/edit.hpp"

#include <algorithm>
#include <cmath>

namespace sweep::editor {
namespace {

const glm::vec3 kGridColor{0.24f, 0.26f, 0.30f};
const glm::vec3 kGridXAxisColor{0.55f, 0.25f, 0.25f};  // the line y = 0
const glm::vec3 kGridYAxisColor{0.25f, 0.50f, 0.25f};  // the line x = 0

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

/// A grid in the xy-plane around the view, with the axes in colour.
void add_grid(const GridView& view, std::vector<OverlayBatch>& overlay) {
  double step = nice_step(view.half_height / 5.0);
  // The snapping grid when it is not too dense to see.
  if (view.snap > 0.0 && view.snap >= view.half_height / 60.0) step = view.snap;
  const double reach = view.half_height * 3.0;  // covers wide windows and the lens shift
  const glm::dvec3 c = view.centre;
  const double x0 = std::floor((c.x - reach) / step) * step;
  const double y0 = std::floor((c.y - reach) / step) * step;
  const int count = std::min(400, int(std::ceil(2.0 * reach / step)) + 1);
  const double x1 = x0 + double(count - 1) * step;
  const double y1 = y0 + double(count - 1) * step;
  OverlayBatch grid = lines(kGridColor);
  for (int k = 0; k < count; ++k) {
    const double x = x0 + k * step;
    const double y = y0 + k * step;
    grid.positions.emplace_back(float(x), float(y0), 0.0f);
    grid.positions.emplace_back(float(x), float(y1), 0.0f);
    grid.positions.emplace_back(float(x0), float(y), 0.0f);
    grid.positions.emplace_back(float(x1), float(y), 0.0f);
  }
  overlay.push_back(std::move(grid));
  OverlayBatch x_axis = lines(kGridXAxisColor);
  x_axis.positions = {glm::vec3(float(c.x - reach), 0.0f, 0.0f), glm::vec3(float(c.x + reach), 0.0f, 0.0f)};
  OverlayBatch y_axis = lines(kGridYAxisColor);
  y_axis.positions = {glm::vec3(0.0f, float(c.y - reach), 0.0f), glm::vec3(0.0f, float(c.y + reach), 0.0f)};
  overlay.push_back(std::move(x_axis));
  overlay.push_back(std::move(y_axis));
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
  OverlayBatch chosen = hovered;
  chosen.color = kHandleSelectedColor;
  std::vector<int> partners;
  if (in.selected_point >= 0 && in.selected_point < int(object.as<PointsPart>().points.size())) {
    partners = seam_partners(object, in.selected_point);
  }
  for (std::size_t i = 0; i < object.as<PointsPart>().points.size(); ++i) {
    const glm::vec3 p(object.as<PointsPart>().points[i]);
    polygon.positions.push_back(p);
    if (std::find(partners.begin(), partners.end(), int(i)) != partners.end()) {
      chosen.positions.push_back(p);
    } else if (int(i) == in.hovered_point) {
      hovered.positions.push_back(p);
    } else {
      handles.positions.push_back(p);
    }
  }
  // A patch's or cage's net is not one polygon: the renderer draws it (EvaluatedObject::net).
  if (has_control_net(object.kind())) polygon.positions.clear();
  for (OverlayBatch* batch : {&polygon, &handles, &hovered, &chosen}) overlay.push_back(std::move(*batch));
}

}  // namespace

double nice_step(double rough) {
  if (!(rough > 0.0) || !std::isfinite(rough)) return 1.0;
  const double power = std::pow(10.0, std::floor(std::log10(rough)));
  const double m = rough / power;
  return (m < 1.5 ? 1.0 : m < 3.5 ? 2.0 : m < 7.5 ? 5.0 : 10.0) * power;
}

std::vector<OverlayBatch> build_overlay(const OverlayInput& in) {
  std::vector<OverlayBatch> overlay;
  if (in.grid) add_grid(*in.grid, overlay);
  if (in.curves_shown) add_folds(in, overlay);
  const Document& doc = *in.doc;
  if (in.selected < 0 || in.selected >= int(doc.objects.size()) || !visible(in, std::size_t(in.selected))) {
    return overlay;
  }
  const Object& object = doc.objects[std::size_t(in.selected)];
  if (is_curve(object.kind())) add_highlight(in.scene->objects[std::size_t(in.selected)].curve, overlay);
  if (has_editable_points(object.kind())) add_handles(in, object, overlay);
  return overlay;
}

}  // namespace sweep::editor
