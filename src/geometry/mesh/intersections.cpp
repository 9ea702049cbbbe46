#include "geometry/mesh/intersections.hpp"

#include "base/precondition.hpp"
#include "geometry/mesh/triangle_bvh.hpp"
#include "geometry/mesh/triangle_intersection.hpp"
#include "geometry/thread_pool.hpp"

#include <glm/common.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <atomic>
#include <optional>

namespace sweep {
namespace {

constexpr std::size_t kParallelTriangles = 1 << 14;  // below this one thread is quicker

using Pair = std::pair<std::uint32_t, std::uint32_t>;

struct Found {
  Pair pair;
  glm::dvec3 point;
  bool operator<(const Found& other) const { return pair < other.pair; }
};

/// Counts the intersections the threads find, up to a limit, and keeps each thread's lowest
/// pairs (so that the result does not depend on which thread found what).
class Collector {
 public:
  Collector(std::size_t limit, int threads) : limit_(limit), lowest_(static_cast<std::size_t>(threads)) {}

  /// Records an intersection; returns whether to go on (the limit is not reached).
  bool add(const Pair& pair, const glm::dvec3& point, int worker) {
    std::vector<Found>& lowest = lowest_[static_cast<std::size_t>(worker)];
    const Found found{pair, point};
    lowest.insert(std::upper_bound(lowest.begin(), lowest.end(), found), found);
    if (lowest.size() > kIntersectionSample) lowest.pop_back();
    return count_.fetch_add(1, std::memory_order_relaxed) + 1 < limit_;
  }

  IntersectingPairs result() const {
    std::vector<Found> all;
    for (const std::vector<Found>& lowest : lowest_) all.insert(all.end(), lowest.begin(), lowest.end());
    std::sort(all.begin(), all.end());
    IntersectingPairs out;
    out.count = std::min(count_.load(), limit_);
    if (!all.empty()) out.first_point = all.front().point;
    for (std::size_t i = 0; i < all.size() && i < kIntersectionSample; ++i) out.sample.push_back(all[i].pair);
    return out;
  }

 private:
  std::size_t limit_;
  std::atomic<std::size_t> count_{0};
  std::vector<std::vector<Found>> lowest_;
};

int threads_for(std::size_t triangles) {
  return triangles < kParallelTriangles ? 1 : worker_count();
}

bool boxes_apart(const BvhBox& a, const BvhBox& b) {
  return glm::any(glm::lessThan(a.high, b.low)) || glm::any(glm::lessThan(b.high, a.low));
}

}  // namespace

IntersectingPairs self_intersections(const Shell& shell, std::size_t limit) {
  SWEEP_EXPECTS(limit > 0, "limit > 0");
  return self_intersections(TriangleBvh(shell, threads_for(shell.triangle_count())), limit);
}

IntersectingPairs self_intersections(const TriangleBvh& bvh, std::size_t limit) {
  SWEEP_EXPECTS(limit > 0, "limit > 0");
  const int threads = threads_for(bvh.triangle_count());
  Collector collector(limit, threads);
  for_each_overlapping_pair(
      bvh,
      [&](std::uint32_t a, std::uint32_t b, int worker) {
        if (bvh.share_vertex(a, b)) return true;
        const std::optional<glm::dvec3> point = triangle_intersection_point(bvh.corners(a), bvh.corners(b));
        return !point || collector.add({a, b}, *point, worker);
      },
      threads);
  return collector.result();
}

IntersectingPairs mutual_intersections(const Shell& a, const Shell& b, std::size_t limit) {
  SWEEP_EXPECTS(limit > 0, "limit > 0");
  if (a.triangle_count() == 0 || b.triangle_count() == 0 || boxes_apart(box_of(a), box_of(b))) return {};
  const int threads = threads_for(a.triangle_count() + b.triangle_count());
  return mutual_intersections(TriangleBvh(a, threads), TriangleBvh(b, threads), limit);
}

IntersectingPairs mutual_intersections(const TriangleBvh& bvh_a, const TriangleBvh& bvh_b, std::size_t limit) {
  SWEEP_EXPECTS(limit > 0, "limit > 0");
  if (bvh_a.triangle_count() == 0 || bvh_b.triangle_count() == 0 ||
      boxes_apart(bvh_a.nodes().front().box, bvh_b.nodes().front().box)) {
    return {};
  }
  const int threads = threads_for(bvh_a.triangle_count() + bvh_b.triangle_count());
  Collector collector(limit, threads);
  for_each_overlapping_pair(
      bvh_a, bvh_b,
      [&](std::uint32_t ta, std::uint32_t tb, int worker) {
        const std::optional<glm::dvec3> point = triangle_intersection_point(bvh_a.corners(ta), bvh_b.corners(tb));
        return !point || collector.add({ta, tb}, *point, worker);
      },
      threads);
  return collector.result();
}

}  // namespace sweep
