#include "app/viewer/curve_actions.hpp"

#include "app/viewer/actions.hpp"
#include "model/edit.hpp"

#include <string>
#include <utility>
#include <vector>

namespace sweep::viewer {

int selected_joint(const ViewerState& s) {
  const Object* curve = selected_control_curve(s);
  const int point = s.selection.point;
  if (curve == nullptr || point < 0 || point >= int(curve->as<PointsPart>().points.size())) return -1;
  return editor::joint_of(*curve, point);
}

editor::JointType selected_joint_type(const ViewerState& s) {
  const Object* curve = selected_control_curve(s);
  return s.curve_editing.joints.type(*curve, curve->id, selected_joint(s));
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
                  [object, moves = std::move(moves)](Document& d) { return move_points(d, object, moves); })) {
      return;
    }
  }
  const Object& after = *selected_control_curve(s);
  s.curve_editing.joints.set(after, id, joint, type);
  s.status = "joint " + std::to_string(joint) + " is " + std::string(editor::joint_type_label(type));
}

}  // namespace sweep::viewer
