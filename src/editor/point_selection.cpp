#include "editor/point_selection.hpp"

#include "base/precondition.hpp"

#include <algorithm>

namespace sweep::editor {
namespace {

bool all_within(std::span<const int> indices, std::size_t count) {
  return std::all_of(indices.begin(), indices.end(), [count](int i) { return i >= 0 && std::size_t(i) < count; });
}

}  // namespace

void PointSelection::click(int point) {
  SWEEP_EXPECTS(point >= 0, "a point index is not negative");
  points_ = {point};
  active_ = point;
}

void PointSelection::toggle(int point) {
  SWEEP_EXPECTS(point >= 0, "a point index is not negative");
  const auto at = std::lower_bound(points_.begin(), points_.end(), point);
  if (at != points_.end() && *at == point) {
    points_.erase(at);
    if (active_ == point) active_ = -1;
    return;
  }
  points_.insert(at, point);
  active_ = point;
}

void PointSelection::select_all(int count) {
  SWEEP_EXPECTS(count >= 0, "a point count is not negative");
  points_.resize(std::size_t(count));
  for (int i = 0; i < count; ++i) points_[std::size_t(i)] = i;
  if (active_ >= count) active_ = -1;
}

void PointSelection::select(std::span<const int> points, bool add) {
  SWEEP_EXPECTS(std::all_of(points.begin(), points.end(), [](int i) { return i >= 0; }),
                "point indices are not negative");
  if (!add) points_.clear();
  points_.insert(points_.end(), points.begin(), points.end());
  std::sort(points_.begin(), points_.end());
  points_.erase(std::unique(points_.begin(), points_.end()), points_.end());
  if (!contains(active_)) active_ = -1;
}

void PointSelection::fix(int count) {
  points_.erase(std::lower_bound(points_.begin(), points_.end(), std::max(count, 0)), points_.end());
  if (active_ >= count) active_ = -1;
}

bool PointSelection::contains(int point) const {
  return std::binary_search(points_.begin(), points_.end(), point);
}

std::vector<int> points_in_rect(const ScreenMapping& mapping, std::span<const glm::dvec3> points, glm::dvec2 corner_a,
                                glm::dvec2 corner_b) {
  const glm::dvec2 low = glm::min(corner_a, corner_b);
  const glm::dvec2 high = glm::max(corner_a, corner_b);
  std::vector<int> inside;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::optional<glm::dvec2> pixel = to_screen(mapping, points[i]);
    if (!pixel) continue;
    if (pixel->x >= low.x && pixel->x <= high.x && pixel->y >= low.y && pixel->y <= high.y) {
      inside.push_back(static_cast<int>(i));
    }
  }
  return inside;
}

glm::dvec3 centre(std::span<const glm::dvec3> points, const PointSelection& selection) {
  SWEEP_EXPECTS(!selection.empty(), "some point is selected");
  SWEEP_EXPECTS(all_within(selection.points(), points.size()), "the selected points are points of the curve");
  std::vector<glm::dvec3> distinct;
  distinct.reserve(selection.size());
  for (int i : selection.points()) distinct.push_back(points[std::size_t(i)]);
  // Sorted, so equal positions meet and the sum does not depend on the order of the indices.
  const auto less = [](const glm::dvec3& a, const glm::dvec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  };
  std::sort(distinct.begin(), distinct.end(), less);
  distinct.erase(std::unique(distinct.begin(), distinct.end()), distinct.end());
  glm::dvec3 sum(0.0);
  for (const glm::dvec3& p : distinct) sum += p;
  return sum / static_cast<double>(distinct.size());
}

glm::dvec3 box_centre(std::span<const glm::dvec3> points, const PointSelection& selection) {
  SWEEP_EXPECTS(!selection.empty(), "some point is selected");
  SWEEP_EXPECTS(all_within(selection.points(), points.size()), "the selected points are points of the curve");
  glm::dvec3 low = points[std::size_t(selection.points().front())];
  glm::dvec3 high = low;
  for (int i : selection.points()) {
    low = glm::min(low, points[std::size_t(i)]);
    high = glm::max(high, points[std::size_t(i)]);
  }
  return (low + high) * 0.5;
}

std::vector<PointMove> mirror_moves(std::span<const glm::dvec3> points, const PointSelection& selection, int axis,
                                    const glm::dvec3& pivot, bool planar) {
  SWEEP_EXPECTS(axis >= 0 && axis <= 2, "the axis is x, y or z");
  SWEEP_EXPECTS(all_within(selection.points(), points.size()), "the selected points are points of the curve");
  std::vector<PointMove> moves;
  if (planar && axis == 2) return moves;
  moves.reserve(selection.size());
  for (int i : selection.points()) {
    glm::dvec3 to = points[std::size_t(i)];
    // 2 pivot is exact, so mirroring twice gives the point back whenever one mirror is exact.
    to[axis] = 2.0 * pivot[axis] - to[axis];
    moves.push_back({i, to});
  }
  return moves;
}

}  // namespace sweep::editor
