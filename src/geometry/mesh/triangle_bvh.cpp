#include "geometry/mesh/triangle_bvh.hpp"

#include "base/precondition.hpp"
#include "geometry/thread_pool.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <utility>

namespace sweep {
namespace {

constexpr std::uint32_t kLeafSize = 4;
constexpr std::size_t kParallelDepth = 4;  // 16 subtrees partitioned side by side
constexpr std::size_t kChunk = 1 << 14;

// A triangle's centroid in float: only where to split depends on it, never a box, and the
// partitions, which are most of the build, move half the bytes.
struct Item {
  glm::vec3 centroid;
  std::uint32_t triangle;
};

void grow(BvhBox& box, const glm::dvec3& p) {
  box.low = glm::min(box.low, p);
  box.high = glm::max(box.high, p);
}

bool valid_part(const TriangleSpan& part) {
  return part.indices.size() % 3 == 0 && std::all_of(part.indices.begin(), part.indices.end(),
                                                     [&](std::uint32_t i) { return i < part.positions.size(); });
}

std::size_t node_count(std::size_t items) {
  return items <= kLeafSize ? 1 : 1 + node_count(items / 2) + node_count(items - items / 2);
}

/// Appends the nodes over items [begin, end) in depth-first order, each split in halves.
std::uint32_t lay_out(std::vector<BvhNode>& nodes, std::uint32_t begin, std::uint32_t end) {
  const auto index = static_cast<std::uint32_t>(nodes.size());
  nodes.emplace_back();
  if (end - begin <= kLeafSize) {
    nodes[index].first = begin;
    nodes[index].count = end - begin;
    return index;
  }
  const std::uint32_t middle = begin + (end - begin) / 2;
  lay_out(nodes, begin, middle);
  const std::uint32_t right = lay_out(nodes, middle, end);
  nodes[index].first = right;
  return index;
}

template <int kAxis>
void split_along(std::span<Item> items) {
  std::nth_element(items.begin(), items.begin() + static_cast<std::ptrdiff_t>(items.size() / 2), items.end(),
                   [](const Item& a, const Item& b) { return a.centroid[kAxis] < b.centroid[kAxis]; });
}

/// Puts the half of `items` with the lower centroids along the longest axis of their box first.
void split_at_median(std::span<Item> items) {
  glm::vec3 low = items.front().centroid, high = low;
  for (const Item& item : items) {
    low = glm::min(low, item.centroid);
    high = glm::max(high, item.centroid);
  }
  const glm::vec3 extent = high - low;
  if (extent.x >= extent.y && extent.x >= extent.z) {
    split_along<0>(items);
  } else if (extent.y >= extent.z) {
    split_along<1>(items);
  } else {
    split_along<2>(items);
  }
}

struct Subtree {
  std::uint32_t node, begin, end;
};

/// Splits the items of `tree` and of every node below it; the nodes `depth` levels down are
/// left to `rest` when it is given.
void partition(std::span<const BvhNode> nodes, std::span<Item> items, Subtree tree, std::size_t depth,
               std::vector<Subtree>* rest) {
  if (nodes[tree.node].count > 0) return;
  if (rest != nullptr && depth == 0) {
    rest->push_back(tree);
    return;
  }
  split_at_median(items.subspan(tree.begin, tree.end - tree.begin));
  const std::uint32_t middle = tree.begin + (tree.end - tree.begin) / 2;
  const std::size_t below = depth > 0 ? depth - 1 : 0;
  partition(nodes, items, {tree.node + 1, tree.begin, middle}, below, rest);
  partition(nodes, items, {nodes[tree.node].first, middle, tree.end}, below, rest);
}

/// 1 / direction, with a finite stand-in where a component is (nearly) 0, so that the slab
/// test below never multiplies 0 by infinity: a ray along a face of a box stays inside it.
glm::dvec3 inverse_direction(const glm::dvec3& direction) {
  glm::dvec3 inverse;
  for (int axis = 0; axis < 3; ++axis) {
    const double d = direction[axis];
    inverse[axis] = std::abs(d) > 1e-300 ? 1.0 / d : std::copysign(1e300, d);
  }
  return inverse;
}

/// Where the ray enters `box` (0 if it starts inside), or nullopt if it misses it before
/// `limit` (the slab test, without branches).
std::optional<double> entry_distance(const BvhBox& box, const glm::dvec3& origin, const glm::dvec3& inverse,
                                     double limit) {
  const glm::dvec3 t0 = (box.low - origin) * inverse, t1 = (box.high - origin) * inverse;
  const glm::dvec3 near = glm::min(t0, t1), far = glm::max(t0, t1);
  const double enter = std::max(std::max(near.x, near.y), std::max(near.z, 0.0));
  const double leave = std::min(std::min(far.x, far.y), std::min(far.z, limit));
  if (enter > leave) return std::nullopt;
  return enter;
}

}  // namespace

TriangleBvh::TriangleBvh(std::span<const TriangleSpan> parts, int threads) : parts_(parts.begin(), parts.end()) {
  SWEEP_EXPECTS(std::all_of(parts.begin(), parts.end(), valid_part), "indices in threes, below the position count");
  SWEEP_EXPECTS(threads >= 1, "threads >= 1");
  std::size_t total = 0;
  for (const TriangleSpan& part : parts_) {
    part_starts_.push_back(static_cast<std::uint32_t>(total));
    total += part.indices.size() / 3;
  }
  SWEEP_EXPECTS(total < kNoTriangle, "fewer than 2^32 - 1 triangles");
  order_.resize(total);
  build(threads);
}

TriangleBvh::TriangleBvh(const Shell& shell, int threads)
    : TriangleBvh(std::array{TriangleSpan{shell.positions, shell.indices}}, threads) {}

std::size_t TriangleBvh::part_of(std::uint32_t triangle) const {
  if (parts_.size() == 1) return 0;
  return static_cast<std::size_t>(std::upper_bound(part_starts_.begin(), part_starts_.end(), triangle) -
                                  part_starts_.begin()) -
         1;
}

TriangleCorners TriangleBvh::corners(std::uint32_t triangle) const {
  SWEEP_EXPECTS(triangle < order_.size(), "triangle < triangle_count()");
  const std::size_t part = part_of(triangle);
  const TriangleSpan& span = parts_[part];
  const std::size_t k = 3 * static_cast<std::size_t>(triangle - part_starts_[part]);
  return {span.positions[span.indices[k]], span.positions[span.indices[k + 1]], span.positions[span.indices[k + 2]]};
}

bool TriangleBvh::share_vertex(std::uint32_t a, std::uint32_t b) const {
  SWEEP_EXPECTS(a < order_.size() && b < order_.size(), "triangles below triangle_count()");
  const std::size_t part = part_of(a);
  if (part != part_of(b)) return false;
  const std::span<const std::uint32_t> indices = parts_[part].indices;
  const std::size_t i = 3 * static_cast<std::size_t>(a - part_starts_[part]);
  const std::size_t j = 3 * static_cast<std::size_t>(b - part_starts_[part]);
  for (std::size_t m = 0; m < 3; ++m) {
    if (indices[i + m] == indices[j] || indices[i + m] == indices[j + 1] || indices[i + m] == indices[j + 2]) {
      return true;
    }
  }
  return false;
}

void TriangleBvh::build(int threads) {
  const std::size_t count = order_.size();
  if (count == 0) return;
  std::vector<Item> items(count);
  parallel_chunks(count, kChunk, threads, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t t = begin; t < end; ++t) {
      const TriangleCorners c = corners(static_cast<std::uint32_t>(t));
      items[t] = {glm::vec3((c[0] + c[1] + c[2]) / 3.0), static_cast<std::uint32_t>(t)};
    }
  });
  nodes_.reserve(node_count(count));
  lay_out(nodes_, 0, static_cast<std::uint32_t>(count));
  // The top levels split one node at a time; the subtrees under them are independent.
  std::vector<Subtree> subtrees;
  partition(nodes_, items, {0, 0, static_cast<std::uint32_t>(count)}, kParallelDepth, &subtrees);
  parallel_chunks(subtrees.size(), 1, threads, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t s = begin; s < end; ++s) partition(nodes_, items, subtrees[s], 0, nullptr);
  });
  for (std::size_t k = 0; k < count; ++k) order_[k] = items[k].triangle;
  fit_boxes(threads);
}

