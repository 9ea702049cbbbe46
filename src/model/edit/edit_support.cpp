#include "model/edit/edit_support.hpp"

#include "geometry/subdivision/subdivision.hpp"
#include "geometry/surfaces/birail.hpp"
#include "geometry/surfaces/surface.hpp"
#include "geometry/surfaces/sweep_controls.hpp"
#include "model/caps.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/file_limits.hpp"
#include "model/surface_validation.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>

namespace sweep::edit_support {

/// A name as shown in a message.
std::string shown_name(std::string_view name) {
  return printable_excerpt(name, 40);
}

std::string quoted(const Document& doc, int index) {
  // Appending rather than "'" + s + "'", which trips GCC 12's false -Wrestrict at -O3.
  std::string text(1, '\'');
  text.append(display_name(doc, index));
  text.push_back('\'');
  return text;
}

void check_object_index(const Document& doc, int object) {
  if (object < 0 || to_size(object) >= doc.objects.size()) {
    throw EditError("object " + std::to_string(object) + " is out of range: the document has " +
                    std::to_string(doc.objects.size()) + (doc.objects.size() == 1 ? " object" : " objects"));
  }
}

/// Checks that `object` is a control-point curve and returns it.
Object& control_point_curve(Document& doc, int object) {
  check_object_index(doc, object);
  Object& o = doc.objects[to_size(object)];
  if (has_control_net(o.kind())) {
    throw EditError(quoted(doc, object) + " is a surface (" + std::string(keyword(o.kind())) +
                    ") with a fixed net of points: they can be moved, not inserted or deleted");
  }
  if (!has_control_points(o.kind())) {
    throw EditError(
        quoted(doc, object) + " is " +
        (is_curve(o.kind())
             ? std::string("a ") + (o.kind() == ObjectKind::Circle ? "circle" : std::string(keyword(o.kind())))
             : "a surface (" + std::string(keyword(o.kind())) + ")") +
        ": it has no control points");
  }
  return o;
}

Object& editable_points_object(Document& doc, int object) {
  check_object_index(doc, object);
  Object& o = doc.objects[to_size(object)];
  return has_control_net(o.kind()) ? o : control_point_curve(doc, object);
}

void check_point_index(const Document& doc, int object, int point) {
  const Object& o = doc.objects[to_size(object)];
  if (point < 0 || to_size(point) >= o.as<PointsPart>().points.size()) {
    throw EditError("point " + std::to_string(point) + " is out of range: curve " + quoted(doc, object) + " has " +
                    std::to_string(o.as<PointsPart>().points.size()) + " points");
  }
}

/// The position a curve of `kind` stores for `position` (z dropped for planar curves), after
/// checking that it is finite and within the coordinate cap.
glm::dvec3 checked_position(ObjectKind kind, const glm::dvec3& position) {
  const bool planar = is_planar_curve(kind);
  const char* axes[3] = {"x", "y", "z"};
  for (int axis = 0; axis < (planar ? 2 : 3); ++axis) {
    const double value = position[axis];
    if (!std::isfinite(value)) {
      throw EditError(std::string("coordinate ") + axes[axis] + " = " + number_text(value) + " is not a finite number");
    }
    if (std::abs(value) > limits::kMaxCoordinate) {
      throw EditError(std::string("coordinate ") + axes[axis] + " = " + number_text(value) +
                      " is out of range: coordinates must be from -1e12 to 1e12");
    }
  }
  return planar ? glm::dvec3(position.x, position.y, 0.0) : position;
}

/// Checks a new name for object `object` (-1: an object not in the document yet). "" is allowed
/// (anonymous); the parser's rules otherwise: letters, digits, '_', '-', '.', starting with a
/// letter or '_', at most limits::kMaxNameLength bytes, unique.
void check_new_name(const Document& doc, int object, const std::string& name) {
  if (name.empty()) return;
  if (name.size() > limits::kMaxNameLength) {
    throw EditError("name '" + shown_name(name) + "' is too long: at most " + std::to_string(limits::kMaxNameLength) +
                    " characters");
  }
  if (!is_valid_object_name(name)) {
    const auto first = static_cast<unsigned char>(name[0]);
    if (!std::isalpha(first) && first != '_' && (std::isalnum(first) || first == '-' || first == '.')) {
      throw EditError("name '" + shown_name(name) + "' is not a valid SWP name: start with a letter or '_'");
    }
    throw EditError("name '" + shown_name(name) + "' is not a valid SWP name: use letters, digits, '_', '-' or '.'");
  }
  const int owner = doc.find(name);
  if (owner >= 0 && owner != object) {
    throw EditError("name '" + name + "' is already used by another object");
  }
}

/// The caps (caps.hpp) of the document with objects[replaced] taken to be `replacement` and
/// `appended` added at the end (either may be absent), in the reader's words, naming the object
/// that breaks one. O(number of objects).
void check_caps(const Document& doc, int replaced, const Object* replacement, const Object* appended) {
  const int count = to_int(doc.objects.size()) + (appended ? 1 : 0);
  const ObjectAt object_at = [&](int i) -> const Object& {
    if (appended && i == to_int(doc.objects.size())) return *appended;
    if (replacement && i == replaced) return *replacement;
    return doc.objects[to_size(i)];
  };
  const auto breach = first_cap_breach(count, object_at);
  if (!breach) return;
  const Object& o = object_at(breach->first);
  std::string name(1, '\'');  // appended: see quoted()
  name.append(o.name.empty() ? std::string(keyword(o.kind())) + "#" + std::to_string(breach->first) : o.name);
  name.push_back('\'');
  throw EditError(std::string(is_curve(o.kind()) ? "curve " : "surface ") + name + ": " + breach->second.expected +
                  (breach->second.note.empty() ? std::string() : " (" + breach->second.note + ")"));
}

namespace {

/// What the reader says of a subd whose cage cannot take its scheme, as an edit error.
void check_subdivision(const Document& doc, int index) {
  const SubdivisionSurface& subd = doc.objects[to_size(index)].as<SubdivisionSurface>();
  const auto problem = check_subdivision_scheme(subd, doc.objects[to_size(subd.source)], quoted(doc, subd.source));
  if (problem) throw EditError("surface " + quoted(doc, index) + ": " + problem->expected + " (" + problem->note + ")");
}

}  // namespace

void check_users(const Document& doc, int object) {
  for (std::size_t i = to_size(object); i < doc.objects.size(); ++i) {
    const Object& o = doc.objects[i];
    if (!is_surface(o.kind())) continue;
    const auto refs = references(o);
    if (to_int(i) != object && std::find(refs.begin(), refs.end(), object) == refs.end()) continue;
    if (o.kind() == ObjectKind::Subdivision) check_subdivision(doc, to_int(i));
    if (const std::optional<CurveProblem> problem = check_surface_curves(doc, o)) {
      throw EditError("surface " + quoted(doc, to_int(i)) + ": " + problem->expected +
                      (problem->note.empty() ? std::string() : " (" + problem->note + ")"));
    }
  }
}

/// Replaces objects[object] by `replacement` after checking the caps and the surfaces using it.
Change commit(Document& doc, int object, Object&& replacement) {
  // The reader's count rule, so no edit makes a file the reader refuses.
  if (const std::string problem = count_problem(replacement); !problem.empty()) {
    throw EditError("curve " + quoted(doc, object) + ": " + problem);
  }
  check_caps(doc, object, &replacement, nullptr);
  std::swap(doc.objects[to_size(object)], replacement);
  try {
    check_users(doc, object);
  } catch (...) {
    std::swap(doc.objects[to_size(object)], replacement);
    throw;
  }
  return Change{{object}, false};
}

std::size_t seam_repeats(ObjectKind kind) {
  return point_layout(kind).seam_repeats;
}

std::vector<glm::dvec3> distinct_points(ObjectKind kind, const std::vector<glm::dvec3>& points) {
  return {points.begin(), points.end() - static_cast<std::ptrdiff_t>(seam_repeats(kind))};
}

std::vector<glm::dvec3> closed_polygon(ObjectKind kind, std::vector<glm::dvec3> distinct) {
  const std::size_t repeats = seam_repeats(kind);
  for (std::size_t k = 0; k < repeats; ++k) distinct.push_back(distinct[k]);
  return distinct;
}

}  // namespace sweep::edit_support
