#include "model/edit_support.hpp"

#include "geometry/birail.hpp"
#include "geometry/limits.hpp"
#include "geometry/subdivision.hpp"
#include "geometry/surface.hpp"
#include "geometry/sweep_controls.hpp"
#include "model/curve_evaluation.hpp"
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

bool is_bezier(ObjectKind kind) {
  return kind == ObjectKind::Bezier2 || kind == ObjectKind::Bezier3;
}
bool is_bspline(ObjectKind kind) {
  return kind == ObjectKind::BSpline2 || kind == ObjectKind::BSpline3;
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

/// The samples and mesh vertices of a document, counted as the parser counts them, with
/// objects[replaced] taken to be `replacement` and `appended` added at the end (either may be
/// absent). Throws EditError naming the first cap exceeded. O(number of objects).
void check_caps(const Document& doc, int replaced, const Object* replacement, const Object* appended) {
  const std::size_t count = doc.objects.size() + (appended ? 1 : 0);
  auto object_at = [&](std::size_t i) -> const Object& {
    if (appended && i == doc.objects.size()) return *appended;
    if (replacement && to_int(i) == replaced) return *replacement;
    return doc.objects[i];
  };
  auto name_of = [&](std::size_t i) {
    const Object& o = object_at(i);
    std::string text(1, '\'');  // appended: see quoted()
    text.append(o.name.empty() ? std::string(keyword(o.kind())) + "#" + std::to_string(i) : o.name);
    text.push_back('\'');
    return text;
  };
  std::int64_t total_points = 0;
  std::int64_t total_samples = 0;
  std::int64_t total_vertices = 0;
  for (std::size_t i = 0; i < count; ++i) {
    const Object& o = object_at(i);
    if (is_curve(o.kind())) {
      total_points += static_cast<std::int64_t>(points_of(o).size());
      const std::int64_t samples = curve_sample_count(o);
      if (samples > limits::kMaxCurveSamples) {
        throw EditError("curve " + name_of(i) + " would have " + std::to_string(samples) + " samples: at most " +
                        std::to_string(limits::kMaxCurveSamples) + " are allowed");
      }
      total_samples += samples;
      continue;
    }
    const SweptCurves curves = swept_curves(o);
    if (curves.profile < 0) {  // patches, cages, subdivision: the reader's check of the whole document counts them
      total_points += static_cast<std::int64_t>(points_of(o).size());
      continue;
    }
    // References point backwards, so the curves they name are already counted (and valid).
    const std::int64_t profile = curve_sample_count(object_at(to_size(curves.profile)));
    const std::int64_t sweep = curve_sample_count(object_at(to_size(std::max(curves.path, 0))));
    std::int64_t vertices = 0;
    if (const auto* revolution = o.find<RevolutionSurface>()) {
      vertices = revolution_vertex_count(profile, false, revolution->steps);
    } else if (curves.rail2 >= 0) {
      vertices = birail_vertex_count(profile, sweep, curve_sample_count(object_at(to_size(curves.rail2))));
    } else {
      vertices = cylinder_vertex_count(profile, false, sweep, false);
    }
    if (vertices > limits::kMaxMeshVertices) {
      throw EditError("surface " + name_of(i) + " would have " + std::to_string(vertices) + " vertices: at most " +
                      std::to_string(limits::kMaxMeshVertices) + " are allowed");
    }
    total_vertices += vertices;
  }
  if (total_points > limits::kMaxControlPoints) {
    throw EditError("the document would have " + std::to_string(total_points) + " control points: at most " +
                    std::to_string(limits::kMaxControlPoints) + " are allowed");
  }
  if (total_samples > 2 * limits::kMaxCurveSamples) {
    throw EditError("the curves would have " + std::to_string(total_samples) + " samples in all: at most " +
                    std::to_string(2 * limits::kMaxCurveSamples) + " are allowed");
  }
  if (total_vertices > limits::kMaxMeshVertices) {
    throw EditError("the surfaces would have " + std::to_string(total_vertices) + " vertices in all: at most " +
                    std::to_string(limits::kMaxMeshVertices) + " are allowed");
  }
}

namespace {

/// What the reader says of a subd whose cage cannot take its scheme or level, as an edit error.
void check_subdivision(const Document& doc, int index) {
  const SubdivisionSurface& subd = doc.objects[to_size(index)].as<SubdivisionSurface>();
  const Object& source = doc.objects[to_size(subd.source)];
  const std::string what = "surface " + quoted(doc, index) + ": ";
  const auto* cage = source.find<PolygonMeshSurface>();
  if (!cage) {
    if (subd.loop && source.kind() != ObjectKind::Subdivision) {
      throw EditError(what + "expected a triangle cage for loop (" + quoted(doc, subd.source) +
                      " is a grid of quads; Catmull-Clark, the default, takes them)");
    }
    return;
  }
  const auto quad = std::find_if(cage->face_sizes.begin(), cage->face_sizes.end(), [](int n) { return n != 3; });
  if (subd.loop && quad != cage->face_sizes.end()) {
    throw EditError(what + "expected a triangle cage for loop (face " +
                    std::to_string(quad - cage->face_sizes.begin() + 1) + " of " + quoted(doc, subd.source) + " has " +
                    std::to_string(*quad) + " vertices; Catmull-Clark, the default, takes any polygons)");
  }
  const SubdivisionScheme scheme = subd.loop ? SubdivisionScheme::Loop : SubdivisionScheme::CatmullClark;
  const std::int64_t vertices = refined_counts(cage_of(source), subd.levels, scheme).vertices;
  if (vertices > limits::kMaxMeshVertices) {
    throw EditError(what + "level " + std::to_string(subd.levels) + " would have " + std::to_string(vertices) +
                    " vertices: at most " + std::to_string(limits::kMaxMeshVertices) + " are allowed");
  }
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
  return is_bspline(kind) ? 3 : 1;
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
