// Editing operations on a Document. Each operation checks everything first (indices, values,
// names, the caps of core/limits.hpp), builds the changed object aside, and only then commits it
// with a move, so a throw leaves the document exactly as it was (strong guarantee).
//
// The caps are checked with the O(number of objects) function check_caps below rather than with
// validate_document (which writes and re-reads the whole text), because numeric fields such as
// STEPS are dragged in the editor and edited every frame. move_point changes no count, so it only
// checks the position (O(1) per call plus its seam partners) and the surfaces that read the
// curve as a graph or a rail (check_users).
#include "model/edit/edit.hpp"

#include "model/curve_parameters.hpp"
#include "model/edit/edit_support.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include "geometry/subdivision/subdivision.hpp"
#include "geometry/surfaces/surface.hpp"
#include "model/file_limits.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <utility>

namespace sweep {

using namespace edit_support;

namespace {

/// Joint `joint` of `points` removed (see join_bezier_pieces for the handles' rule). Throws if a
/// new handle would leave the coordinate range.
std::vector<glm::dvec3> joined_points(const std::vector<glm::dvec3>& points, std::size_t joint) {
  const glm::dvec3& a0 = points[joint - 3];
  const glm::dvec3& a1 = points[joint - 2];
  const glm::dvec3& a2 = points[joint - 1];
  const glm::dvec3& m = points[joint];
  const glm::dvec3& b1 = points[joint + 1];
  const glm::dvec3& b2 = points[joint + 2];
  const glm::dvec3& b3 = points[joint + 3];
  // A split at t puts the joint at (1-t) a2 + t b1, so t = |m - a2| / (|m - a2| + |b1 - m|)
  // recovers it; the outer handles were a1 = a0 + t (p1 - a0) and b2 = b3 + (1-t) (p2 - b3).
  const double left = glm::length(m - a2);
  const double right = glm::length(b1 - m);
  double t = left + right > 0.0 ? left / (left + right) : 0.5;
  if (left == 0.0 || right == 0.0) {
    // A joint without one of its handles says nothing about t: take the chord-length ratio.
    const double chord_left = glm::length(m - a0);
    const double chord_right = glm::length(b3 - m);
    t = chord_left + chord_right > 0.0 ? chord_left / (chord_left + chord_right) : 0.5;
    if (t <= 0.0 || t >= 1.0) t = 0.5;
  }
  const glm::dvec3 p1 = a0 + (a1 - a0) / t;
  const glm::dvec3 p2 = b3 + (b2 - b3) / (1.0 - t);
  for (const glm::dvec3& p : {p1, p2}) {
    for (int axis = 0; axis < 3; ++axis) {
      if (!std::isfinite(p[axis]) || std::abs(p[axis]) > limits::kMaxCoordinate) {
        throw EditError("cannot join the pieces at point " + std::to_string(joint) +
                        ": the joined handles would be out of range (coordinates from -1e12 to 1e12)");
      }
    }
  }
  std::vector<glm::dvec3> result;
  result.reserve(points.size() - 3);
  result.insert(result.end(), points.begin(), points.begin() + static_cast<std::ptrdiff_t>(joint) - 2);
  result.push_back(p1);
  result.push_back(p2);
  result.insert(result.end(), points.begin() + static_cast<std::ptrdiff_t>(joint) + 3, points.end());
  return result;
}

/// What a point deletion that would leave too few points says, from the kind's layout: "a
/// B-spline needs at least 4 control points", "a closed Catmull-Rom curve needs at least 3
/// distinct points (besides the first, repeated)".
std::string too_few_points_message(ObjectKind kind, bool closed) {
  const PointLayout& layout = point_layout(kind);
  const std::string what(phrase(kind));  // "a Catmull-Rom curve"
  const std::string points = kind_info(kind).interpolating ? "points" : "control points";
  if (!closed) return what + " needs at least " + std::to_string(layout.least_open) + " " + points;
  const std::string repeats = layout.seam_repeats == layout.stride
                                  ? "the first, repeated"
                                  : "the " + std::to_string(layout.seam_repeats) + " it repeats";
  return "a closed " + what.substr(2) + " needs at least " + std::to_string(layout.least_closed) + " distinct " +
         points + " (besides " + repeats + ")";
}

/// The new tangent of a Hermite point inserted at group `at` of `groups` (points and tangents,
/// the distinct ones when closed): half the chord between its neighbours, as Catmull-Rom's.
glm::dvec3 neighbour_tangent(const std::vector<glm::dvec3>& groups, std::size_t at, const glm::dvec3& position,
                             bool closed) {
  const std::size_t count = groups.size() / 2;
  const glm::dvec3 before = at > 0 ? groups[2 * (at - 1)] : closed ? groups[2 * (count - 1)] : position;
  const glm::dvec3 after = at < count ? groups[2 * at] : closed ? groups[0] : position;
  return (after - before) / 2.0;
}

/// Checks that `joint` of curve `object` is a joint between two Bezier pieces.
void check_joint(const Document& doc, int object, int joint) {
  const Object& o = doc.objects[to_size(object)];
  if (!point_layout(o.kind()).has_joints()) {
    throw EditError("curve " + quoted(doc, object) + " is " + std::string(phrase(o.kind())) + " (" +
                    std::string(keyword(o.kind())) + "): only Bezier curves have pieces to join");
  }
  check_point_index(doc, object, joint);
  if (o.as<PointsPart>().points.size() == 4) {
    throw EditError("curve " + quoted(doc, object) + " has a single piece: there is no joint to remove");
  }
  if (joint == 0 || to_size(joint) == o.as<PointsPart>().points.size() - 1) {
    throw EditError("point " + std::to_string(joint) + " of " + quoted(doc, object) +
                    " is an end point: a Bezier curve keeps its end points");
  }
  if (joint % 3 != 0) {
    throw EditError("point " + std::to_string(joint) + " of " + quoted(doc, object) +
                    " is a handle: only joints between pieces (every third point) can be removed");
  }
}

}  // namespace

bool is_closed_polygon(const Object& curve) {
  // The curve's own basis decides (geometry/curves/curve.hpp's is_closed): what the editor keeps
  // closed is exactly what evaluates closed. O(1): move_point calls this on every drag frame.
  return is_curve(curve.kind()) && has_control_points(curve.kind()) && is_closed(describe_curve(curve));
}

std::vector<int> seam_partners(const Object& curve, int point) {
  const std::vector<glm::dvec3>& points = curve.as<PointsPart>().points;
  if (point < 0 || to_size(point) >= points.size()) {
    throw EditError("point " + std::to_string(point) + " is out of range: the curve has " +
                    std::to_string(points.size()) + " points");
  }
  if (curve.kind() == ObjectKind::BezierPatch || curve.kind() == ObjectKind::BSplinePatch) {
    // Patches share a point where their nets repeat it (a shared edge, a periodic seam, a pole):
    // every copy moves, so the surface does not tear.
    std::vector<int> same{point};
    const glm::dvec3 at = points[to_size(point)];
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (to_int(i) != point && points[i] == at) same.push_back(to_int(i));
    }
    return same;
  }
  if (!is_closed_polygon(curve)) return {point};
  // Entry i < r of a closed list of n is repeated as entry i + n - r (r: the layout's repeats).
  const int n = to_int(points.size());
  const int r = point_layout(curve.kind()).seam_repeats;
  if (point < r) return {point, point + n - r};
  if (point >= n - r) return {point, point - (n - r)};
  return {point};
}

