#include "geometry/mesh/weld.hpp"

#include "base/precondition.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>
#include <unordered_map>

namespace sweep {
namespace {

struct Cell {
  std::int64_t x, y, z;
  bool operator==(const Cell&) const = default;
};

struct CellHash {
  std::size_t operator()(const Cell& c) const {
    std::uint64_t h = 1469598103934665603ull;
    for (const std::int64_t v : {c.x, c.y, c.z}) h = (h ^ static_cast<std::uint64_t>(v)) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

Cell cell_of(const glm::dvec3& p, double size) {
  return {static_cast<std::int64_t>(std::floor(p.x / size)), static_cast<std::int64_t>(std::floor(p.y / size)),
          static_cast<std::int64_t>(std::floor(p.z / size))};
}

}  // namespace

std::vector<std::uint32_t> weld_points(std::span<const glm::dvec3> points, double tolerance) {
  SWEEP_EXPECTS(tolerance > 0.0, "tolerance > 0");
  // Each cell keeps its first representative; a point joins the nearest cell's representative
  // within the tolerance, or becomes one. Coordinates are capped (limits.hpp), so cells fit.
  std::unordered_map<Cell, std::vector<std::uint32_t>, CellHash> cells;
  cells.reserve(points.size());
  std::vector<std::uint32_t> out(points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Cell c = cell_of(points[i], tolerance);
    std::uint32_t found = static_cast<std::uint32_t>(i);
    for (std::int64_t dx = -1; dx <= 1 && found == i; ++dx) {
      for (std::int64_t dy = -1; dy <= 1 && found == i; ++dy) {
        for (std::int64_t dz = -1; dz <= 1 && found == i; ++dz) {
          const auto it = cells.find({c.x + dx, c.y + dy, c.z + dz});
          if (it == cells.end()) continue;
          for (const std::uint32_t j : it->second) {
            if (glm::distance(points[i], points[j]) <= tolerance) {
              found = j;
              break;
            }
          }
        }
      }
    }
    out[i] = found;
    if (found == i) cells[c].push_back(found);
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
