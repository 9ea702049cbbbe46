#include "geometry/surfaces/sweep_controls.hpp"

#include "base/number_text.hpp"
#include "base/precondition.hpp"
#include "geometry/surfaces/surface.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace sweep {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

/// How far x may go back before it counts: evaluation rounds a vertical run of a B-spline to
/// noise around its x.
double x_noise(const CurveSamples& graph) {
  double largest = 0.0;
  for (const Frame& f : graph.frames) largest = std::max(largest, std::abs(f.V.x));
  return 1e-9 * largest;
}

const char* role_name(GraphRole role) {
  return role == GraphRole::Scale ? "scale curve" : "twist curve";
}

/// A sample's coordinate in a message: 6 significant digits, as a user reads them.
std::string coordinate_text(double value) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", value);
  return buf;
}

std::string sample_text(std::size_t index, std::size_t count) {
  return "sample " + std::to_string(index + 1) + " of " + std::to_string(count);
}

}  // namespace

GraphValue graph_at(const CurveSamples& graph, double fraction) {
  SWEEP_EXPECTS(graph.frames.size() >= 2, "at least two samples");
  const std::vector<Frame>& f = graph.frames;
  const double x0 = f.front().V.x;
  const double span = f.back().V.x - x0;
  if (!(span > 0.0) || f.size() < 2) return {f.front().V.y, 0.0};
  const double x = x0 + std::clamp(fraction, 0.0, 1.0) * span;
  // The last sample whose x is <= x (binary search; a graph whose x goes back reads the part
  // the search lands in, which check_graph reports).
  std::size_t lo = 0, hi = f.size() - 1;
  while (hi - lo > 1) {
    const std::size_t mid = lo + (hi - lo) / 2;
    (f[mid].V.x <= x ? lo : hi) = mid;
  }
  const glm::dvec3& a = f[lo].V;
  const glm::dvec3& b = f[hi].V;
  const double dx = b.x - a.x;
  if (!(dx > 0.0)) return {x >= b.x ? b.y : a.y, 0.0};
  const double t = std::clamp((x - a.x) / dx, 0.0, 1.0);
  return {a.y + t * (b.y - a.y), (b.y - a.y) / dx * span};
}

std::optional<CurveProblem> check_graph(const CurveSamples& graph, GraphRole role) {
  const std::vector<Frame>& f = graph.frames;
  const std::string what = role_name(role);
  const double noise = x_noise(graph);
  for (std::size_t i = 1; i < f.size(); ++i) {
    if (f[i].V.x < f[i - 1].V.x - noise) {
      return CurveProblem{CurveProblem::At::Profile, "expected a " + what + " whose x never decreases",
                          sample_text(i, f.size()) + " goes back from x = " + coordinate_text(f[i - 1].V.x) + " to " +
                              coordinate_text(f[i].V.x)};
    }
  }
  if (!(f.back().V.x - f.front().V.x > noise)) {
    return CurveProblem{CurveProblem::At::Profile,
                        "expected a " + what + " whose x grows from its first to its last sample",
                        "both are at x = " + coordinate_text(f.front().V.x)};
  }
  if (role == GraphRole::Scale) {
    for (std::size_t i = 0; i < f.size(); ++i) {
      if (!(f[i].V.y > 0.0)) {
        return CurveProblem{CurveProblem::At::Profile, "expected a scale curve with y > 0",
                            sample_text(i, f.size()) + " has y = " + coordinate_text(f[i].V.y)};
      }
    }
  }
  return std::nullopt;
}

glm::dvec3 place_at_station(const Frame& frame, const Station& station, double x, double y) {
  Frame turned = frame;
  rotate_about_tangent(turned, station.twist);
  return turned.V + (station.scale * x) * turned.N + (station.scale * y) * turned.B;
}

double total_twist_degrees(const SweepControls& controls) {
  if (!controls.twist_curve) return controls.twist_degrees;
  const std::vector<Frame>& f = controls.twist_curve->frames;
  return f.back().V.y - f.front().V.y;
}

std::vector<Station> sweep_stations(const std::vector<Frame>& frames, const SweepControls& controls) {
  SWEEP_EXPECTS(frames.size() >= 2, "frames.size() >= 2");
  const std::vector<double> length = chord_lengths(frames);
  const std::size_t n = frames.size();
  const double total = length.back();
  const double per_length = total > 0.0 ? 1.0 / total : 0.0;
  std::vector<Station> stations(n);
  for (std::size_t j = 0; j < n; ++j) {
    Station& s = stations[j];
    const double fraction = total > 0.0 ? length[j] / total : static_cast<double>(j) / static_cast<double>(n - 1);
    if (controls.scale) {
      const GraphValue g = graph_at(*controls.scale, fraction);
      s.scale = std::max(g.value, 0.0);
      s.scale_rate = g.slope * per_length;
    }
    if (controls.twist_curve) {
      const GraphValue g = graph_at(*controls.twist_curve, fraction);
      s.twist = kRadiansPerDegree * g.value;
      s.twist_rate = kRadiansPerDegree * g.slope * per_length;
    } else {
      s.twist = kRadiansPerDegree * controls.twist_degrees * fraction;
      s.twist_rate = kRadiansPerDegree * controls.twist_degrees * per_length;
    }
    const std::size_t before = j > 0 ? j - 1 : j;
    const std::size_t after = j + 1 < n ? j + 1 : j;
    const double ds = length[after] - length[before];
    if (ds > 0.0) s.bend = (frames[after].T - frames[before].T) / ds;
  }
  return stations;
}

}  // namespace sweep