Change move_point(Document& doc, int object, int point, const glm::dvec3& position) {
  Object& curve = editable_points_object(doc, object);
  check_point_index(doc, object, point);
  const glm::dvec3 stored = checked_position(curve.kind(), position);
  // Handles next to a closed Bezier's seam are not moved: the joint keeps whatever smoothness
  // the user gives it (see edit.hpp).
  std::vector<glm::dvec3>& points = curve.as<PointsPart>().points;
  const std::vector<glm::dvec3> before = points;
  for (int i : seam_partners(curve, point)) points[to_size(i)] = stored;
  try {
    check_users(doc, object);  // a scale or twist graph must stay a graph
  } catch (...) {
    doc.objects[to_size(object)].as<PointsPart>().points = before;
    throw;
  }
  return Change{{object}, false};
}

Change move_points(Document& doc, int object, std::span<const PointMove> moves) {
  Object& curve = editable_points_object(doc, object);
  std::vector<glm::dvec3> after = curve.as<PointsPart>().points;
  for (const PointMove& move : moves) {
    check_point_index(doc, object, move.point);
    const glm::dvec3 stored = checked_position(curve.kind(), move.to);
    for (int i : seam_partners(curve, move.point)) after[to_size(i)] = stored;
  }
  std::vector<glm::dvec3>& points = curve.as<PointsPart>().points;
  std::swap(points, after);  // `after` now holds the points before
  try {
    check_users(doc, object);
  } catch (...) {
    doc.objects[to_size(object)].as<PointsPart>().points = std::move(after);
    throw;
  }
  return Change{{object}, false};
}

