#include "snapshot/object_ids.hpp"

#include "base/precondition.hpp"

#include <glm/mat4x4.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sweep::snapshot {
namespace {

/// A point on screen: pixels (x right, y down) and depth (normalized device z).
struct ScreenPoint {
  glm::dvec2 at{0.0};
  double depth = 0.0;
  bool valid = false;  // in front of the eye
};

/// The id map with its depth buffer, and the transform to the screen.
class Raster {
 public:
  Raster(glm::ivec2 size) : size_(size) {
    map_.width = size.x;
    map_.height = size.y;
    const std::size_t count = std::size_t(size.x) * std::size_t(size.y);
    map_.ids.assign(count, 0);
    depth_.assign(count, std::numeric_limits<double>::infinity());
  }

  ScreenPoint project(const glm::dmat4& transform, const glm::dvec3& point) const {
    const glm::dvec4 clip = transform * glm::dvec4(point, 1.0);
    ScreenPoint out;
    if (!(clip.w > 1e-12) || !std::isfinite(clip.x) || !std::isfinite(clip.y)) return out;
    const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
    out.at = {(ndc.x * 0.5 + 0.5) * size_.x, (0.5 - ndc.y * 0.5) * size_.y};
    out.depth = ndc.z;
    out.valid = std::abs(ndc.z) <= 1.0 + 1e-9;
    return out;
  }

  void triangle(const ScreenPoint& a, const ScreenPoint& b, const ScreenPoint& c, std::uint16_t id) {
    if (!a.valid || !b.valid || !c.valid) return;
    const double area = edge(a.at, b.at, c.at);
    if (area == 0.0 || !std::isfinite(area)) return;
    const int x0 = std::max(0, int(std::floor(std::min({a.at.x, b.at.x, c.at.x}))));
    const int x1 = std::min(size_.x - 1, int(std::ceil(std::max({a.at.x, b.at.x, c.at.x}))));
    const int y0 = std::max(0, int(std::floor(std::min({a.at.y, b.at.y, c.at.y}))));
    const int y1 = std::min(size_.y - 1, int(std::ceil(std::max({a.at.y, b.at.y, c.at.y}))));
    for (int y = y0; y <= y1; ++y) {
      for (int x = x0; x <= x1; ++x) {
        const glm::dvec2 p(x + 0.5, y + 0.5);
        const double wa = edge(b.at, c.at, p) / area;
        const double wb = edge(c.at, a.at, p) / area;
        const double wc = 1.0 - wa - wb;
        if (wa < 0.0 || wb < 0.0 || wc < 0.0) continue;  // both windings: surfaces are two-sided
        plot(x, y, wa * a.depth + wb * b.depth + wc * c.depth, id);
      }
    }
  }

  /// A one-pixel line, drawn a little in front so curves lying on surfaces win (as in the picture).
  void line(const ScreenPoint& a, const ScreenPoint& b, std::uint16_t id) {
    if (!a.valid || !b.valid) return;
    const glm::dvec2 d = b.at - a.at;
    const double length = std::max(std::abs(d.x), std::abs(d.y));
    if (!(length < 4.0 * double(size_.x + size_.y))) return;  // off-screen far away, or not finite
    const int steps = std::max(1, int(std::ceil(length)));
    for (int k = 0; k <= steps; ++k) {
      const double t = double(k) / steps;
      const glm::dvec2 p = a.at + t * d;
      plot(int(std::floor(p.x)), int(std::floor(p.y)), a.depth + t * (b.depth - a.depth) - kLineBias, id);
    }
  }

  /// A control point: a square `side` pixels wide.
  void point(const ScreenPoint& a, int side, std::uint16_t id) {
    if (!a.valid) return;
    const int x0 = int(std::floor(a.at.x - 0.5 * side));
    const int y0 = int(std::floor(a.at.y - 0.5 * side));
    for (int y = y0; y < y0 + side; ++y) {
      for (int x = x0; x < x0 + side; ++x) plot(x, y, a.depth - kLineBias, id);
    }
  }

