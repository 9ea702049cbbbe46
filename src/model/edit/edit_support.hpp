#pragma once
// What the editing operations share (internal to src/core: edit.cpp, edit_create.cpp,
// edit_parameters.cpp): index and value checks that throw EditError with the user's message, the
// caps check, and the commit of a changed object.
#include "model/edit/edit.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

namespace sweep::edit_support {

/// A name as shown in a message.
std::string shown_name(std::string_view name);
/// 'NAME' (or 'kind#index') of object `index`, quoted for a message.
std::string quoted(const Document& doc, int index);
inline std::size_t to_size(int index) {
  return static_cast<std::size_t>(index);
}
inline int to_int(std::size_t index) {
  return static_cast<int>(index);
}
void check_object_index(const Document& doc, int object);
/// Checks that `object` is a control-point curve and returns it.
Object& control_point_curve(Document& doc, int object);
/// Checks that `object` has points one may move (a control-point curve, a patch or a cage).
Object& editable_points_object(Document& doc, int object);
void check_point_index(const Document& doc, int object, int point);
/// The position a curve of `kind` stores for `position` (z dropped for planar curves), after
/// checking that it is finite and within the coordinate cap.
glm::dvec3 checked_position(ObjectKind kind, const glm::dvec3& position);
/// Checks a new name for object `object` (-1: an object not in the document yet); "" is allowed.
void check_new_name(const Document& doc, int object, const std::string& name);
/// The samples and mesh vertices of a document, counted as the parser counts them, with
/// objects[replaced] taken to be `replacement` and `appended` added at the end (either may be
/// absent). Throws EditError naming the first cap exceeded. O(number of objects).
void check_caps(const Document& doc, int replaced, const Object* replacement, const Object* appended);
/// Throws EditError "surface 'S': expected ..." if object `object` (when a surface) or a surface
/// using it has a problem with the curves it refers to (check_surface_curves: graphs, closed
/// twists, rails). O(samples of those curves); nothing for a curve no surface uses.
void check_users(const Document& doc, int object);
/// Replaces objects[object] by `replacement` after checking the caps and check_users; a throw
/// leaves the document as it was.
Change commit(Document& doc, int object, Object&& replacement);

/// How many points a closed polygon of `kind` repeats at its end (its layout's seam_repeats).
std::size_t seam_repeats(ObjectKind kind);
/// The distinct points of a closed polygon (all but the repeats at the end).
std::vector<glm::dvec3> distinct_points(ObjectKind kind, const std::vector<glm::dvec3>& points);
/// A closed polygon from its distinct points: the first seam_repeats(kind) repeated at the end.
std::vector<glm::dvec3> closed_polygon(ObjectKind kind, std::vector<glm::dvec3> distinct);
/// Inserts `entries` (one group of the curve's layout, checked) before entry `before` of curve
/// `object`, rounded down to a group's start; inside the repeats of a closed curve it means before
/// the group they repeat, and the curve stays closed. Throws EditError for `before` out of range.
Change insert_group(Document& doc, int object, int before, const std::vector<glm::dvec3>& entries);

}  // namespace sweep::edit_support
