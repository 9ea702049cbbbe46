// The continuity rules of a Bezier curve's joints: classification, drags and conversions
// (bezier_joints.hpp).
#include "editor/bezier_joints.hpp"

#include "base/precondition.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace sweep::editor {

namespace {

bool is_bezier(const Object& curve) {
  return point_layout(curve.kind()).has_joints();
}

const std::vector<glm::dvec3>& curve_points(const Object& curve) {
  return curve.as<PointsPart>().points;
}

int point_count(const Object& curve) {
  return static_cast<int>(curve_points(curve).size());
}

const glm::dvec3& point_at(const Object& curve, int index) {
  return curve_points(curve)[static_cast<std::size_t>(index)];
}

/// True if `joint` is one of bezier_joints(curve), without building the list.
bool is_joint(const Object& curve, int joint) {
  if (!is_bezier(curve)) return false;
  const int n = point_count(curve);
  if (joint == 0) return n >= 4 && is_closed_polygon(curve);
  return joint % 3 == 0 && joint >= 3 && joint <= n - 4;
}

/// The in and out handles of joint `joint` (the seam's: n-2 and 1).
std::pair<int, int> handles_of(const Object& curve, int joint) {
  if (joint == 0) return {point_count(curve) - 2, 1};
  return {joint - 1, joint + 1};
}

/// The handles' vectors (joint - in) and (out - joint).
std::pair<glm::dvec3, glm::dvec3> handle_vectors(const Object& curve, int joint) {
  const auto [in, out] = handles_of(curve, joint);
  const glm::dvec3& at = point_at(curve, joint);
  return {at - point_at(curve, in), point_at(curve, out) - at};
}

bool has_zero_handle(const Object& curve, int joint) {
  const auto [a, b] = handle_vectors(curve, joint);
  return !(glm::length(a) > 0.0) || !(glm::length(b) > 0.0);
}

/// `moves` with `delta` added to point `index` (the translation of a joint's or end's handle).
void translate(std::vector<PointMove>& moves, const Object& curve, int index, const glm::dvec3& delta) {
  moves.push_back({index, point_at(curve, index) + delta});
}

/// Where the handle opposite the dragged one goes, by the rule of `type`; nothing for a corner
/// and for a smooth joint whose dragged handle is on the joint.
void follow(std::vector<PointMove>& moves, const Object& curve, int joint, int opposite, const glm::dvec3& to,
            JointType type) {
  const glm::dvec3& at = point_at(curve, joint);
  if (type == JointType::Symmetric) {
    moves.push_back({opposite, 2.0 * at - to});
  } else if (type == JointType::Smooth) {
    const glm::dvec3 along = at - to;
    const double length = glm::length(along);
    if (!(length > 0.0)) return;  // no direction: the opposite handle stays
    const double keep = glm::length(point_at(curve, opposite) - at);
    moves.push_back({opposite, at + along * (keep / length)});
  }
}

/// The direction a smooth joint's handles take (convert_joint). Precondition: la > 0 or lb > 0.
glm::dvec3 smooth_direction(const glm::dvec3& a, double la, const glm::dvec3& b, double lb) {
  if (!(la > 0.0)) return b / lb;
  if (!(lb > 0.0)) return a / la;
  const glm::dvec3 sum = a / la + b / lb;
  const double length = glm::length(sum);
  // A cusp (the handles pointing back on each other) has no bisector: take the out direction.
  return length > 1e-6 ? sum / length : b / lb;
}

}  // namespace

std::string_view joint_type_label(JointType type) {
  switch (type) {
    case JointType::Corner:
      return "corner";
    case JointType::Smooth:
      return "smooth";
    case JointType::Symmetric:
      return "symmetric";
  }
  return "corner";
}

std::vector<int> bezier_joints(const Object& curve) {
  std::vector<int> joints;
  if (!is_bezier(curve)) return joints;
  const int n = point_count(curve);
  if (n >= 4 && is_closed_polygon(curve)) joints.push_back(0);
  for (int joint = 3; joint <= n - 4; joint += 3) joints.push_back(joint);
  return joints;
}

