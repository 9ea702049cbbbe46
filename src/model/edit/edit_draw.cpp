// Curves drawn point by point (the viewer's pen, editor/pen.hpp): a new curve of a kind with its
// whole point list, and a curve's point list replaced, each checked as the reader checks a file.
#include "model/edit/edit.hpp"
#include "model/edit/edit_support.hpp"

#include <utility>

namespace sweep {

using namespace edit_support;

namespace {

/// `points` as a curve of `kind` stores them (z dropped for a planar kind), each checked.
std::vector<glm::dvec3> checked_points(ObjectKind kind, std::vector<glm::dvec3> points) {
  for (glm::dvec3& p : points) p = checked_position(kind, p);
  return points;
}

}  // namespace

int add_drawn_curve(Document& doc, ObjectKind kind, const std::string& name, std::vector<glm::dvec3> points) {
  Object curve(kind);
  if (point_layout(kind).role != PointRole::ControlPoints || !is_curve(kind)) {
    throw EditError(std::string(keyword(kind)) + " is not a curve of control points: it cannot be drawn");
  }
  check_new_name(doc, -1, name);
  curve.name = name;
  if (auto* steps = curve.find<StepsPart>()) steps->steps = 16;  // as the templates
  curve.as<PointsPart>().points = checked_points(kind, std::move(points));
  if (const std::string problem = count_problem(curve); !problem.empty()) {
    throw EditError("a drawn " + std::string(keyword(kind)) + ": " + problem);
  }
  check_caps(doc, -1, nullptr, &curve);
  doc.objects.push_back(std::move(curve));
  return to_int(doc.objects.size() - 1);
}

Change set_curve_points(Document& doc, int object, std::vector<glm::dvec3> points) {
  const Object& o = control_point_curve(doc, object);
  Object changed = o;
  changed.as<PointsPart>().points = checked_points(o.kind(), std::move(points));
  return commit(doc, object, std::move(changed));
}

}  // namespace sweep
