// Ear clipping (core/polygon_triangulation.hpp) checked by the properties a flat cap needs, on
// convex, star, comb, zigzag and L shapes, collinear runs and repeated points, and random
// star-shaped polygons (rapidcheck), in both orientations:
//  - n - 2 triangles, every vertex used, every ring edge in one triangle and every diagonal in
//    two (watertight against the ring);
//  - the triangles' signed areas sum to the polygon's;
//  - for simple polygons none turns against the polygon, they do not overlap (absolute areas
//    sum to the polygon's), every centroid lies inside the polygon and, with exact coordinates,
//    no other vertex lies inside or on a triangle of positive area (no T-junction).
// Degenerate inputs (fewer than 3 points, all collinear, self-intersecting) must still give
// n - 2 triangles (none below 3 points) without hanging.
#include "geometry/mesh/polygon_triangulation.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace {

using Polygon = std::vector<glm::dvec2>;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

double twice_area(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

/// Squared diagonal of the bounding box: the area scale of the tolerances.
double area_scale(const Polygon& polygon) {
  glm::dvec2 low = polygon.front(), high = polygon.front();
  for (const glm::dvec2& p : polygon) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  const glm::dvec2 d = high - low;
  return d.x * d.x + d.y * d.y;
}

/// Crossing-number test, written independently of the library.
bool inside(const Polygon& polygon, const glm::dvec2& p) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const glm::dvec2 a = polygon[i], b = polygon[j];
    if ((a.y > p.y) != (b.y > p.y) && p.x < a.x + (p.y - a.y) * (b.x - a.x) / (b.y - a.y)) in = !in;
  }
  return in;
}

Polygon reversed(Polygon polygon) {
  std::reverse(polygon.begin(), polygon.end());
  return polygon;
}

/// "" if there are n - 2 triangles of distinct indices into `polygon` using every vertex.
std::string index_defect(const Polygon& polygon, const Triangles& triangles) {
  const std::size_t n = polygon.size();
  if (triangles.size() != n - 2) return "triangle count " + std::to_string(triangles.size());
  std::vector<bool> used(n, false);
  for (const auto& t : triangles) {
    for (const std::uint32_t i : t) {
      if (i >= n) return "index out of range";
      used[i] = true;
    }
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2]) return "repeated index in a triangle";
  }
  return std::find(used.begin(), used.end(), false) == used.end() ? "" : "unused vertex";
}

/// "" if the cap is watertight against the ring: each polygon edge i -> i + 1 is an edge of
/// exactly one triangle, in that direction, and every other directed edge a -> b of a triangle
/// is matched by exactly one b -> a of another.
std::string edge_defect(const Polygon& polygon, const Triangles& triangles) {
  const auto n = static_cast<std::uint32_t>(polygon.size());
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (const auto& t : triangles) {
    for (int k = 0; k < 3; ++k) ++count[{t[k], t[(k + 1) % 3]}];
  }
  for (std::uint32_t i = 0; i < n; ++i) count[{(i + 1) % n, i}] += 1;  // the ring closes the cap
  for (const auto& [edge, c] : count) {
    const auto back = count.find({edge.second, edge.first});
    if (c != 1 || back == count.end() || back->second != 1) return "edge not matched exactly once";
  }
  return "";
}

/// "" if the triangles' signed areas sum to the polygon's and, if `simple`, none turns against
/// the polygon and their absolute areas sum to its (no overlap).
std::string area_defect(const Polygon& polygon, const Triangles& triangles, bool simple) {
  const double area = sweep::polygon_twice_signed_area(polygon);
  const double sign = area < 0.0 ? -1.0 : 1.0;
  const double scale = area_scale(polygon);
  double signed_sum = 0.0, absolute_sum = 0.0;
  for (const auto& t : triangles) {
    const double a = twice_area(polygon[t[0]], polygon[t[1]], polygon[t[2]]);
    if (simple && sign * a < -1e-12 * scale) return "triangle against the polygon's orientation";
    signed_sum += a;
    absolute_sum += std::abs(a);
  }
  // Relative to the polygon's area, or to its box's for a polygon of (nearly) no area.
  if (std::abs(signed_sum - area) > 1e-9 * std::max(std::abs(area), scale)) return "signed areas differ";
  if (simple && std::abs(absolute_sum - std::abs(area)) > 1e-9 * std::abs(area)) return "triangles overlap";
  return "";
}

