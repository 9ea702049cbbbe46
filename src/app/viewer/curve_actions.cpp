#include "app/viewer/curve_actions.hpp"

#include "app/viewer/actions.hpp"
#include "base/number_text.hpp"
#include "editor/bezier_joints.hpp"
#include "editor/picking.hpp"
#include "model/edit/edit.hpp"
#include "model/edit/shown_points.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace sweep::viewer {

const Object* control_curve(const editor::EditSession& session, const editor::Selection& selection) {
  const int index = selection.index(session);
  if (index < 0) return nullptr;
  const Object& object = session.document().objects[std::size_t(index)];
  return has_editable_points(object.kind()) ? &object : nullptr;
}

int selected_joint(const editor::EditSession& session, const editor::Selection& selection) {
  const Object* curve = control_curve(session, selection);
  const int point = selection.point;
  if (curve == nullptr || point < 0 || point >= int(curve->as<PointsPart>().points.size())) return -1;
  return editor::joint_of(*curve, point);
}

editor::JointType selected_joint_type(const editor::EditSession& session, const editor::Selection& selection,
                                      const CurveEditing& editing) {
  const Object* curve = control_curve(session, selection);
  return editing.joints.type(*curve, curve->id, selected_joint(session, selection));
}

int selected_joint(const ViewerState& s) {
  return selected_joint(s.session, s.selection);
}

editor::JointType selected_joint_type(const ViewerState& s) {
  return selected_joint_type(s.session, s.selection, s.curve_editing);
}

void convert_selected_joint(ViewerState& s, editor::JointType type) {
  const int joint = selected_joint(s);
  if (joint < 0) return;
  const Object& curve = *selected_control_curve(s);
  const std::string label = "make joint " + std::to_string(joint) + " " + std::string(editor::joint_type_label(type));
  std::vector<PointMove> moves = editor::convert_joint(curve, joint, type);
  const editor::ObjectId id = curve.id;
  if (!moves.empty()) {
    const int object = s.selected();
    if (!run_edit(s, label,
                  [object, moves = std::move(moves)](Document& d) { return move_shown_points(d, object, moves); })) {
      return;
    }
  }
  const Object& after = *selected_control_curve(s);
  s.curve_editing.joints.set(after, id, joint, type);
  s.status = "joint " + std::to_string(joint) + " is " + std::string(editor::joint_type_label(type));
}

const editor::CurvatureComb* selected_comb(const editor::EditSession& session, const editor::Selection& selection,
                                           const editor::ViewStates& views, CurveEditing& editing) {
  const int index = selection.index(session);
  if (!editing.comb || index < 0) return nullptr;
  const Object& object = session.document().objects[std::size_t(index)];
  if (!is_curve(object.kind()) || !views.visible(object.id)) return nullptr;
  const EvaluatedObject& evaluated = session.scene().objects[std::size_t(index)];
  CombCache& cache = editing.comb_cache;
  const double factor = editing.comb_scale;
  if (cache.object != object.id || cache.revision != evaluated.revision || cache.factor != factor) {
    cache = {object.id, evaluated.revision, factor, editor::curvature_comb(object, evaluated.curve, factor)};
  }
  return &cache.comb;
}

const editor::CurvatureComb* selected_comb(ViewerState& s) {
  return selected_comb(s.session, s.selection, s.views, s.curve_editing);
}

void select_all_points(ViewerState& s) {
  const Object* curve = selected_control_curve(s);
  if (curve == nullptr) return;
  const int count = int(curve->as<PointsPart>().points.size());
  s.selection.group.select_all(count);
  if (s.selection.point < 0) s.selection.point = 0;
  s.selection.group.toggle(s.selection.point);  // makes it the active one, as A keeps it
  s.selection.group.toggle(s.selection.point);
  s.status = std::to_string(count) + " points selected";
}