  IdMap take() { return std::move(map_); }

 private:
  static constexpr double kLineBias = 1e-4;

  static double edge(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
  }

  void plot(int x, int y, double depth, std::uint16_t id) {
    if (x < 0 || y < 0 || x >= size_.x || y >= size_.y) return;
    const std::size_t i = std::size_t(y) * std::size_t(size_.x) + std::size_t(x);
    if (depth >= depth_[i]) return;
    depth_[i] = depth;
    map_.ids[i] = id;
  }

  glm::ivec2 size_;
  IdMap map_;
  std::vector<double> depth_;
};

void draw_mesh(Raster& raster, const glm::dmat4& transform, const Mesh& mesh, std::uint16_t id) {
  std::vector<ScreenPoint> points(mesh.positions.size());
  for (std::size_t i = 0; i < points.size(); ++i) points[i] = raster.project(transform, glm::dvec3(mesh.positions[i]));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    if (a >= points.size() || b >= points.size() || c >= points.size()) continue;
    raster.triangle(points[a], points[b], points[c], id);
  }
}

void draw_curve(Raster& raster, const glm::dmat4& transform, const CurveSamples& curve, std::uint16_t id) {
  ScreenPoint previous;
  for (std::size_t i = 0; i < curve.frames.size(); ++i) {
    const ScreenPoint p = raster.project(transform, curve.frames[i].V);
    if (i > 0) raster.line(previous, p, id);
    previous = p;
  }
}

void draw_polygon(Raster& raster, const glm::dmat4& transform, std::span<const glm::dvec3> points, std::uint16_t id) {
  ScreenPoint previous;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const ScreenPoint p = raster.project(transform, points[i]);
    if (i > 0) raster.line(previous, p, id);
    raster.point(p, 6, id);
    previous = p;
  }
}

}  // namespace

std::size_t IdMap::coverage(int index) const {
  const auto id = static_cast<std::uint16_t>(index + 1);
  return static_cast<std::size_t>(std::count(ids.begin(), ids.end(), id));
}

IdMap object_ids(const render::DrawList& list, const render::Camera& camera, glm::ivec2 size,
                 const IdPassContent& content) {
  SWEEP_EXPECTS(list.scene != nullptr, "object_ids: list.scene is set");
  SWEEP_EXPECTS(size.x >= 1 && size.y >= 1 && size.x <= 16384 && size.y <= 16384, "object_ids: size in [1, 16384]");
  SWEEP_EXPECTS(list.scene->objects.size() < 65535, "object_ids: at most 65,534 objects");
  Raster raster(size);
  const double aspect = double(size.x) / double(size.y);
  const glm::dmat4 transform = camera.projection_matrix(aspect) * camera.view_matrix();
  const std::vector<EvaluatedObject>& objects = list.scene->objects;
  for (std::size_t i = 0; i < objects.size() && i < 65534; ++i) {
    const auto id = static_cast<std::uint16_t>(i + 1);
    const EvaluatedObject& object = objects[i];
    if (!list.is_visible(i)) continue;
    if (content.surfaces && list.is_shaded(i)) draw_mesh(raster, transform, object.mesh, id);
    if (list.curve_rides(i)) continue;  // a rider's model's curves are not drawn
    if (content.curves) draw_curve(raster, transform, object.curve, id);
    if (content.control_points && i < list.control_polygons.size()) {
      draw_polygon(raster, transform, list.control_polygons[i], id);
    }
  }
  for (const render::RiderPlacement& rider : list.riders) {
    if (!content.surfaces || rider.model < 0 || std::size_t(rider.model) >= objects.size()) continue;
    draw_mesh(raster, transform * glm::dmat4(rider.matrix), objects[std::size_t(rider.model)].mesh,
              static_cast<std::uint16_t>(rider.model + 1));
  }
  return raster.take();
}

}  // namespace sweep::snapshot