/// "" if every triangle of positive area has its centroid inside the polygon and, with
/// `exact_empty`, no other polygon vertex inside or on it (one at the place of a corner aside):
/// a vertex on a diagonal would be a T-junction.
std::string placement_defect(const Polygon& polygon, const Triangles& triangles, bool exact_empty) {
  const double scale = area_scale(polygon);
  for (const auto& t : triangles) {
    const glm::dvec2 a = polygon[t[0]], b = polygon[t[1]], c = polygon[t[2]];
    const double area = twice_area(a, b, c);
    if (std::abs(area) <= 1e-9 * scale) continue;
    if (!inside(polygon, (a + b + c) / 3.0)) return "centroid outside the polygon";
    if (!exact_empty) continue;
    for (const glm::dvec2& p : polygon) {
      if (p == a || p == b || p == c) continue;
      if (twice_area(a, b, p) * area >= 0.0 && twice_area(b, c, p) * area >= 0.0 && twice_area(c, a, p) * area >= 0.0) {
        return "a vertex inside or on a triangle";
      }
    }
  }
  return "";
}

/// "" if the triangulation of `polygon` has the properties of any input (count, indices,
/// watertight edges, signed area) and, if `simple`, those of a simple polygon (orientation, no
/// overlap, placement; a vertex on a diagonal is checked only with exact coordinates); else what
/// is wrong.
std::string triangulation_defect(const Polygon& polygon, bool simple, bool exact = true) {
  const Triangles triangles = sweep::triangulate_polygon(polygon);
  std::string defect = index_defect(polygon, triangles);
  if (defect.empty()) defect = edge_defect(polygon, triangles);
  if (defect.empty()) defect = area_defect(polygon, triangles, simple);
  if (defect.empty() && simple) defect = placement_defect(polygon, triangles, exact);
  return defect;
}

/// Checks a simple polygon in both orientations.
void expect_simple_triangulated(const Polygon& polygon) {
  EXPECT_EQ(triangulation_defect(polygon, true), "");
  EXPECT_EQ(triangulation_defect(reversed(polygon), true), "");
}

/// Regular n-gon of radius 1, counterclockwise.
Polygon regular(int n) {
  Polygon p;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / n;
    p.emplace_back(std::cos(angle), std::sin(angle));
  }
  return p;
}

/// Star with `points` tips at radius 1 and notches at radius `inner`, counterclockwise.
Polygon star(int points, double inner) {
  Polygon p;
  for (int i = 0; i < 2 * points; ++i) {
    const double angle = std::numbers::pi * i / points, r = i % 2 == 0 ? 1.0 : inner;
    p.emplace_back(r * std::cos(angle), r * std::sin(angle));
  }
  return p;
}

/// Comb: a bar along y in [0, 1] with `teeth` unit-wide teeth of height `height` going up,
/// counterclockwise.
Polygon comb(int teeth, double height) {
  Polygon p{{0.0, 0.0}, {2.0 * teeth - 1.0, 0.0}};
  for (int k = teeth - 1; k >= 0; --k) {
    const double right = 2.0 * k + 1.0, left = 2.0 * k;
    p.emplace_back(right, 1.0 + height);
    p.emplace_back(left, 1.0 + height);
    if (k > 0) {
      p.emplace_back(left, 1.0);
      p.emplace_back(left - 1.0, 1.0);
    }
  }
  return p;
}

/// Zigzag band: a sawtooth top over a flat bottom, counterclockwise.
Polygon zigzag(int teeth) {
  Polygon p{{0.0, 0.0}, {2.0 * teeth, 0.0}};
  for (int k = 2 * teeth; k >= 0; --k) p.emplace_back(k, k % 2 == 0 ? 1.0 : 3.0);
  return p;
}

Polygon l_shape() {
  return {{0, 0}, {3, 0}, {3, 1}, {1, 1}, {1, 4}, {0, 4}};
}

/// Square of side 4 with every integer point of its sides: straight runs of 5 collinear points.
Polygon square_with_collinear_runs() {
  Polygon p;
  for (int i = 0; i < 4; ++i) p.emplace_back(i, 0);
  for (int i = 0; i < 4; ++i) p.emplace_back(4, i);
  for (int i = 4; i > 0; --i) p.emplace_back(i, 4);
  for (int i = 4; i > 0; --i) p.emplace_back(0, i);
  return p;
}

