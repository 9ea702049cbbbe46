#include "geometry/mesh/triangle_intersection.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <utility>

namespace sweep {
namespace {

using Distances = std::array<double, 3>;

double longest_edge(const TriangleCorners& t) {
  return std::sqrt(std::max(
      {glm::dot(t[1] - t[0], t[1] - t[0]), glm::dot(t[2] - t[1], t[2] - t[1]), glm::dot(t[0] - t[2], t[0] - t[2])}));
}

/// The unit normal of `t`, or nullopt when its area is (nearly) zero for its size.
std::optional<glm::dvec3> unit_normal(const TriangleCorners& t, double size) {
  const glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
  const double length = glm::length(n);
  if (!(length > kIntersectionTolerance * size * size)) return std::nullopt;
  return n / length;
}

/// Signed distances of the corners of `t` from the plane through `origin` with unit normal `n`;
/// those within `zero` of it are set to 0, so a corner on the plane is on it exactly.
Distances plane_distances(const TriangleCorners& t, const glm::dvec3& n, const glm::dvec3& origin, double zero) {
  Distances d{};
  for (std::size_t i = 0; i < 3; ++i) {
    d[i] = glm::dot(n, t[i] - origin);
    if (std::abs(d[i]) <= zero) d[i] = 0.0;
  }
  return d;
}

bool one_strict_side(const Distances& d) {
  return (d[0] > 0.0 && d[1] > 0.0 && d[2] > 0.0) || (d[0] < 0.0 && d[1] < 0.0 && d[2] < 0.0);
}

bool all_zero(const Distances& d) {
  return d[0] == 0.0 && d[1] == 0.0 && d[2] == 0.0;
}

struct Segment {
  glm::dvec3 from, to;
};

/// The part of `t` on the plane its corners have distances `d` from: its corners on the plane
/// and the points where its edges cross it. Precondition: `d` neither all zero nor all of one
/// strict sign, so there are one or two such points (one: a corner touching the plane).
Segment plane_section(const TriangleCorners& t, const Distances& d) {
  std::array<glm::dvec3, 3> points{};
  std::size_t count = 0;
  for (std::size_t i = 0; i < 3; ++i) {
    if (d[i] == 0.0) points[count++] = t[i];
  }
  for (std::size_t i = 0; i < 3 && count < 3; ++i) {
    const std::size_t j = (i + 1) % 3;
    if (d[i] * d[j] < 0.0) points[count++] = t[i] + (t[j] - t[i]) * (d[i] / (d[i] - d[j]));
  }
  return {points[0], points[count - 1]};
}

/// A convex polygon (or what clipping leaves of one: a segment, a point).
struct Polygon {
  std::array<glm::dvec3, 8> points{};
  std::size_t count = 0;
};

/// The part of `polygon` where dot(inward, p - on_edge) >= -zero (Sutherland-Hodgman).
Polygon clip_to_edge(const Polygon& polygon, const glm::dvec3& inward, const glm::dvec3& on_edge, double zero) {
  Polygon out;
  for (std::size_t i = 0; i < polygon.count && out.count + 2 <= out.points.size(); ++i) {
    const glm::dvec3& p = polygon.points[i];
    const glm::dvec3& q = polygon.points[(i + 1) % polygon.count];
    const double dp = glm::dot(inward, p - on_edge) + zero, dq = glm::dot(inward, q - on_edge) + zero;
    if (dp >= 0.0) out.points[out.count++] = p;
    if ((dp >= 0.0) != (dq >= 0.0)) out.points[out.count++] = p + (q - p) * (dp / (dp - dq));
  }
  return out;
}

/// Coplanar `a` and `b` (unit normal `n`, b's): a clipped to b grown by `zero`, if anything is
/// left, and the mean of what is.
std::optional<glm::dvec3> coplanar_overlap(const TriangleCorners& a, const TriangleCorners& b, const glm::dvec3& n,
                                           double zero) {
  Polygon polygon{{a[0], a[1], a[2]}, 3};
  for (std::size_t i = 0; i < 3 && polygon.count > 0; ++i) {
    polygon = clip_to_edge(polygon, glm::normalize(glm::cross(n, b[(i + 1) % 3] - b[i])), b[i], zero);
  }
  if (polygon.count == 0) return std::nullopt;
  glm::dvec3 sum{0.0};
  for (std::size_t i = 0; i < polygon.count; ++i) sum += polygon.points[i];
  return sum / static_cast<double>(polygon.count);
}

/// Where `section` spans along the unit direction `line`: its ends' parameters, in order.
std::pair<double, double> span_along(const Segment& section, const glm::dvec3& line) {
  const double s = glm::dot(line, section.from), t = glm::dot(line, section.to);
  return {std::min(s, t), std::max(s, t)};
}

/// A point of both sections (of each triangle by the other's plane) when they overlap or are
/// within `zero` of each other along their common line: the middle of their overlap, on a's.
std::optional<glm::dvec3> common_point(const Segment& a, const Segment& b, const glm::dvec3& line, double zero) {
  const auto [a_low, a_high] = span_along(a, line);
  const auto [b_low, b_high] = span_along(b, line);
  const double low = std::max(a_low, b_low), high = std::min(a_high, b_high);
  if (!(high - low >= -zero)) return std::nullopt;
  const double from = glm::dot(line, a.from), to = glm::dot(line, a.to);
  if (from == to) return a.from;  // a touches b's plane at one point
  return a.from + (a.to - a.from) * std::clamp((0.5 * (low + high) - from) / (to - from), 0.0, 1.0);
}

}  // namespace

std::optional<glm::dvec3> triangle_intersection_point(const TriangleCorners& a, const TriangleCorners& b) {
  const double size_a = longest_edge(a), size_b = longest_edge(b);
  const double size = std::max(size_a, size_b), zero = kIntersectionTolerance * size;
  const std::optional<glm::dvec3> na = unit_normal(a, size_a);
  if (!na) return std::nullopt;
  const Distances db = plane_distances(b, *na, a[0], zero);
  if (one_strict_side(db)) return std::nullopt;  // the usual case: decided by a's plane alone
  const std::optional<glm::dvec3> nb = unit_normal(b, size_b);
  if (!nb) return std::nullopt;
  const Distances da = plane_distances(a, *nb, b[0], zero);
  if (one_strict_side(da)) return std::nullopt;
  const glm::dvec3 line = glm::cross(*na, *nb);
  const double sine = glm::length(line);
  if (all_zero(db) || all_zero(da) || sine <= kIntersectionTolerance) return coplanar_overlap(a, b, *nb, zero);
  return common_point(plane_section(a, da), plane_section(b, db), line / sine, zero);
}

bool triangles_intersect(const TriangleCorners& a, const TriangleCorners& b) {
  return triangle_intersection_point(a, b).has_value();
}

std::optional<double> ray_triangle_distance(const glm::dvec3& origin, const glm::dvec3& direction,
                                            const TriangleCorners& t) {
  constexpr double kEdgeSlack = 1e-9, kParallel = 1e-12;
  const glm::dvec3 e1 = t[1] - t[0], e2 = t[2] - t[0];
  const glm::dvec3 p = glm::cross(direction, e2);
  const double det = glm::dot(e1, p);  // -direction . (e1 x e2)
  // Compared squared: |det| <= kParallel |e1| |e2| |direction| is a ray (nearly) in the plane.
  if (det * det <= kParallel * kParallel * glm::dot(e1, e1) * glm::dot(e2, e2) * glm::dot(direction, direction)) {
    return std::nullopt;
  }
  const double inverse = 1.0 / det;
  const glm::dvec3 s = origin - t[0];
  const double u = glm::dot(s, p) * inverse;
  if (u < -kEdgeSlack || u > 1.0 + kEdgeSlack) return std::nullopt;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(direction, q) * inverse;
  if (v < -kEdgeSlack || u + v > 1.0 + kEdgeSlack) return std::nullopt;
  const double distance = glm::dot(e2, q) * inverse;
  if (distance < 0.0) return std::nullopt;
  return distance;
}

}  // namespace sweep