int joint_of(const Object& curve, int point) {
  SWEEP_EXPECTS(curve.find<PointsPart>() != nullptr, "the object has points");
  const int n = point_count(curve);
  SWEEP_EXPECTS(point >= 0 && point < n, "the point is one of the curve's");
  if (!is_bezier(curve) || n < 4) return -1;
  if (point <= 1 || point >= n - 2) return is_closed_polygon(curve) ? 0 : -1;
  switch (point % 3) {
    case 0:
      return point;
    case 1:
      return point - 1;
    default:
      return point + 1;
  }
}

JointType classify_joint(const Object& curve, int joint) {
  SWEEP_EXPECTS(is_joint(curve, joint), "the point is a joint of a Bezier curve");
  const auto [a, b] = handle_vectors(curve, joint);
  const double la = glm::length(a);
  const double lb = glm::length(b);
  if (!(la > 0.0) || !(lb > 0.0)) return JointType::Corner;
  // atan2 of |a x b| and a . b is accurate near 0 (acos of the normalised dot product is not).
  const double angle = std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
  if (!(angle <= kCollinearAngle)) return JointType::Corner;
  return std::abs(la - lb) <= kEqualLengthRatio * std::max(la, lb) ? JointType::Symmetric : JointType::Smooth;
}

std::vector<PointMove> drag_moves(const Object& curve, int point, const glm::dvec3& to, JointType type,
                                  bool break_rule) {
  SWEEP_EXPECTS(curve.find<PointsPart>() != nullptr, "the object has points");
  const int n = point_count(curve);
  SWEEP_EXPECTS(point >= 0 && point < n, "the point is one of the curve's");
  const bool planar = is_planar_curve(curve.kind());
  const glm::dvec3 target = planar ? glm::dvec3(to.x, to.y, 0.0) : to;
  std::vector<PointMove> moves{{point, target}};
  if (break_rule || !is_bezier(curve) || n < 4) return moves;
  const glm::dvec3 delta = target - point_at(curve, point);
  const int joint = joint_of(curve, point);
  if (joint < 0) {  // an open curve's end carries its handle; the end's handle moves alone
    if (point == 0) translate(moves, curve, 1, delta);
    if (point == n - 1) translate(moves, curve, n - 2, delta);
    return moves;
  }
  const auto [in, out] = handles_of(curve, joint);
  if (point % 3 == 0) {  // the joint (or the seam's repeat n-1): both handles translate
    translate(moves, curve, in, delta);
    translate(moves, curve, out, delta);
    return moves;
  }
  follow(moves, curve, joint, point == in ? out : in, target, type);
  return moves;
}

std::vector<PointMove> convert_joint(const Object& curve, int joint, JointType to) {
  SWEEP_EXPECTS(is_joint(curve, joint), "the point is a joint of a Bezier curve");
  const auto [a, b] = handle_vectors(curve, joint);
  double la = glm::length(a);
  double lb = glm::length(b);
  if (to == JointType::Corner || (!(la > 0.0) && !(lb > 0.0))) return {};
  const glm::dvec3 direction = smooth_direction(a, la, b, lb);
  if (to == JointType::Symmetric) la = lb = 0.5 * (la + lb);
  const auto [in, out] = handles_of(curve, joint);
  const glm::dvec3& at = point_at(curve, joint);
  return {{in, at - direction * la}, {out, at + direction * lb}};
}

JointType JointTypes::type(const Object& curve, ObjectId id, int joint) const {
  const JointType classified = classify_joint(curve, joint);
  const auto object = chosen_.find(id);
  if (object == chosen_.end() || object->second.point_count != curve_points(curve).size()) return classified;
  const auto found = object->second.joints.find(joint);
  if (found == object->second.joints.end()) return classified;
  const JointType chosen = found->second;
  const bool allowed = chosen <= classified || (chosen == JointType::Smooth && has_zero_handle(curve, joint));
  return allowed ? chosen : classified;
}

void JointTypes::set(const Object& curve, ObjectId id, int joint, JointType type) {
  SWEEP_EXPECTS(is_joint(curve, joint), "the point is a joint of a Bezier curve");
  Chosen& object = chosen_[id];
  if (object.point_count != curve_points(curve).size()) object = Chosen{curve_points(curve).size(), {}};
  object.joints[joint] = type;
}

}  // namespace sweep::editor
