// The pair queries of triangle_bvh.hpp: a simultaneous descent of two trees (or of one tree
// against itself: each node's two children against each other, then each child against itself),
// split into independent tasks for the threads.
#include "geometry/mesh/triangle_bvh.hpp"

#include "base/precondition.hpp"
#include "geometry/thread_pool.hpp"

#include <glm/common.hpp>

#include <array>
#include <atomic>
#include <utility>
#include <vector>

namespace sweep {
namespace {

constexpr std::size_t kTasksPerThread = 64;

bool overlap(const BvhBox& a, const BvhBox& b) {
  return a.low.x <= b.high.x && b.low.x <= a.high.x && a.low.y <= b.high.y && b.low.y <= a.high.y &&
         a.low.z <= b.high.z && b.low.z <= a.high.z;
}

BvhBox triangle_box(const TriangleCorners& c) {
  return {glm::min(glm::min(c[0], c[1]), c[2]), glm::max(glm::max(c[0], c[1]), c[2])};
}

double extent(const BvhBox& box) {
  const glm::dvec3 d = box.high - box.low;
  return d.x + d.y + d.z;
}

/// Which of two overlapping inner-or-leaf nodes to open: the first unless it is a leaf or the
/// second is an inner node with the larger box.
bool open_first(const BvhNode& a, const BvhNode& b) {
  return a.count == 0 && (b.count > 0 || extent(a.box) >= extent(b.box));
}

/// A node against itself (`self`), or a node of the first tree against one of the second.
struct PairTask {
  std::uint32_t a, b;
  bool self;
};

/// The walk of one thread: reports pairs to `visit` until it or another thread stops.
class PairWalk {
 public:
  PairWalk(const TriangleBvh& a, const TriangleBvh& b, bool one_tree, const PairVisitor& visit,
           std::atomic<bool>& stopped, int worker)
      : a_(a), b_(b), one_tree_(one_tree), visit_(visit), stopped_(stopped), worker_(worker) {}

  bool run(const PairTask& task) { return task.self ? self(task.a) : across(task.a, task.b); }

 private:
  bool self(std::uint32_t node) {
    if (stopped_.load(std::memory_order_relaxed)) return false;
    const BvhNode& n = a_.nodes()[node];
    if (n.count > 0) return leaf_self(n);
    return self(node + 1) && self(n.first) && across(node + 1, n.first);
  }

  bool across(std::uint32_t node_a, std::uint32_t node_b) {
    if (stopped_.load(std::memory_order_relaxed)) return false;
    const BvhNode& na = a_.nodes()[node_a];
    const BvhNode& nb = b_.nodes()[node_b];
    if (!overlap(na.box, nb.box)) return true;
    if (na.count > 0 && nb.count > 0) return leaf_pair(na, nb);
    if (open_first(na, nb)) return across(node_a + 1, node_b) && across(na.first, node_b);
    return across(node_a, node_b + 1) && across(node_a, nb.first);
  }

  bool leaf_self(const BvhNode& leaf) {
    std::array<BvhBox, 8> boxes;
    for (std::uint32_t i = 0; i < leaf.count; ++i) boxes[i] = triangle_box(a_.corners(a_.order()[leaf.first + i]));
    for (std::uint32_t i = 0; i < leaf.count; ++i) {
      for (std::uint32_t j = i + 1; j < leaf.count; ++j) {
        if (overlap(boxes[i], boxes[j]) && !report(a_.order()[leaf.first + i], a_.order()[leaf.first + j])) {
          return false;
        }
      }
    }
    return true;
  }

  bool leaf_pair(const BvhNode& leaf_a, const BvhNode& leaf_b) {
    std::array<BvhBox, 8> boxes;
    for (std::uint32_t j = 0; j < leaf_b.count; ++j) boxes[j] = triangle_box(b_.corners(b_.order()[leaf_b.first + j]));
    for (std::uint32_t i = 0; i < leaf_a.count; ++i) {
      const std::uint32_t ta = a_.order()[leaf_a.first + i];
      const BvhBox box = triangle_box(a_.corners(ta));
      if (!overlap(box, leaf_b.box)) continue;
      for (std::uint32_t j = 0; j < leaf_b.count; ++j) {
        if (overlap(box, boxes[j]) && !report(ta, b_.order()[leaf_b.first + j])) return false;
      }
    }
    return true;
  }

  bool report(std::uint32_t ta, std::uint32_t tb) {
    const bool go_on = one_tree_ && tb < ta ? visit_(tb, ta, worker_) : visit_(ta, tb, worker_);
    if (!go_on) stopped_.store(true, std::memory_order_relaxed);
    return go_on;
  }

  const TriangleBvh& a_;
  const TriangleBvh& b_;
  bool one_tree_;
  const PairVisitor& visit_;
  std::atomic<bool>& stopped_;
  int worker_;
};

/// Replaces `task` by the tasks one level down that cover the same pairs (none when the boxes
/// are apart) in `next`; returns whether it could be split.
bool split_task(const TriangleBvh& a, const TriangleBvh& b, const PairTask& task, std::vector<PairTask>& next) {
  const BvhNode& na = a.nodes()[task.a];
  const BvhNode& nb = b.nodes()[task.b];
  if (task.self) {
    if (na.count > 0) {
      next.push_back(task);
      return false;
    }
    next.insert(next.end(),
                {{task.a + 1, task.a + 1, true}, {na.first, na.first, true}, {task.a + 1, na.first, false}});
    return true;
  }
  if (!overlap(na.box, nb.box)) return true;
  if (na.count > 0 && nb.count > 0) {
    next.push_back(task);
    return false;
  }
  if (open_first(na, nb)) {
    next.insert(next.end(), {{task.a + 1, task.b, false}, {na.first, task.b, false}});
  } else {
    next.insert(next.end(), {{task.a, task.b + 1, false}, {task.a, nb.first, false}});
  }
  return true;
}

bool walk(const TriangleBvh& a, const TriangleBvh& b, PairTask root, const PairVisitor& visit, int threads) {
  SWEEP_EXPECTS(threads >= 1, "threads >= 1");
  if (a.nodes().empty() || b.nodes().empty()) return true;
  std::vector<PairTask> tasks{root};
  const std::size_t target = threads > 1 ? kTasksPerThread * static_cast<std::size_t>(threads) : 1;
  for (bool split = true; split && tasks.size() < target;) {
    std::vector<PairTask> next;
    split = false;
    for (const PairTask& task : tasks) split = split_task(a, b, task, next) || split;
    tasks = std::move(next);
  }
  std::atomic<bool> stopped{false};
  parallel_chunks(tasks.size(), 1, threads, [&](std::size_t begin, std::size_t end, int worker) {
    PairWalk pairs(a, b, root.self, visit, stopped, worker);
    for (std::size_t t = begin; t < end; ++t) {
      if (!pairs.run(tasks[t])) return;
    }
  });
  return !stopped.load();
}

}  // namespace

bool for_each_overlapping_pair(const TriangleBvh& bvh, const PairVisitor& visit, int threads) {
  return walk(bvh, bvh, {0, 0, true}, visit, threads);
}

bool for_each_overlapping_pair(const TriangleBvh& first, const TriangleBvh& second, const PairVisitor& visit,
                               int threads) {
  return walk(first, second, {0, 0, false}, visit, threads);
}

}  // namespace sweep