void TriangleBvh::fit_boxes(int threads) {
  parallel_chunks(nodes_.size(), kChunk, threads, [&](std::size_t begin, std::size_t end, int) {
    for (std::size_t n = begin; n < end; ++n) {
      BvhNode& node = nodes_[n];
      for (std::uint32_t k = node.first; k < node.first + node.count; ++k) {
        for (const glm::dvec3& p : corners(order_[k])) grow(node.box, p);
      }
    }
  });
  // Depth-first order puts children after their parent: from the back, children are ready.
  for (std::size_t n = nodes_.size(); n-- > 0;) {
    BvhNode& node = nodes_[n];
    if (node.count > 0) continue;
    const BvhBox &left = nodes_[n + 1].box, &right = nodes_[node.first].box;
    node.box = {glm::min(left.low, right.low), glm::max(left.high, right.high)};
  }
}

void TriangleBvh::leaf_hit(const BvhNode& leaf, const Ray& ray, RaySkip skip, RayHit& best) const {
  for (std::uint32_t k = leaf.first; k < leaf.first + leaf.count; ++k) {
    const std::uint32_t t = order_[k];
    if (t == skip.triangle || (skip.neighbours && skip.triangle != kNoTriangle && share_vertex(t, skip.triangle))) {
      continue;
    }
    const std::optional<double> distance = ray_triangle_distance(ray.origin, ray.direction, corners(t));
    if (distance && (*distance < best.distance || (*distance == best.distance && t < best.triangle))) {
      best = {*distance, t};
    }
  }
}