Change set_steps_or_levels(Document& doc, int object, int steps) {
  check_object_index(doc, object);
  const Object& o = doc.objects[to_size(object)];
  if (o.kind() == ObjectKind::GeneralizedCylinder || o.kind() == ObjectKind::Birail) {
    throw EditError("surface " + quoted(doc, object) + " is " +
                    (o.kind() == ObjectKind::Birail ? "a birail surface (birail)" : "a generalized cylinder (gcyl)") +
                    ": it has no STEPS; it takes its samples from its curves");
  }
  if (o.kind() == ObjectKind::PolygonMesh) {
    throw EditError("surface " + quoted(doc, object) + " is a polygon cage (mesh): it has no STEPS");
  }
  if (is_curve(o.kind()) && !o.find<StepsPart>()) {
    throw EditError("curve " + quoted(doc, object) + " is a " + std::string(kind_info(o.kind()).label) +
                    ": it has no STEPS; it has one sample per point");
  }
  if (o.kind() == ObjectKind::Subdivision) {
    if (steps < 0 || steps > kMaxSubdivisionLevel) {
      throw EditError("LEVELS must be from 0 to " + std::to_string(kMaxSubdivisionLevel) + ", not " +
                      std::to_string(steps));
    }
    Object changed = o;
    changed.as<SubdivisionSurface>().levels = steps;
    return commit(doc, object, std::move(changed));
  }
  if (!steps_field(o)) {  // a material, a rider: nothing to sample
    throw EditError(std::string(kind_info(o.kind()).label) + " " + quoted(doc, object) + " has no STEPS");
  }
  if (steps < 1 || steps > limits::kMaxSteps) {
    throw EditError("STEPS must be from 1 to " + std::to_string(limits::kMaxSteps) + ", not " + std::to_string(steps));
  }
  Object changed = o;
  *steps_field(changed) = steps;
  return commit(doc, object, std::move(changed));
}

Change set_radius(Document& doc, int object, double radius) {
  check_object_index(doc, object);
  const Object& o = doc.objects[to_size(object)];
  if (o.kind() != ObjectKind::Circle) {
    throw EditError(quoted(doc, object) + " is not a circle (it is a " + std::string(keyword(o.kind())) +
                    "): it has no radius");
  }
  if (!(radius >= limits::kMinRadius && radius <= limits::kMaxCoordinate)) {
    throw EditError("the radius must be from 1e-12 to 1e12, not " + number_text(radius));
  }
  doc.objects[to_size(object)].as<RadiusPart>().radius = radius;  // no count changes: no cap to check
  return Change{{object}, false};
}

Change split_bezier_piece(Document& doc, int object, int piece, double t) {
  const Object& o = control_point_curve(doc, object);
  if (!point_layout(o.kind()).has_joints()) {
    throw EditError("curve " + quoted(doc, object) + " is " + std::string(phrase(o.kind())) + " (" +
                    std::string(keyword(o.kind())) + "): only Bezier curves are split into pieces");
  }
  const std::vector<glm::dvec3>& p = o.as<PointsPart>().points;
  const int pieces = to_int((p.size() - 1) / 3);
  if (piece < 0 || piece >= pieces) {
    throw EditError("piece " + std::to_string(piece) + " is out of range: curve " + quoted(doc, object) + " has " +
                    std::to_string(pieces) + (pieces == 1 ? " piece" : " pieces"));
  }
  if (!(t > 0.0 && t < 1.0)) {
    throw EditError("the split parameter must be strictly between 0 and 1, not " + number_text(t));
  }
  // de Casteljau's algorithm (P. de Casteljau, 1959; Farin, "Curves and Surfaces for CAGD",
  // ch. 4): the intermediate points of the evaluation at t are the control points of the two
  // halves, which trace exactly the original piece over [0, t] and [t, 1].
  const std::size_t first = 3 * to_size(piece);
  const glm::dvec3 p0 = p[first], p1 = p[first + 1], p2 = p[first + 2], p3 = p[first + 3];
  const double s = 1.0 - t;
  const glm::dvec3 p01 = s * p0 + t * p1, p12 = s * p1 + t * p2, p23 = s * p2 + t * p3;
  const glm::dvec3 p012 = s * p01 + t * p12, p123 = s * p12 + t * p23;
  const glm::dvec3 p0123 = s * p012 + t * p123;
  Object changed = o;
  std::vector<glm::dvec3>& split = changed.as<PointsPart>().points;
  split[first + 1] = p01;
  split[first + 2] = p012;
  const std::array<glm::dvec3, 3> inserted{p0123, p123, p23};
  split.insert(split.begin() + static_cast<std::ptrdiff_t>(first) + 3, inserted.begin(), inserted.end());
  return commit(doc, object, std::move(changed));
}

