#include "geometry/mesh/polygon_triangulation.hpp"

#include "base/precondition.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <optional>

// Ear clipping (D. Eberly, "Triangulation by Ear Clipping", Geometric Tools, 2002). An ear is a
// strictly convex vertex whose triangle with its two neighbours holds no other vertex; clipping
// it leaves a simple polygon with one vertex fewer, and by Meisters' two-ears theorem ("Polygons
// have ears", Amer. Math. Monthly 82, 1975) a simple polygon with more than three vertices always
// has one. As Eberly shows, only reflex vertices need testing (a convex vertex inside the
// triangle implies a reflex one inside it), and clipping an ear changes the status of its two
// neighbours only, so the remaining vertices are a doubly linked ring whose ears wait in a queue:
// O(n r) for r reflex vertices, O(n) for a convex polygon.
//
// Degenerate profiles change three things:
//  - A collinear vertex (a straight run, a spike, a repeated point) counts as "blocking" like a
//    reflex one, since a diagonal through it would leave a T-junction in the cap; a blocking
//    vertex at the same place as a corner of the triangle (a repeated point) is ignored.
//  - A collinear vertex is itself a zero-area ear: clipping it changes neither the area nor the
//    boundary, and its triangle keeps every vertex in the cap. Strict ears go first, so these
//    thin triangles appear only where nothing else can be clipped.
//  - Rounding, or a self-intersecting input, can leave no ear at all. The queues are then
//    rebuilt from scratch (rounding can hide an ear from the neighbour updates), and if that
//    finds nothing either, the sharpest convex corner (smallest interior angle) is clipped: of
//    all corners it is the likeliest to be an ear that rounding hid, and its triangle is the
//    least likely to reach across the polygon. Each step clips one vertex, so the loop always
//    ends after n - 3 clips (O(n^3) at worst, as each may rebuild). The tests never see a
//    rebuild or a fallback on a simple polygon, collinear runs and repeated points included.
//
// A FIFO queue, where an entry is stale once its vertex's neighbours changed, clips every other
// vertex of a convex polygon in one round, then every other of the rest: the triangles stay
// balanced instead of fanning out of a single vertex into slivers.

namespace sweep {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

/// Twice the signed area of the triangle (a, b, c): positive if it runs counterclockwise.
double orientation(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c) {
  const glm::dvec2 ab = b - a, ac = c - a;
  return ab.x * ac.y - ab.y * ac.x;
}

/// The shape of a corner relative to the polygon's orientation.
enum class Corner : std::uint8_t { kConvex, kFlat, kReflex };

/// Whether a corner can stop a diagonal: reflex or collinear.
bool is_blocking(Corner c) {
  return c != Corner::kConvex;
}

/// A queued candidate: valid while the vertex's stamp is unchanged.
struct QueueEntry {
  std::uint32_t vertex;
  std::uint32_t stamp;
};

/// A FIFO queue of candidates in one preallocated vector.
struct CandidateQueue {
  std::vector<QueueEntry> entries;
  std::size_t head = 0;

  void clear() {
    entries.clear();
    head = 0;
  }
};

class EarClipper {
 public:
  explicit EarClipper(std::span<const glm::dvec2> polygon)
      : points_(polygon),
        sign_(polygon_twice_signed_area(polygon) < 0.0 ? -1.0 : 1.0),
        prev_(polygon.size()),
        next_(polygon.size()),
        corner_(polygon.size(), Corner::kConvex),
        stamp_(polygon.size(), 0),
        remaining_(static_cast<std::uint32_t>(polygon.size())) {
    for (std::uint32_t v = 0; v < remaining_; ++v) {
      prev_[v] = v == 0 ? remaining_ - 1 : v - 1;
      next_[v] = v + 1 == remaining_ ? 0 : v + 1;
    }
    // Between two rebuilds the queues get at most n entries plus two per clip: no reallocation.
    ears_.entries.reserve(3 * polygon.size());
    flats_.entries.reserve(3 * polygon.size());
    blocking_.reserve(polygon.size());
    triangles_.reserve(polygon.size() - 2);
  }

  std::vector<Triangle> run() {
    rebuild();
    while (remaining_ > 3) clip(choose());
    triangles_.push_back({prev_[first_], first_, next_[first_]});
    return std::move(triangles_);
  }

 private:
  /// v's corner between its current neighbours.
  Corner corner_shape(std::uint32_t v) const {
    const double turn = sign_ * orientation(points_[prev_[v]], points_[v], points_[next_[v]]);
    if (turn > 0.0) return Corner::kConvex;
    return turn < 0.0 ? Corner::kReflex : Corner::kFlat;
  }

  /// Records v's corner and keeps the blocking list in step.
  void set_corner(std::uint32_t v, Corner c) {
    const bool was_blocking = is_blocking(corner_[v]), now_blocking = is_blocking(c);
    if (was_blocking && !now_blocking) {
      std::erase(blocking_, v);
      blocking_shrank_ = true;
    } else if (!was_blocking && now_blocking) {
      blocking_.push_back(v);
    }
    corner_[v] = c;
  }

  /// Whether p lies inside or on the triangle (a, b, c), which has the polygon's orientation.
  bool inside_or_on(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c, const glm::dvec2& p) const {
    return sign_ * orientation(a, b, p) >= 0.0 && sign_ * orientation(b, c, p) >= 0.0 &&
           sign_ * orientation(c, a, p) >= 0.0;
  }

