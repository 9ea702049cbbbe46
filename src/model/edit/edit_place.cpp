// Where the Create panel puts what it makes: a new curve sized to the scene and beside it, and a
// new tube's profile small enough for its sweep's bends.
#include "base/nice_step.hpp"
#include "base/number_text.hpp"
#include "model/edit/edit.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <variant>
#include <vector>

namespace sweep {
namespace {

/// The box of a curve's samples, which follow its shape (a Hermite curve's tangents and a
/// B-spline's control points lie off it). False without samples.
bool sampled_box(const Object& curve, glm::dvec3& lo, glm::dvec3& hi) {
  const CurveSamples samples = evaluate_curve(curve);
  if (samples.frames.empty()) return false;
  lo = hi = samples.frames.front().V;
  for (const Frame& f : samples.frames) {
    lo = glm::min(lo, f.V);
    hi = glm::max(hi, f.V);
  }
  return true;
}

double largest_side(const glm::dvec3& lo, const glm::dvec3& hi) {
  const glm::dvec3 side = hi - lo;
  return std::max({side.x, side.y, side.z});
}

/// Moves a 3D curve by `offset`: its positions (not a Hermite curve's tangents), or its place.
void move_curve(Object& curve, const glm::dvec3& offset) {
  if (auto* place = curve.find<PlacePart>()) place->at += offset;
  auto* points = curve.find<PointsPart>();
  if (points == nullptr) return;
  const PointLayout& layout = point_layout(curve.kind());
  for (std::size_t i = 0; i < points->points.size(); ++i) {
    if (layout.is_position(i)) points->points[i] += offset;
  }
}

/// The nearest grid line at or above `value`.
double grid_up(double value, double step) {
  return std::ceil(value / step) * step;
}
double grid_near(double value, double step) {
  return std::round(value / step) * step;
}

}  // namespace

void scale_curve(Object& curve, double factor) {
  std::visit(
      [factor](auto& data) {
        using Kind = std::decay_t<decltype(data)>;
        if constexpr (std::is_base_of_v<PointsPart, Kind>) {
          for (glm::dvec3& p : data.points) p *= factor;
        }
        if constexpr (std::is_base_of_v<RadiusPart, Kind>) data.radius *= factor;
        if constexpr (std::is_base_of_v<PlacePart, Kind>) data.at *= factor;
        if constexpr (std::is_same_v<HelixCurve, Kind>) data.pitch *= factor;
        if constexpr (std::is_same_v<TorusKnotCurve, Kind>) data.major_radius *= factor;
      },
      curve.data);
}

std::string place_new_curve(Object& curve, const SceneBox& scene) {
  const double scene_size = largest_side(scene.lo, scene.hi);
  glm::dvec3 lo(0.0), hi(0.0);
  // Scenes from a micrometre to a million kilometres: beyond, a scaled radius or a place beside
  // could leave the ranges the reader accepts (1e-12 .. 1e12), and the template is kept as it is.
  if (!(scene_size >= 1e-6 && scene_size <= 1e9) || !sampled_box(curve, lo, hi)) return {};
  const double size = largest_side(lo, hi);
  const double factor = size > 0.0 ? nice_step(0.5 * scene_size / size) : 1.0;
  std::string how;
  if (factor != 1.0) {
    scale_curve(curve, factor);
    lo *= factor;
    hi *= factor;
    how = "scaled by " + number_text(factor);
  }
  if (!is_planar_curve(curve.kind())) {
    const double step = scene.step > 0.0 ? scene.step : 1.0;
    const glm::dvec3 offset(grid_up(scene.hi.x + 0.25 * scene_size - lo.x, step), scene.ground - lo.y,
                            grid_near(0.5 * (scene.lo.z + scene.hi.z - lo.z - hi.z), step));
    move_curve(curve, offset);
    how += std::string(how.empty() ? "" : ", ") + "beside the scene";
  }
  return how.empty() ? how : " (" + how + ")";
}

int add_curve(Document& doc, std::string_view label, const std::string& name, const SceneBox& scene, std::string& how) {
  const int index = add_curve(doc, label, name);
  how = place_new_curve(doc.objects[std::size_t(index)], scene);
  return index;
}

double profile_fit_factor(const Document& doc, int profile, int sweep) {
  const CurveSamples path = evaluate_curve(doc.objects[std::size_t(sweep)]);
  double bend = 0.0;  // the largest curvature
  for (const double k : path.curvature) bend = std::max(bend, std::isfinite(k) ? k : 0.0);
  if (!(bend > 0.0)) return 1.0;  // straight: any profile
  double reach = 0.0;
  for (const Frame& f : evaluate_curve(doc.objects[std::size_t(profile)]).frames) {
    reach = std::max(reach, glm::length(glm::dvec2(f.V)));
  }
  const double limit = 0.5 / bend;
  return reach > limit ? nice_at_most(limit / reach) : 1.0;
}

bool is_referenced(const Document& doc, int index) {
  return std::any_of(doc.objects.begin(), doc.objects.end(), [index](const Object& o) {
    const std::vector<int> used = references(o);
    return std::find(used.begin(), used.end(), index) != used.end();
  });
}

}  // namespace sweep