std::optional<RayHit> TriangleBvh::nearest_hit(const Ray& ray, RaySkip skip) const {
  if (nodes_.empty()) return std::nullopt;
  const glm::dvec3 inverse = inverse_direction(ray.direction);
  RayHit best{ray.max_distance, kNoTriangle};
  struct Entry {
    std::uint32_t node;
    double distance;
  };
  std::array<Entry, 64> stack{};  // a median tree over < 2^32 triangles is at most 32 deep
  std::size_t size = 0;
  if (const auto d = entry_distance(nodes_[0].box, ray.origin, inverse, best.distance)) stack[size++] = {0, *d};
  while (size > 0) {
    const Entry entry = stack[--size];
    if (entry.distance > best.distance) continue;
    const BvhNode& node = nodes_[entry.node];
    if (node.count > 0) {
      leaf_hit(node, ray, skip, best);
      continue;
    }
    std::array<Entry, 2> children{};
    std::size_t found = 0;
    for (const std::uint32_t child : {entry.node + 1, node.first}) {
      if (const auto d = entry_distance(nodes_[child].box, ray.origin, inverse, best.distance)) {
        children[found++] = {child, *d};
      }
    }
    if (found == 2 && children[0].distance < children[1].distance) std::swap(children[0], children[1]);
    for (std::size_t c = 0; c < found; ++c) stack[size++] = children[c];  // the nearer is popped first
  }
  if (best.triangle == kNoTriangle) return std::nullopt;
  return best;
}

BvhBox box_of(const Shell& shell) {
  BvhBox box;
  for (const glm::dvec3& p : shell.positions) {
    box.low = glm::min(box.low, p);
    box.high = glm::max(box.high, p);
  }
  return box;
}

}  // namespace sweep