  /// Whether no blocking vertex other than the corners lies inside or on v's triangle.
  bool is_ear(std::uint32_t v) const {
    const std::uint32_t p = prev_[v], n = next_[v];
    const glm::dvec2 a = points_[p], b = points_[v], c = points_[n];
    // The box test first: most blocking vertices are far away, and it is 3-4 times faster.
    const glm::dvec2 low = glm::min(glm::min(a, b), c), high = glm::max(glm::max(a, b), c);
    for (const std::uint32_t q : blocking_) {
      const glm::dvec2 x = points_[q];
      if (x.x < low.x || x.x > high.x || x.y < low.y || x.y > high.y) continue;
      if (q == p || q == n || x == a || x == b || x == c) continue;
      if (inside_or_on(a, b, c, x)) return false;
    }
    return true;
  }

  /// Invalidates v's queued entries and queues it again if it is a strict or a zero-area ear.
  void enqueue(std::uint32_t v) {
    const QueueEntry entry{v, ++stamp_[v]};
    if (corner_[v] == Corner::kFlat) {
      flats_.entries.push_back(entry);
    } else if (corner_[v] == Corner::kConvex && is_ear(v)) {
      ears_.entries.push_back(entry);
    }
  }

  /// Classifies every remaining vertex from scratch and queues the ears.
  void rebuild() {
    ears_.clear();
    flats_.clear();
    std::uint32_t v = first_;
    for (std::uint32_t k = 0; k < remaining_; ++k, v = next_[v]) set_corner(v, corner_shape(v));
    for (std::uint32_t k = 0; k < remaining_; ++k, v = next_[v]) enqueue(v);
    blocking_shrank_ = false;
  }

  /// The next still valid entry of `queue`. Strict ears are tested again: a neighbour update may
  /// have made a vertex blocking since they were queued (only at spikes or self-intersections).
  std::optional<std::uint32_t> pop(CandidateQueue& queue) const {
    while (queue.head < queue.entries.size()) {
      const QueueEntry e = queue.entries[queue.head++];
      if (e.stamp != stamp_[e.vertex]) continue;
      if (corner_[e.vertex] == Corner::kFlat || is_ear(e.vertex)) return e.vertex;
    }
    return std::nullopt;
  }

  /// The vertex to clip next: a strict ear, else a zero-area one, else (after a rebuild finds
  /// neither) the sharpest convex corner.
  std::uint32_t choose() {
    for (;;) {
      if (const std::optional<std::uint32_t> v = pop(ears_)) return *v;
      if (const std::optional<std::uint32_t> v = pop(flats_)) return *v;
      // Neighbour updates miss an ear only where a blocking vertex stopped blocking.
      if (!blocking_shrank_) return sharpest_corner();
      rebuild();
    }
  }

  /// The remaining vertex whose corner turns the most in the polygon's direction.
  std::uint32_t sharpest_corner() const {
    std::uint32_t best = first_, v = first_;
    double best_turn = -std::numeric_limits<double>::infinity();
    for (std::uint32_t k = 0; k < remaining_; ++k, v = next_[v]) {
      const glm::dvec2 in = points_[v] - points_[prev_[v]], out = points_[next_[v]] - points_[v];
      const double turn = std::atan2(sign_ * (in.x * out.y - in.y * out.x), glm::dot(in, out));
      if (turn > best_turn) {
        best = v;
        best_turn = turn;
      }
    }
    return best;
  }

  /// Emits v's triangle, unlinks v and updates its neighbours.
  void clip(std::uint32_t v) {
    const std::uint32_t p = prev_[v], n = next_[v];
    triangles_.push_back({p, v, n});
    next_[p] = n;
    prev_[n] = p;
    set_corner(v, Corner::kConvex);  // leaves the blocking list
    ++stamp_[v];
    if (first_ == v) first_ = n;
    --remaining_;
    set_corner(p, corner_shape(p));
    set_corner(n, corner_shape(n));
    enqueue(p);
    enqueue(n);
  }

  std::span<const glm::dvec2> points_;
  double sign_;  // +1 for a counterclockwise (or zero-area) polygon, -1 for a clockwise one
  std::vector<std::uint32_t> prev_, next_;
  std::vector<Corner> corner_;
  std::vector<std::uint32_t> stamp_;
  std::vector<std::uint32_t> blocking_;  // the remaining reflex and collinear vertices
  bool blocking_shrank_ = false;         // since the last rebuild
  CandidateQueue ears_, flats_;
  std::vector<Triangle> triangles_;
  std::uint32_t first_ = 0;  // any remaining vertex
  std::uint32_t remaining_;
};

}  // namespace

std::vector<Triangle> triangulate_polygon(std::span<const glm::dvec2> polygon) {
  SWEEP_EXPECTS(polygon.size() <= std::numeric_limits<std::uint32_t>::max(), "fewer than 2^32 vertices");
  if (polygon.size() < 3) return {};
  return EarClipper(polygon).run();
}

double polygon_twice_signed_area(std::span<const glm::dvec2> polygon) {
  SWEEP_EXPECTS(polygon.size() <= std::numeric_limits<std::uint32_t>::max(), "fewer than 2^32 vertices");
  if (polygon.size() < 3) return 0.0;
  // Relative to the first vertex, so far-off coordinates do not cancel.
  double sum = 0.0;
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i) sum += orientation(polygon[0], polygon[i], polygon[i + 1]);
  return sum;
}

}  // namespace sweep
