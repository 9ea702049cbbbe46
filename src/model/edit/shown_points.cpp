#include "model/edit/shown_points.hpp"

#include "base/precondition.hpp"

namespace sweep {
namespace {

bool has_tangents(const PointLayout& layout) {
  for (std::size_t k = 0; k < layout.stride; ++k) {
    if (!layout.is_position(k)) return true;
  }
  return false;
}

}  // namespace

std::vector<glm::dvec3> shown_points(const Object& object) {
  const std::span<const glm::dvec3> points = points_of(object);
  std::vector<glm::dvec3> shown(points.begin(), points.end());
  const PointLayout& layout = point_layout(object.kind());
  for (std::size_t i = 1; i < shown.size(); ++i) {
    if (!layout.is_position(i)) shown[i] = points[i - 1] + points[i] / kTangentThirds;
  }
  return shown;
}

std::vector<glm::dvec3> control_polygon(const Object& object) {
  const PointLayout& layout = point_layout(object.kind());
  if (layout.polygon == PolygonStyle::None) return {};
  const std::vector<glm::dvec3> shown = shown_points(object);
  if (layout.polygon == PolygonStyle::Through) return shown;
  std::vector<glm::dvec3> polygon;
  for (std::size_t i = 0; i < shown.size(); ++i) {
    polygon.push_back(shown[i]);
    if (!layout.is_position(i)) polygon.push_back(shown[i - 1]);  // back from the handle to its point
  }
  return polygon;
}

std::vector<PointMove> stored_moves(const Object& object, std::span<const PointMove> moves) {
  std::vector<PointMove> stored(moves.begin(), moves.end());
  const PointLayout& layout = point_layout(object.kind());
  if (!has_tangents(layout)) return stored;
  const std::span<const glm::dvec3> points = points_of(object);
  std::vector<glm::dvec3> after(points.begin(), points.end());
  for (const PointMove& move : moves) {
    SWEEP_EXPECTS(move.point >= 0 && static_cast<std::size_t>(move.point) < points.size(), "a move of a point");
    if (layout.is_position(static_cast<std::size_t>(move.point))) after[static_cast<std::size_t>(move.point)] = move.to;
  }
  for (PointMove& move : stored) {
    const auto i = static_cast<std::size_t>(move.point);
    if (i > 0 && !layout.is_position(i)) move.to = (move.to - after[i - 1]) * kTangentThirds;
  }
  return stored;
}

Change move_shown_points(Document& doc, int object, std::span<const PointMove> moves) {
  if (object < 0 || static_cast<std::size_t>(object) >= doc.objects.size()) return move_points(doc, object, moves);
  for (const PointMove& move : moves) {
    if (move.point < 0 || static_cast<std::size_t>(move.point) >= points_of(doc.objects[std::size_t(object)]).size()) {
      return move_points(doc, object, moves);  // says which index is out of range
    }
  }
  return move_points(doc, object, stored_moves(doc.objects[static_cast<std::size_t>(object)], moves));
}

}  // namespace sweep
