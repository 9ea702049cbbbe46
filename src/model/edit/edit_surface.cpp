// Editing the optional clauses of the surfaces: the scale and twist of a generalized cylinder
// (sweep_controls.hpp) and the caps and height flags. Each checks the surface with the reader's
// rules (check_users) before the document changes.
#include "model/clauses.hpp"
#include "model/edit/edit.hpp"
#include "model/edit/edit_support.hpp"
#include "model/surface_validation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <string_view>

namespace sweep {

using namespace edit_support;

namespace {

Object& cylinder(Document& doc, int object) {
  check_object_index(doc, object);
  Object& o = doc.objects[to_size(object)];
  if (o.kind() != ObjectKind::GeneralizedCylinder) {
    throw EditError(quoted(doc, object) + " is not a generalized cylinder (gcyl): only those have a scale and a twist");
  }
  return o;
}

}  // namespace

Change set_surface_graph(Document& doc, int object, SurfaceGraph graph, int curve) {
  Object changed = cylinder(doc, object);
  const char* role = graph == SurfaceGraph::Scale ? "scale" : "twist";
  if (curve >= 0) {
    if (curve >= object) {
      throw EditError(std::string("the ") + role + " curve must be defined before " + quoted(doc, object) +
                      " (references point backwards)");
    }
    const Object& target = doc.objects[to_size(curve)];
    const std::string graph_role = std::string("a ") + role + " curve";
    if (const auto problem = check_reference_kind(target, graph_role.c_str(), true)) {
      throw EditError(quoted(doc, curve) + ": " + problem->expected + " (" + problem->note + ")");
    }
    if (target.name.empty()) {
      throw EditError("curve " + quoted(doc, curve) +
                      " has no name: a surface can only use a named curve (name it first)");
    }
  }
  (graph == SurfaceGraph::Scale ? changed.as<CylinderSurface>().scale : changed.as<CylinderSurface>().twist_curve) =
      std::max(curve, -1);
  return commit(doc, object, std::move(changed));
}

Change set_twist(Document& doc, int object, double degrees) {
  Object changed = cylinder(doc, object);
  if (const std::string problem = swp_clause_checks::twist(ObjectKind::GeneralizedCylinder, degrees);
      !problem.empty()) {
    throw EditError(problem + ", not " + number_text(degrees));
  }
  changed.as<CylinderSurface>().twist = degrees;
  changed.as<CylinderSurface>().twist_curve = -1;
  return commit(doc, object, std::move(changed));
}

namespace {

/// The flag's clause key: the clause table (model/clauses.hpp) says which kinds have it and
/// which field it sets, for the reader, the writer, the editor and the panel alike.
std::string_view flag_key(SurfaceFlag flag) {
  static constexpr std::array<std::string_view, 4> kKeys{"caps", "height", "loop", "smooth-boundary"};
  return kKeys[static_cast<std::size_t>(flag)];
}

const SwpClause* flag_clause(ObjectKind kind, SurfaceFlag flag) {
  for (const SwpClause& clause : swp_clauses(kind)) {
    if (clause.flag && clause.key == flag_key(flag)) return &clause;
  }
  return nullptr;
}

}  // namespace

bool has_flag(ObjectKind kind, SurfaceFlag flag) {
  return flag_clause(kind, flag) != nullptr;
}

bool flag_value(const Object& object, SurfaceFlag flag) {
  const SwpClause* clause = flag_clause(object.kind(), flag);
  return clause && clause_flag(*clause, object);
}

Change set_surface_flag(Document& doc, int object, SurfaceFlag flag, bool on) {
  check_object_index(doc, object);
  Object changed = doc.objects[to_size(object)];
  const SwpClause* clause = flag_clause(changed.kind(), flag);
  if (!clause) {
    throw EditError(quoted(doc, object) + " has no " + std::string(flag_key(flag)) + " clause (" +
                    std::string(keyword(changed.kind())) + ")");
  }
  *clause->flag(changed) = on;
  return commit(doc, object, std::move(changed));
}

}  // namespace sweep
