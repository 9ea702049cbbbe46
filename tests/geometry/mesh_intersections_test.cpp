// The bounding volume hierarchy's queries (triangle_bvh.hpp) against brute force on random
// triangles, and the intersection checks (intersections.hpp) on random triangles, spheres and
// tori: a closed sphere does not pass through itself, overlapping spheres intersect and separate
// ones do not, a torus whose tube is wider than its ring meets itself where its tube crosses the
// axis, and the result does not depend on the thread count.
#include "geometry/mesh/intersections.hpp"
#include "geometry/mesh/triangle_bvh.hpp"
#include "geometry/mesh/triangle_intersection.hpp"
#include "geometry/thread_pool.hpp"
#include "support/shell_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdint>
#include <mutex>
#include <numbers>
#include <random>
#include <set>
#include <utility>
#include <vector>

namespace sweep {
namespace {

using test::on_triangle;
using test::sphere;
using test::torus;

using Pairs = std::set<std::pair<std::uint32_t, std::uint32_t>>;

/// `count` random triangles in the unit cube, corners up to `size` from a centre along each axis,
/// each with its own vertices.
Shell random_triangles(std::uint32_t count, std::uint32_t seed, double size = 0.15) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0), offset(-size, size);
  Shell s;
  for (std::uint32_t t = 0; t < count; ++t) {
    const glm::dvec3 centre{unit(random), unit(random), unit(random)};
    for (std::uint32_t k = 0; k < 3; ++k) {
      s.indices.push_back(static_cast<std::uint32_t>(s.positions.size()));
      s.positions.push_back(centre + glm::dvec3(offset(random), offset(random), offset(random)));
    }
  }
  return s;
}

TriangleCorners corners_of(const Shell& s, std::uint32_t t) {
  return {s.positions[s.indices[3 * t]], s.positions[s.indices[3 * t + 1]], s.positions[s.indices[3 * t + 2]]};
}

bool boxes_overlap(const TriangleCorners& a, const TriangleCorners& b) {
  for (int axis = 0; axis < 3; ++axis) {
    const double a_low = std::min({a[0][axis], a[1][axis], a[2][axis]});
    const double a_high = std::max({a[0][axis], a[1][axis], a[2][axis]});
    const double b_low = std::min({b[0][axis], b[1][axis], b[2][axis]});
    const double b_high = std::max({b[0][axis], b[1][axis], b[2][axis]});
    if (a_high < b_low || b_high < a_low) return false;
  }
  return true;
}

Pairs bvh_pairs(const TriangleBvh& a, const TriangleBvh* b, int threads) {
  Pairs found;
  std::mutex lock;
  const PairVisitor visit = [&](std::uint32_t x, std::uint32_t y, int) {
    const std::lock_guard<std::mutex> hold(lock);
    EXPECT_TRUE(found.insert({x, y}).second) << "pair reported twice";
    return true;
  };
  EXPECT_TRUE(b == nullptr ? for_each_overlapping_pair(a, visit, threads)
                           : for_each_overlapping_pair(a, *b, visit, threads));
  return found;
}

TEST(TriangleBvh, OverlappingPairsAgreeWithBruteForce) {
  const Shell shell = random_triangles(400, 7), other = random_triangles(300, 11);
  Pairs self, across;
  for (std::uint32_t i = 0; i < shell.triangle_count(); ++i) {
    for (std::uint32_t j = i + 1; j < shell.triangle_count(); ++j) {
      if (boxes_overlap(corners_of(shell, i), corners_of(shell, j))) self.insert({i, j});
    }
    for (std::uint32_t j = 0; j < other.triangle_count(); ++j) {
      if (boxes_overlap(corners_of(shell, i), corners_of(other, j))) across.insert({i, j});
    }
  }
  const TriangleBvh bvh(shell), other_bvh(other);
  ASSERT_GT(self.size(), 100u);
  for (const int threads : {1, 2, 3}) {
    EXPECT_EQ(bvh_pairs(bvh, nullptr, threads), self) << threads << " threads";
    EXPECT_EQ(bvh_pairs(bvh, &other_bvh, threads), across) << threads << " threads";
  }
}

TEST(TriangleBvh, AVisitorThatReturnsFalseStopsTheWalk) {
  const Shell shell = random_triangles(400, 7);
  const TriangleBvh bvh(shell);
  int calls = 0;
  EXPECT_FALSE(for_each_overlapping_pair(bvh, [&](std::uint32_t, std::uint32_t, int) { return ++calls < 5; }));
  EXPECT_EQ(calls, 5);
}

TEST(TriangleBvh, NearestHitAgreesWithBruteForce) {
  const Shell shell = random_triangles(400, 3);
  const TriangleBvh bvh(shell, 2);
  std::mt19937 random(5);
  std::uniform_real_distribution<double> unit(-0.2, 1.2), direction(-1.0, 1.0);
  int hits = 0;
  for (int r = 0; r < 500; ++r) {
    const Ray ray{{unit(random), unit(random), unit(random)},
                  glm::normalize(glm::dvec3(direction(random), direction(random), direction(random))),
                  r % 2 ? 0.5 : 10.0};
    const std::uint32_t skip = static_cast<std::uint32_t>(r) % 400;
    RayHit expected{ray.max_distance, kNoTriangle};
    for (std::uint32_t t = 0; t < shell.triangle_count(); ++t) {
      const auto d = ray_triangle_distance(ray.origin, ray.direction, corners_of(shell, t));
      if (t != skip && d && *d <= expected.distance && (*d < expected.distance || t < expected.triangle)) {
        expected = {*d, t};
      }
    }
    const std::optional<RayHit> hit = bvh.nearest_hit(ray, {skip, false});
    ASSERT_EQ(hit.has_value(), expected.triangle != kNoTriangle) << "ray " << r;
    if (!hit) continue;
    ++hits;
    EXPECT_EQ(hit->triangle, expected.triangle) << "ray " << r;
    EXPECT_EQ(hit->distance, expected.distance) << "ray " << r;
  }
  EXPECT_GT(hits, 100);
}

