// Ends that extend: a point added past either end of an open control-point curve, as each kind's
// point layout says (a B-spline, Catmull-Rom, Kochanek-Bartels or polyline point; a Hermite point
// with its tangent; a whole Bezier piece whose first handle mirrors the one across the joint, so
// the joint stays smooth).
#include "model/edit/edit.hpp"
#include "model/edit/edit_support.hpp"

#include <glm/geometric.hpp>

#include <optional>
#include <vector>

namespace sweep {

using namespace edit_support;

namespace {

/// The Bezier piece added past the end at `end` (points[end]) whose handle is points[handle]:
/// its first handle mirrors that one across the joint; it ends at `to`, else one handle length
/// three times further on, straight; its second handle a third of the way back from its end
/// towards the joint. Returned in the order from the joint outwards.
std::vector<glm::dvec3> bezier_extension(const std::vector<glm::dvec3>& points, std::size_t end, std::size_t handle,
                                         std::size_t far_end, const std::optional<glm::dvec3>& to) {
  const glm::dvec3 joint = points[end];
  glm::dvec3 step = joint - points[handle];
  if (glm::length(step) == 0.0) step = (joint - points[far_end]) / 3.0;  // a handle on its joint: the chord
  if (glm::length(step) == 0.0) throw EditError("the end piece has no length: there is no direction to extend in");
  const glm::dvec3 first = joint + step;
  const glm::dvec3 last = to ? *to : joint + 3.0 * step;
  return {first, last + (first - last) / 3.0, last};
}

}  // namespace

Change extend_curve(Document& doc, int object, CurveEnd end, const std::optional<glm::dvec3>& to) {
  const Object& o = control_point_curve(doc, object);
  if (is_closed_polygon(o)) {
    throw EditError("curve " + quoted(doc, object) + " is closed: it has no end to extend");
  }
  const PointLayout& layout = point_layout(o.kind());
  const std::vector<glm::dvec3>& points = o.as<PointsPart>().points;
  const std::size_t n = points.size();
  const std::optional<glm::dvec3> target = to ? std::optional(checked_position(o.kind(), *to)) : std::nullopt;
  const bool start = end == CurveEnd::Start;
  if (layout.has_joints()) {
    Object changed = o;
    std::vector<glm::dvec3>& list = changed.as<PointsPart>().points;
    std::vector<glm::dvec3> piece =
        start ? bezier_extension(points, 0, 1, 3, target) : bezier_extension(points, n - 1, n - 2, n - 4, target);
    for (glm::dvec3& p : piece) p = checked_position(o.kind(), p);
    if (start) {
      list.insert(list.begin(), piece.rbegin(), piece.rend());
    } else {
      list.insert(list.end(), piece.begin(), piece.end());
    }
    return commit(doc, object, std::move(changed));
  }
  // One group: the end point (and a Hermite tangent) one step past the end, or at `to`.
  const std::size_t stride = layout.stride;
  const std::size_t last = n - stride;
  const glm::dvec3 end_point = start ? points[0] : points[last];
  const glm::dvec3 neighbour = start ? points[stride] : points[last - stride];
  const glm::dvec3 position = target ? *target : end_point + (end_point - neighbour);
  return insert_bspline_point(doc, object, start ? 0 : int(n), position);
}

int end_point(const Object& curve, CurveEnd end) {
  const std::size_t n = curve.as<PointsPart>().points.size();
  const PointLayout& layout = point_layout(curve.kind());
  // A Bezier's list ends on a joint (J H H J ... J); the others end on a whole group.
  return end == CurveEnd::Start ? 0 : int(layout.has_joints() ? n - 1 : n - layout.stride);
}

std::optional<CurveEnd> end_at(const Object& curve, int point) {
  const auto* points = curve.find<PointsPart>();
  const PointLayout& layout = point_layout(curve.kind());
  if (points == nullptr || layout.role != PointRole::ControlPoints || is_closed_polygon(curve) || point < 0) {
    return std::nullopt;
  }
  if (point == 0) return CurveEnd::Start;
  if (point == end_point(curve, CurveEnd::End)) return CurveEnd::End;
  return std::nullopt;
}

}  // namespace sweep
