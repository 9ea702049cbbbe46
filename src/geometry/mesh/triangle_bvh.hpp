#pragma once
// A bounding volume hierarchy over triangles (one Shell, or several numbered one after another),
// for the printability checks: which triangles may touch (intersections.hpp) and where a ray
// first meets the surface (wall_thickness.hpp). Axis-aligned boxes in double, a flat array of
// nodes in depth-first order; each node splits its triangles in two halves at the median
// centroid along the longest axis of the centroids' box, down to leaves of at most 4.
// The tree keeps views of the positions and indices it was built from, not copies: they must
// outlive it and not change.
#include "geometry/mesh/shell.hpp"
#include "geometry/mesh/triangle_intersection.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <span>
#include <vector>

namespace sweep {

/// An axis-aligned box; empty (low above high) until a point is added.
struct BvhBox {
  glm::dvec3 low{std::numeric_limits<double>::infinity()};
  glm::dvec3 high{-std::numeric_limits<double>::infinity()};
};

/// The box around every position of `shell` (empty: low above high).
BvhBox box_of(const Shell& shell);

/// A leaf (count > 0) holds the triangles order()[first, first + count); an inner node
/// (count == 0) has its two children at its own index + 1 and at `first`.
struct BvhNode {
  BvhBox box;
  std::uint32_t first = 0;
  std::uint32_t count = 0;
};

/// Triangles as positions and 3 indices into them per triangle.
struct TriangleSpan {
  std::span<const glm::dvec3> positions;
  std::span<const std::uint32_t> indices;
};

/// No triangle (a RaySkip that skips nothing, a RayHit that hit nothing).
inline constexpr std::uint32_t kNoTriangle = std::numeric_limits<std::uint32_t>::max();

/// The segment origin + t * direction, 0 <= t <= max_distance; direction of unit length.
struct Ray {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, 1.0};
  double max_distance = std::numeric_limits<double>::infinity();
};

/// Triangles a ray query passes through: `triangle` and, with `neighbours`, every triangle that
/// shares a vertex index with it (in the same part).
struct RaySkip {
  std::uint32_t triangle = kNoTriangle;
  bool neighbours = false;
};

struct RayHit {
  double distance = 0.0;
  std::uint32_t triangle = kNoTriangle;
};

/// Called with two triangles whose boxes overlap and the calling thread's worker index (in
/// [0, threads)); returns false to stop the traversal.
using PairVisitor = std::function<bool(std::uint32_t a, std::uint32_t b, int worker)>;

class TriangleBvh {
 public:
  /// A tree over no triangles.
  TriangleBvh() = default;

  /// A tree over the triangles of `parts`, numbered consecutively (part 0's first). Runs on
  /// `threads` threads; O(n log n) (1.6 million triangles: about 0.4 s on one thread, 0.25 s on two).
  /// Preconditions: each part's index count is a multiple of 3 and its indices are below its
  /// position count; fewer than 2^32 - 1 triangles in all; threads >= 1.
  explicit TriangleBvh(std::span<const TriangleSpan> parts, int threads = 1);

  /// A tree over the triangles of `shell` (numbered as in the shell); as above.
  explicit TriangleBvh(const Shell& shell, int threads = 1);
  TriangleBvh(Shell&&, int = 1) = delete;  // the tree would outlive the shell it views

  /// The nodes, root first (none when there are no triangles).
  std::span<const BvhNode> nodes() const { return nodes_; }

  /// Triangle numbers in leaf order: leaves index into this.
  std::span<const std::uint32_t> order() const { return order_; }

  std::size_t triangle_count() const { return order_.size(); }

  /// The corners of triangle `triangle`. Precondition: triangle < triangle_count(). O(1) for a
  /// tree of one part, O(log parts) otherwise.
  TriangleCorners corners(std::uint32_t triangle) const;

  /// Whether triangles `a` and `b` are in the same part and share a vertex index (or a == b).
  /// Preconditions: both below triangle_count().
  bool share_vertex(std::uint32_t a, std::uint32_t b) const;

  /// The nearest triangle the ray meets (from either side) at a distance at most
  /// ray.max_distance, leaving out `skip`; on equal distances the lower triangle number. Nearest
  /// child first, so typically O(log n).
  std::optional<RayHit> nearest_hit(const Ray& ray, RaySkip skip = {}) const;

 private:
  std::size_t part_of(std::uint32_t triangle) const;
  void build(int threads);
  void fit_boxes(int threads);
  void leaf_hit(const BvhNode& leaf, const Ray& ray, RaySkip skip, RayHit& best) const;

  std::vector<TriangleSpan> parts_;
  std::vector<std::uint32_t> part_starts_;  // the first triangle of each part
  std::vector<BvhNode> nodes_;
  std::vector<std::uint32_t> order_;
};

/// Calls visit(a, b, worker) once for every unordered pair of distinct triangles of `bvh` whose
/// boxes overlap (touching counts), with a < b. With threads > 1 `visit` is called from several
/// threads at once. Returns false if `visit` stopped it (other threads stop soon after).
/// Cost: proportional to the overlapping node pairs, about n log n for a surface.
/// Precondition: threads >= 1.
bool for_each_overlapping_pair(const TriangleBvh& bvh, const PairVisitor& visit, int threads = 1);

/// Calls visit(a, b, worker) once for every triangle a of `first` and b of `second` whose boxes
/// overlap; otherwise as above.
bool for_each_overlapping_pair(const TriangleBvh& first, const TriangleBvh& second, const PairVisitor& visit,
                               int threads = 1);

}  // namespace sweep