/// Each vertex of `polygon` repeated `times` times in a row.
Polygon repeated_points(const Polygon& polygon, int times) {
  Polygon p;
  for (const glm::dvec2& v : polygon) p.insert(p.end(), static_cast<std::size_t>(times), v);
  return p;
}

TEST(PolygonTriangulation, TwiceSignedAreaIsPositiveCounterclockwise) {
  EXPECT_DOUBLE_EQ(sweep::polygon_twice_signed_area(l_shape()), 2.0 * 6.0);
  EXPECT_DOUBLE_EQ(sweep::polygon_twice_signed_area(reversed(l_shape())), -2.0 * 6.0);
  EXPECT_EQ(sweep::polygon_twice_signed_area(Polygon{{0, 0}, {1, 1}}), 0.0);
}

TEST(PolygonTriangulation, TriangleIsItself) {
  const Polygon triangle{{0, 0}, {1, 0}, {0, 1}};
  EXPECT_EQ(sweep::triangulate_polygon(triangle).size(), 1u);
  expect_simple_triangulated(triangle);
}

TEST(PolygonTriangulation, ConvexPolygons) {
  for (const int n : {4, 5, 6, 7, 8, 33, 1000}) {
    SCOPED_TRACE(n);
    expect_simple_triangulated(regular(n));
  }
}

TEST(PolygonTriangulation, StarPolygons) {
  for (const int points : {3, 5, 12, 200}) {
    for (const double inner : {0.1, 0.4, 0.9}) {
      SCOPED_TRACE(std::to_string(points) + " " + std::to_string(inner));
      expect_simple_triangulated(star(points, inner));
    }
  }
}

TEST(PolygonTriangulation, CombAndZigzagShapes) {
  for (const int teeth : {1, 2, 5, 40}) {
    SCOPED_TRACE(teeth);
    expect_simple_triangulated(comb(teeth, 10.0));
    expect_simple_triangulated(comb(teeth, 0.01));
    expect_simple_triangulated(zigzag(teeth));
  }
}

TEST(PolygonTriangulation, LShape) {
  expect_simple_triangulated(l_shape());
}

TEST(PolygonTriangulation, CollinearRuns) {
  expect_simple_triangulated(square_with_collinear_runs());
  // The comb's bar bottom and the teeth's tops as runs, and a star with collinear midpoints.
  Polygon comb_runs;
  const Polygon c = comb(4, 2.0);
  for (std::size_t i = 0; i < c.size(); ++i) {
    comb_runs.push_back(c[i]);
    const glm::dvec2 next = c[(i + 1) % c.size()];
    for (int k = 1; k < 4; ++k) comb_runs.push_back(c[i] + (next - c[i]) * (k / 4.0));
  }
  expect_simple_triangulated(comb_runs);
}

TEST(PolygonTriangulation, VerticesOnADiagonalAreNotCut) {
  // The notch's reflex tip (2, 2) lies on the diagonal (0, 4)-(4, 0) of the corner (0, 0).
  expect_simple_triangulated({{0, 0}, {4, 0}, {4, 4}, {2, 2}, {0, 4}});
  // A collinear run (3, 1), (1, 3), (0, 4) along the same diagonal.
  expect_simple_triangulated({{0, 0}, {4, 0}, {4, 4}, {3, 1}, {1, 3}, {0, 4}});
}

TEST(PolygonTriangulation, RepeatedConsecutivePoints) {
  expect_simple_triangulated(repeated_points(l_shape(), 2));
  expect_simple_triangulated(repeated_points(star(5, 0.4), 3));
  expect_simple_triangulated(repeated_points(square_with_collinear_runs(), 2));
  expect_simple_triangulated(repeated_points(comb(3, 1.0), 2));
}

TEST(PolygonTriangulation, FewerThanThreePointsGiveNothing) {
  EXPECT_TRUE(sweep::triangulate_polygon(Polygon{}).empty());
  EXPECT_TRUE(sweep::triangulate_polygon(Polygon{{1, 2}}).empty());
  EXPECT_TRUE(sweep::triangulate_polygon(Polygon{{1, 2}, {3, 4}}).empty());
}