TEST(TriangleBvh, NoTrianglesNoPairsNoHits) {
  const Shell empty;
  const TriangleBvh bvh(empty);
  EXPECT_TRUE(bvh.nodes().empty());
  EXPECT_TRUE(bvh_pairs(bvh, nullptr, 2).empty());
  EXPECT_FALSE(bvh.nearest_hit({}));
}

TEST(SelfIntersections, CountsWhatBruteForceFindsOnRandomTriangles) {
  const Shell shell = random_triangles(300, 13);
  std::size_t expected = 0;
  for (std::uint32_t i = 0; i < shell.triangle_count(); ++i) {
    for (std::uint32_t j = i + 1; j < shell.triangle_count(); ++j) {
      expected += triangles_intersect(corners_of(shell, i), corners_of(shell, j)) ? 1 : 0;
    }
  }
  ASSERT_GT(expected, 10u);
  const IntersectingPairs found = self_intersections(shell);
  EXPECT_EQ(found.count, expected);
  EXPECT_EQ(found.sample.size(), kIntersectionSample);
  EXPECT_EQ(self_intersections(shell, 5).count, 5u);  // the limit
  for (const auto& [a, b] : found.sample) EXPECT_TRUE(triangles_intersect(corners_of(shell, a), corners_of(shell, b)));
}

TEST(SelfIntersections, TheResultDoesNotDependOnTheThreadCount) {
  const Shell shell = random_triangles(40000, 17, 0.01);  // enough to be split among threads
  set_worker_count(1);
  const IntersectingPairs one = self_intersections(shell, 1'000'000);
  set_worker_count(3);
  const IntersectingPairs three = self_intersections(shell, 1'000'000);
  set_worker_count(default_worker_count());
  ASSERT_GT(one.count, 100u);
  EXPECT_EQ(three.count, one.count);
  EXPECT_EQ(three.sample, one.sample);
  EXPECT_EQ(three.first_point, one.first_point);
}

TEST(SelfIntersections, AClosedSphereOrTorusDoesNotPassThroughItself) {
  EXPECT_EQ(self_intersections(sphere({0, 0, 0}, 1.0, 32, 16)).count, 0u);
  EXPECT_EQ(self_intersections(torus(3.0, 1.0, 48, 24)).count, 0u);
}

TEST(SelfIntersections, ATorusWiderThanItsRingMeetsItselfOnItsAxis) {
  // Every tube circle of a spindle torus passes through the two points of the axis at heights
  // +-sqrt(tube^2 - ring^2): there the triangles of the band that crosses the axis all meet.
  const double ring = 1.0, tube = 1.5;
  const Shell shell = torus(ring, tube, 48, 32);
  const IntersectingPairs found = self_intersections(shell);
  ASSERT_GT(found.count, 0u);
  ASSERT_FALSE(found.sample.empty());
  const glm::dvec3 p = found.first_point;
  EXPECT_TRUE(on_triangle(p, corners_of(shell, found.sample[0].first), 1e-9));
  EXPECT_TRUE(on_triangle(p, corners_of(shell, found.sample[0].second), 1e-9));
  // On the surface: the tube circle in p's half-plane, or the part of it past the axis.
  const double rho = std::hypot(p.x, p.y);
  const double off =
      std::min(std::abs(std::hypot(rho - ring, p.z) - tube), std::abs(std::hypot(rho + ring, p.z) - tube));
  EXPECT_LT(off, 0.02);
  EXPECT_LT(rho, 1e-9);
  EXPECT_NEAR(std::abs(p.z), std::sqrt(tube * tube - ring * ring), 0.02);
}

TEST(MutualIntersections, OverlappingSpheresIntersectOnBothSurfaces) {
  const Shell a = sphere({0, 0, 0}, 1.0, 32, 16), b = sphere({1.5, 0.2, 0.1}, 1.0, 32, 16);
  const IntersectingPairs found = mutual_intersections(a, b);
  ASSERT_GT(found.count, 0u);
  EXPECT_NEAR(glm::length(found.first_point), 1.0, 0.01);
  EXPECT_NEAR(glm::distance(found.first_point, glm::dvec3(1.5, 0.2, 0.1)), 1.0, 0.01);
  EXPECT_TRUE(on_triangle(found.first_point, corners_of(a, found.sample[0].first), 1e-9));
  EXPECT_TRUE(on_triangle(found.first_point, corners_of(b, found.sample[0].second), 1e-9));
}

TEST(MutualIntersections, SeparateSpheresDoNotIntersect) {
  const Shell a = sphere({0, 0, 0}, 1.0, 32, 16);
  EXPECT_EQ(mutual_intersections(a, sphere({3, 0, 0}, 1.0, 32, 16)).count, 0u);      // boxes apart
  EXPECT_EQ(mutual_intersections(a, sphere({1.6, 1.6, 0}, 1.0, 32, 16)).count, 0u);  // boxes overlap
  EXPECT_EQ(mutual_intersections(a, Shell{}).count, 0u);
}

}  // namespace
}  // namespace sweep
