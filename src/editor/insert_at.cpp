#include "editor/insert_at.hpp"

#include "base/precondition.hpp"
#include "editor/snapping.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace sweep::editor {
namespace {

struct NearestPlace {
  std::size_t segment = 0;
  double parameter = 0.0;
};

std::optional<NearestPlace> nearest_place(const CurveSamples& samples, const ScreenMapping& mapping,
                                          const glm::dvec2& pointer, double radius) {
  SWEEP_EXPECTS(samples.parameters.size() == samples.frames.size(), "one parameter per sample");
  SWEEP_EXPECTS(radius >= 0.0, "a radius of 0 or more");
  std::vector<ScreenPoint> screen(samples.frames.size());
  for (std::size_t i = 0; i < screen.size(); ++i) screen[i] = project(mapping, samples.frames[i].V);
  const std::optional<PolylineHit> hit = nearest_on_polyline(screen, pointer, radius);
  if (!hit) return std::nullopt;
  const std::vector<double>& u = samples.parameters;
  const std::size_t b = std::min(hit->segment + 1, u.size() - 1);
  return NearestPlace{hit->segment, (1.0 - hit->fraction) * u[hit->segment] + hit->fraction * u[b]};
}

/// Window distance from `pointer` to the curve point at `parameter` (infinity off the window).
double screen_distance(const Object& curve, const ScreenMapping& mapping, const glm::dvec2& pointer, double parameter) {
  const std::optional<glm::dvec2> screen = to_screen(mapping, curve_position(curve, parameter));
  return screen ? glm::length(*screen - pointer) : std::numeric_limits<double>::infinity();
}

/// The parameter in [lo, hi] whose curve point lands nearest `pointer`, by golden-section search
/// (Kiefer, 1953), which assumes one minimum in the interval: true of a short sample interval.
double golden_section(const Object& curve, const ScreenMapping& mapping, const glm::dvec2& pointer, double lo,
                      double hi) {
  const double ratio = (std::sqrt(5.0) - 1.0) / 2.0;
  double a = hi - ratio * (hi - lo);
  double b = lo + ratio * (hi - lo);
  double fa = screen_distance(curve, mapping, pointer, a);
  double fb = screen_distance(curve, mapping, pointer, b);
  for (int i = 0; i < 48; ++i) {  // 0.618^48 < 1e-10 of the interval
    if (fa <= fb) {
      hi = b;
      b = a;
      fb = fa;
      a = hi - ratio * (hi - lo);
      fa = screen_distance(curve, mapping, pointer, a);
    } else {
      lo = a;
      a = b;
      fa = fb;
      b = lo + ratio * (hi - lo);
      fb = screen_distance(curve, mapping, pointer, b);
    }
  }
  return fa <= fb ? a : b;
}

}  // namespace

std::optional<double> parameter_at(const CurveSamples& samples, const ScreenMapping& mapping, glm::dvec2 pointer,
                                   double radius) {
  const std::optional<NearestPlace> place = nearest_place(samples, mapping, pointer, radius);
  if (!place) return std::nullopt;
  return place->parameter;
}

std::optional<double> parameter_at(const Object& curve, const CurveSamples& samples, const ScreenMapping& mapping,
                                   glm::dvec2 pointer, double radius) {
  const std::optional<NearestPlace> place = nearest_place(samples, mapping, pointer, radius);
  if (!place) return std::nullopt;
  const std::vector<double>& u = samples.parameters;
  double best = place->parameter;
  double best_distance = screen_distance(curve, mapping, pointer, best);
  // The nearest place may lie in the interval before or after the polyline's nearest segment.
  const std::size_t first = place->segment > 0 ? place->segment - 1 : 0;
  const std::size_t last = std::min(place->segment + 2, u.size() - 1);
  for (std::size_t i = first; i < last; ++i) {
    const double candidate = golden_section(curve, mapping, pointer, u[i], u[i + 1]);
    const double d = screen_distance(curve, mapping, pointer, candidate);
    if (d < best_distance) {
      best_distance = d;
      best = candidate;
    }
  }
  return best;
}

}  // namespace sweep::editor
