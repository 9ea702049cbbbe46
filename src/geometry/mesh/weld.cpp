#include "geometry/mesh/weld.hpp"

#include "base/fnv1a.hpp"
#include "base/precondition.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <bit>
#include <cmath>

namespace sweep {
namespace {

struct Cell {
  std::int64_t x, y, z;
  bool operator==(const Cell&) const = default;
};

std::uint64_t hash_of(const Cell& c) {
  Fnv1a hash(kShortFnvOffsetBasis);
  for (const std::int64_t v : {c.x, c.y, c.z}) hash.add_word(static_cast<std::uint64_t>(v));
  const std::uint64_t h = hash.value();
  return h ^ (h >> 29);
}

std::int64_t cell_index(double v, double size) {
  return static_cast<std::int64_t>(std::floor(v / size));
}

Cell cell_of(const glm::dvec3& p, double size) {
  return {cell_index(p.x, size), cell_index(p.y, size), cell_index(p.z, size)};
}

/// The representatives filed by cell: an open-addressing table whose slots hold the last
/// representative filed in a cell + 1 (0: empty; the cell is the representative's own), and, per
/// representative, the one filed before it in its cell + 1. Flat arrays of 4-byte entries.
class CellTable {
 public:
  CellTable(std::span<const glm::dvec3> points, double size)
      : points_(points),
        size_(size),
        slots_(std::bit_ceil(std::max<std::size_t>(2 * points.size(), 16)), 0),
        next_(points.size(), 0) {}

  /// Calls visit(j) for every representative filed in `cell`, the latest first.
  template <class Visit>
  void each(const Cell& cell, Visit&& visit) const {
    for (std::uint32_t j = slots_[find(cell)]; j != 0; j = next_[j - 1]) visit(j - 1);
  }

  /// Files `point` as a representative of its cell.
  void file(std::uint32_t point) {
    std::uint32_t& head = slots_[find(cell_of(points_[point], size_))];
    next_[point] = head;
    head = point + 1;
  }

 private:
  std::size_t find(const Cell& cell) const {
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t i = hash_of(cell) & mask;; i = (i + 1) & mask) {
      if (slots_[i] == 0 || cell_of(points_[slots_[i] - 1], size_) == cell) return i;
    }
  }

  std::span<const glm::dvec3> points_;
  double size_;
  std::vector<std::uint32_t> slots_;
  std::vector<std::uint32_t> next_;
};

}  // namespace

std::vector<std::uint32_t> weld_points(std::span<const glm::dvec3> points, double tolerance) {
  SWEEP_EXPECTS(tolerance > 0.0, "tolerance > 0");
  // Cells eight times the tolerance wide: a point's ball meets one cell per axis, or two near a
  // face (one time in four): about two cells a point. Only
  // representatives are filed; a point joins the earliest within the tolerance, or becomes one.
  // Coordinates are capped (limits.hpp), so cells fit.
  const double size = 8.0 * tolerance;
  CellTable table(points, size);
  std::vector<std::uint32_t> out(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::dvec3& p = points[i];
    const Cell low{cell_index(p.x - tolerance, size), cell_index(p.y - tolerance, size),
                   cell_index(p.z - tolerance, size)};
    const Cell high{cell_index(p.x + tolerance, size), cell_index(p.y + tolerance, size),
                    cell_index(p.z + tolerance, size)};
    auto found = static_cast<std::uint32_t>(i);
    for (std::int64_t x = low.x; x <= high.x; ++x) {
      for (std::int64_t y = low.y; y <= high.y; ++y) {
        for (std::int64_t z = low.z; z <= high.z; ++z) {
          table.each({x, y, z}, [&](std::uint32_t j) {
            if (j < found && glm::distance(p, points[j]) <= tolerance) found = j;
          });
        }
      }
    }
    out[i] = found;
    if (found == i) table.file(found);
  }
  return out;
}

double points_extent(std::span<const glm::dvec3> points) {
  if (points.empty()) return 0.0;
  glm::dvec3 lo = points[0];
  glm::dvec3 hi = points[0];
  for (const glm::dvec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::distance(lo, hi);
}

}  // namespace sweep