Change join_bezier_pieces(Document& doc, int object, int joint) {
  const Object& o = control_point_curve(doc, object);
  check_joint(doc, object, joint);
  Object changed = o;
  changed.as<PointsPart>().points = joined_points(o.as<PointsPart>().points, to_size(joint));
  return commit(doc, object, std::move(changed));
}

namespace {

void check_insert_index(const Document& doc, int object, int before) {
  const std::size_t n = points_of(doc.objects[to_size(object)]).size();
  if (before < 0 || to_size(before) > n) {
    throw EditError("cannot insert before point " + std::to_string(before) + ": curve " + quoted(doc, object) +
                    " has " + std::to_string(n) + " points (insert before 0 to " + std::to_string(n) + ")");
  }
}

}  // namespace

Change edit_support::insert_group(Document& doc, int object, int before, const std::vector<glm::dvec3>& entries) {
  check_insert_index(doc, object, before);
  const Object& o = doc.objects[to_size(object)];
  const std::size_t stride = point_layout(o.kind()).stride;
  const std::size_t at = to_size(before) - to_size(before) % stride;
  Object changed = o;
  std::vector<glm::dvec3>& points = changed.as<PointsPart>().points;
  if (is_closed_polygon(o)) {
    // Insert into the cycle of distinct points, then repeat the first ones again. Inserting
    // before one of the trailing repeats means before the point it repeats.
    std::vector<glm::dvec3> distinct = distinct_points(o.kind(), points);
    const std::size_t m = distinct.size();
    distinct.insert(distinct.begin() + static_cast<std::ptrdiff_t>(at > m ? at - m : at), entries.begin(),
                    entries.end());
    points = closed_polygon(o.kind(), std::move(distinct));
  } else {
    points.insert(points.begin() + static_cast<std::ptrdiff_t>(at), entries.begin(), entries.end());
  }
  return commit(doc, object, std::move(changed));
}

Change insert_bspline_point(Document& doc, int object, int before, const glm::dvec3& position) {
  const Object& o = control_point_curve(doc, object);
  const PointLayout& layout = point_layout(o.kind());
  if (layout.has_joints()) {
    throw EditError("curve " + quoted(doc, object) + " is a Bezier curve (" + std::string(keyword(o.kind())) +
                    "): split a piece to add points");
  }
  check_insert_index(doc, object, before);
  const glm::dvec3 stored = checked_position(o.kind(), position);
  std::vector<glm::dvec3> entries{stored};
  if (layout.unit == EditUnit::PointAndTangent) {
    const bool closed = is_closed_polygon(o);
    const std::vector<glm::dvec3> groups =
        closed ? distinct_points(o.kind(), o.as<PointsPart>().points) : o.as<PointsPart>().points;
    const std::size_t stride = layout.stride;
    const std::size_t at = to_size(before) / stride;
    const std::size_t count = groups.size() / stride;
    entries.push_back(neighbour_tangent(groups, at > count ? at - count : at, stored, closed));
  }
  return insert_group(doc, object, before, entries);
}