std::vector<int> points_with_handles(const ViewerState& s) {
  const Object* curve = selected_control_curve(s);
  std::vector<int> points = s.selection.points();
  if (curve == nullptr) return points;
  const int count = int(curve->as<PointsPart>().points.size());
  const std::vector<int> chosen = points;
  for (int point : chosen) {
    // A joint's (or an open end's) handles are the points drag_moves carries with it.
    for (const PointMove& move : editor::drag_moves(*curve, point, shown_points(*curve)[std::size_t(point)],
                                                    editor::JointType::Corner, false)) {
      if (move.point >= 0 && move.point < count) points.push_back(move.point);
    }
    // A point's tangent (a Hermite's) turns and mirrors with it.
    const PointLayout& layout = point_layout(curve->kind());
    if (layout.is_position(std::size_t(point)) && point + 1 < count && !layout.is_position(std::size_t(point) + 1)) {
      points.push_back(point + 1);
    }
  }
  std::sort(points.begin(), points.end());
  points.erase(std::unique(points.begin(), points.end()), points.end());
  return points;
}

void mirror_selected_points(ViewerState& s, int axis) {
  const Object* curve = selected_control_curve(s);
  if (curve == nullptr || s.selection.points().size() < 2) return;
  editor::PointSelection chosen;
  const std::vector<int> points = points_with_handles(s);
  chosen.select(points);
  const std::vector<glm::dvec3> positions = shown_points(*curve);
  std::vector<PointMove> moves = editor::mirror_moves(positions, chosen, axis, editor::box_centre(positions, chosen),
                                                      is_planar_curve(curve->kind()));
  if (moves.empty()) {
    s.status = "a 2D curve has no z to mirror";
    return;
  }
  const int object = s.selected();
  const std::string label = std::string("mirror points in ") + "xyz"[axis];
  if (run_edit(s, label,
               [object, moves = std::move(moves)](Document& d) { return move_shown_points(d, object, moves); })) {
    s.status = label;
  }
}

void snap_selected_points(ViewerState& s) {
  const Object* curve = selected_control_curve(s);
  if (curve == nullptr || s.selection.points().empty()) return;
  const std::vector<glm::dvec3> positions = shown_points(*curve);
  const glm::bvec3 mask(true, true, !is_planar_curve(curve->kind()));
  std::map<int, glm::dvec3> targets;  // a joint's handles go along with it, unless selected themselves
  for (const int point : s.selection.points()) {
    const glm::dvec3 to = editor::snap_to_grid(positions[std::size_t(point)], s.snap_size, mask);
    for (const PointMove& move : editor::drag_moves(*curve, point, to, editor::JointType::Corner, false)) {
      targets.emplace(move.point, move.to);
    }
  }
  for (const int point : s.selection.points()) {
    targets[point] = editor::snap_to_grid(positions[std::size_t(point)], s.snap_size, mask);
  }
  std::vector<PointMove> moves;
  for (const auto& [point, to] : targets) moves.push_back({point, to});
  const int object = s.selected();
  const std::string label = "snap points to the grid";
  if (run_edit(s, label,
               [object, moves = std::move(moves)](Document& d) { return move_shown_points(d, object, moves); })) {
    const std::size_t count = s.selection.points().size();
    s.status = "snapped " + std::to_string(count) + (count == 1 ? " point" : " points") + " to the grid (" +
               number_text(s.snap_size) + ")";
  }
}

void convert_selected_curve(ViewerState& s, ObjectKind to) {
  const Object* curve = selected_control_curve(s);
  if (curve == nullptr || !is_curve(curve->kind())) return;
  const int object = s.selected();
  const double tolerance = 1e-3 * curve_extent(*curve);
  const std::string from(keyword(curve->kind()));
  const std::string target(keyword(to));
  Conversion result;
  if (!run_edit(s, "convert to " + target, [object, to, tolerance, &result](Document& d) {
        return convert_curve(d, object, to, tolerance, &result);
      })) {
    return;
  }
  s.selection.point = -1;
  s.status =
      "converted '" + display_name(s.doc(), object) + "' from " + from + " to " + target +
      (result.exact ? " exactly"
                    : " by a fit of " + std::to_string(points_of(result.curve).size()) + " points, largest deviation " +
                          number_text(result.deviation) + " (tolerance " + number_text(tolerance) + ")");
}

void request_transform(ViewerState& s, editor::TransformMode mode) {
  if (selected_control_curve(s) == nullptr || s.selection.points().empty()) return;
  s.curve_editing.requested = mode;
}

}  // namespace sweep::viewer