TEST(PolygonTriangulation, AllCollinearGivesZeroAreaTriangles) {
  const Polygon line{{0, 0}, {1, 1}, {2, 2}, {3, 3}, {4, 4}};
  const Polygon back_and_forth{{0, 0}, {2, 0}, {1, 0}, {3, 0}, {0, 0}, {-1, 0}};
  const Polygon one_point(5, glm::dvec2(7.0, -1.0));
  for (const Polygon& p : {line, back_and_forth, one_point}) {
    const Triangles triangles = sweep::triangulate_polygon(p);
    EXPECT_EQ(triangulation_defect(p, false), "");
    for (const auto& t : triangles) EXPECT_EQ(twice_area(p[t[0]], p[t[1]], p[t[2]]), 0.0);
  }
}

TEST(PolygonTriangulation, SelfIntersectingGivesTrianglesAndEnds) {
  const Polygon bow_tie{{0, 0}, {1, 1}, {1, 0}, {0, 1}};
  EXPECT_EQ(sweep::triangulate_polygon(bow_tie).size(), 2u);
  // A figure eight whose second loop runs the other way, and a pentagram.
  Polygon eight;
  for (int i = 0; i < 200; ++i) {
    const double t = 2.0 * std::numbers::pi * i / 200;
    eight.emplace_back(std::sin(2.0 * t), std::sin(t));
  }
  const Polygon pentagram{{1, 0}, {-0.81, 0.59}, {0.31, -0.95}, {0.31, 0.95}, {-0.81, -0.59}};
  for (const Polygon& p : {bow_tie, eight, pentagram}) {
    const Triangles triangles = sweep::triangulate_polygon(p);
    EXPECT_EQ(triangles.size(), p.size() - 2);
    for (const auto& t : triangles) {
      for (const std::uint32_t i : t) EXPECT_LT(i, p.size());
    }
  }
}

/// A star-shaped polygon around the origin, so always simple: the k-th of `count` vertices at a
/// random angle in [k, k + 1) * 2 pi / count (so consecutive ones are less than pi apart) and a
/// random radius from 0.05 to 10, times a random scale (2^-20 to 2^20) plus a random offset. With
/// `degenerate`, some vertices are repeated or preceded by the midpoint of their edge.
Polygon random_star_shaped(bool degenerate) {
  const int count = *rc::gen::inRange(3, 80);
  const double scale = std::ldexp(1.0, *rc::gen::inRange(-20, 21));
  const glm::dvec2 offset = scale * glm::dvec2(*rc::gen::inRange(-100, 101), *rc::gen::inRange(-100, 101));
  Polygon p;
  for (int k = 0; k < count; ++k) {
    const double angle = 2.0 * std::numbers::pi * (k + *rc::gen::inRange(0, 1000) / 1000.0) / count;
    const double r = *rc::gen::inRange(5, 1001) / 100.0;
    const glm::dvec2 point = offset + scale * r * glm::dvec2(std::cos(angle), std::sin(angle));
    if (degenerate && !p.empty()) {
      const int kind = *rc::gen::inRange(0, 4);
      if (kind == 0) p.push_back(p.back());
      if (kind == 1) p.push_back((p.back() + point) / 2.0);
    }
    p.push_back(point);
  }
  return *rc::gen::arbitrary<bool>() ? p : reversed(p);
}

RC_GTEST_PROP(PolygonTriangulationProperty, StarShapedPolygonsAreTriangulatedWithoutOverlap, ()) {
  const Polygon polygon = random_star_shaped(false);
  RC_ASSERT(triangulation_defect(polygon, true) == "");
}

RC_GTEST_PROP(PolygonTriangulationProperty, RepeatedAndMidpointVerticesKeepTheProperties, ()) {
  const Polygon polygon = random_star_shaped(true);
  RC_ASSERT(triangulation_defect(polygon, true, false) == "");
}

RC_GTEST_PROP(PolygonTriangulationProperty, RandomPointCloudsEndWithNMinus2Triangles, ()) {
  const int count = *rc::gen::inRange(3, 60);
  Polygon polygon;
  for (int i = 0; i < count; ++i) polygon.emplace_back(*rc::gen::inRange(-5, 6), *rc::gen::inRange(-5, 6));
  RC_ASSERT(triangulation_defect(polygon, false) == "");
}

}  // namespace