Change delete_point(Document& doc, int object, int point) {
  const Object& o = control_point_curve(doc, object);
  check_point_index(doc, object, point);
  const PointLayout& layout = point_layout(o.kind());
  Object changed = o;
  if (layout.has_joints()) {
    check_joint(doc, object, point);
    changed.as<PointsPart>().points = joined_points(o.as<PointsPart>().points, to_size(point));
    return commit(doc, object, std::move(changed));
  }
  // One group of the layout goes (a point; a Hermite point with its tangent); a closed curve
  // loses it from its distinct points and stays closed.
  const bool closed = is_closed_polygon(o);
  std::vector<glm::dvec3>& list = changed.as<PointsPart>().points;  // erased in place: no second copy
  if (closed) list = distinct_points(o.kind(), list);
  const std::size_t stride = layout.stride;
  const std::size_t groups = list.size() / stride;
  if (groups <= (closed ? layout.least_closed : layout.least_open)) {
    throw EditError(too_few_points_message(o.kind(), closed));
  }
  std::size_t at = to_size(point) / stride;
  if (at >= groups) at -= groups;  // a trailing repeat: the group it repeats
  list.erase(list.begin() + static_cast<std::ptrdiff_t>(at * stride),
             list.begin() + static_cast<std::ptrdiff_t>((at + 1) * stride));
  if (closed) list = closed_polygon(o.kind(), std::move(list));
  return commit(doc, object, std::move(changed));
}

/// "surface", "surfaces", "rider", "riders", or "objects" for surfaces and riders together.
static std::string users_word(const Document& doc, const std::vector<int>& users) {
  const auto rider = [&doc](int i) { return is_rider(doc.objects[to_size(i)].kind()); };
  const bool all_riders = std::all_of(users.begin(), users.end(), rider);
  const bool no_riders = std::none_of(users.begin(), users.end(), rider);
  if (!all_riders && !no_riders) return "objects";
  return std::string(all_riders ? "rider" : "surface") + (users.size() == 1 ? "" : "s");
}

Change replace_objects(Document& doc, const Document& replacement) {
  if (doc.objects == replacement.objects) return {};
  std::vector<Object> objects;
  objects.reserve(replacement.objects.size());
  for (const Object& wanted : replacement.objects) {
    const auto same = std::find_if(doc.objects.begin(), doc.objects.end(),
                                   [&wanted](const Object& o) { return o == wanted && !o.name.empty(); });
    if (same != doc.objects.end()) {
      objects.push_back(*same);
    } else {
      Object fresh = wanted;
      fresh.location = {};  // not in the document's text: written as a new object
      fresh.id = 0;
      objects.push_back(std::move(fresh));
    }
  }
  doc.objects = std::move(objects);
  return Change{{}, true};
}

Change rename_object(Document& doc, int object, const std::string& name) {
  check_object_index(doc, object);
  check_new_name(doc, object, name);
  if (name.empty()) {
    // References are written by name, so a used curve must keep one.
    for (std::size_t i = to_size(object) + 1; i < doc.objects.size(); ++i) {
      const auto refs = references(doc.objects[i]);
      if (std::find(refs.begin(), refs.end(), object) != refs.end()) {
        throw EditError("cannot remove the name of " + quoted(doc, object) + ": " + users_word(doc, {to_int(i)}) + " " +
                        quoted(doc, to_int(i)) + " uses it");
      }
    }
  }
  doc.objects[to_size(object)].name = name;
  return Change{{object}, false};
}

Change delete_object(Document& doc, int object) {
  check_object_index(doc, object);
  std::vector<int> users;
  for (std::size_t i = to_size(object) + 1; i < doc.objects.size(); ++i) {
    const auto refs = references(doc.objects[i]);
    if (std::find(refs.begin(), refs.end(), object) != refs.end()) users.push_back(to_int(i));
  }
  if (!users.empty()) {
    std::string list;
    for (std::size_t k = 0; k < users.size(); ++k) {
      if (k > 0) list += k + 1 == users.size() ? " and " : ", ";
      list += quoted(doc, users[k]);
    }
    throw EditError("cannot delete " + quoted(doc, object) + ": " + users_word(doc, users) + " " + list +
                    (users.size() == 1 ? " uses it" : " use it"));
  }
  // Nothing below can throw: erase shifts the later objects, whose references move with them.
  doc.objects.erase(doc.objects.begin() + object);
  for (Object& o : doc.objects) {
    for (int* r : reference_slots(o)) {
      if (*r > object) --*r;
    }
  }
  return Change{{}, true};
}

}  // namespace sweep
