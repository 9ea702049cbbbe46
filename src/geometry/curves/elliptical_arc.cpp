#include "geometry/curves/elliptical_arc.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sweep {
namespace {

glm::dvec2 rotate(glm::dvec2 v, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}

/// The signed angle from u to v (F.6.5.4).
double angle_between(glm::dvec2 u, glm::dvec2 v) {
  return std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y);
}

}  // namespace

std::optional<CentreArc> centre_arc(const EndpointArc& arc) {
  if (arc.from == arc.to || arc.rx == 0.0 || arc.ry == 0.0) return std::nullopt;
  CentreArc out;
  out.rx = std::abs(arc.rx);
  out.ry = std::abs(arc.ry);
  out.phi = std::fmod(arc.x_axis_degrees, 360.0) * std::numbers::pi / 180.0;
  // F.6.5.1: the midpoint of the chord in the ellipse's axes.
  const glm::dvec2 p = rotate((arc.from - arc.to) * 0.5, -out.phi);
  // F.6.6.2: radii too small to reach the end point grow by the same factor.
  const double lambda = (p.x * p.x) / (out.rx * out.rx) + (p.y * p.y) / (out.ry * out.ry);
  if (lambda > 1.0) {
    out.rx *= std::sqrt(lambda);
    out.ry *= std::sqrt(lambda);
  }
  // F.6.5.2: the centre in the ellipse's axes (the radicand clamped at 0 against rounding).
  const double rx2 = out.rx * out.rx;
  const double ry2 = out.ry * out.ry;
  const double numerator = rx2 * ry2 - rx2 * p.y * p.y - ry2 * p.x * p.x;
  const double denominator = rx2 * p.y * p.y + ry2 * p.x * p.x;
  double factor = std::sqrt(std::max(0.0, numerator / denominator));
  if (arc.large_arc == arc.sweep) factor = -factor;
  const glm::dvec2 c_prime{factor * out.rx * p.y / out.ry, -factor * out.ry * p.x / out.rx};
  // F.6.5.3: the centre itself.
  out.centre = rotate(c_prime, out.phi) + (arc.from + arc.to) * 0.5;
  // F.6.5.5 and F.6.5.6: the start angle and the sweep.
  const glm::dvec2 u{(p.x - c_prime.x) / out.rx, (p.y - c_prime.y) / out.ry};
  const glm::dvec2 v{(-p.x - c_prime.x) / out.rx, (-p.y - c_prime.y) / out.ry};
  out.start_angle = angle_between({1.0, 0.0}, u);
  double delta = angle_between(u, v);
  if (!arc.sweep && delta > 0.0) delta -= 2.0 * std::numbers::pi;
  if (arc.sweep && delta < 0.0) delta += 2.0 * std::numbers::pi;
  out.delta_angle = delta;
  // Radii so unequal that the centre form overflows (1e-308 against 1) give an ellipse thinner
  // than rounding: the straight line it is within that rounding.
  const bool finite = std::isfinite(out.rx) && std::isfinite(out.ry) && std::isfinite(out.centre.x) &&
                      std::isfinite(out.centre.y) && std::isfinite(out.start_angle) && std::isfinite(out.delta_angle);
  if (!finite) return std::nullopt;
  return out;
}

glm::dvec2 point_on(const CentreArc& arc, double t) {
  return arc.centre + rotate({arc.rx * std::cos(t), arc.ry * std::sin(t)}, arc.phi);
}

std::vector<glm::dvec2> arc_to_cubics(const EndpointArc& arc) {
  if (arc.from == arc.to) return {};
  const std::optional<CentreArc> centre = centre_arc(arc);
  if (!centre) return {arc.from + (arc.to - arc.from) / 3.0, arc.from + (arc.to - arc.from) * (2.0 / 3.0), arc.to};
  const CentreArc& c = *centre;
  const int pieces = std::max(1, static_cast<int>(std::ceil(std::abs(c.delta_angle) / kArcMaxPieceAngle - 1e-12)));
  const double step = c.delta_angle / pieces;
  const double handle = 4.0 / 3.0 * std::tan(step / 4.0);
  // The derivative of point_on with respect to t.
  const auto tangent = [&c](double t) { return rotate({-c.rx * std::sin(t), c.ry * std::cos(t)}, c.phi); };
  std::vector<glm::dvec2> points;
  points.reserve(static_cast<std::size_t>(3 * pieces));
  glm::dvec2 start = arc.from;
  for (int i = 0; i < pieces; ++i) {
    const double t0 = c.start_angle + step * i;
    const double t1 = i + 1 == pieces ? c.start_angle + c.delta_angle : t0 + step;
    const glm::dvec2 end = i + 1 == pieces ? arc.to : point_on(c, t1);
    points.push_back(start + handle * tangent(t0));
    points.push_back(end - handle * tangent(t1));
    points.push_back(end);
    start = end;
  }
  return points;
}

}  // namespace sweep
