// Editing riders: their path and model (references checked as the reader checks them) and their
// clauses (the checks of kind_rider.hpp's clause table).
#include "model/edit/edit.hpp"
#include "model/edit/edit_support.hpp"
#include "model/surface_validation.hpp"

#include <cmath>

namespace sweep {

using namespace edit_support;

namespace {

/// A named object before `before` (the end for a new object) that `wanted` accepts.
void check_reference(const Document& doc, int before, int index, const char* role, bool (*wanted)(ObjectKind),
                     const char* what) {
  if (index < 0 || index >= before) {
    throw EditError(std::string("the ") + role + " must be " + what + " defined before the rider");
  }
  const Object& target = doc.objects[to_size(index)];
  if (!wanted(target.kind())) {
    throw EditError(quoted(doc, index) + " cannot be the " + role + ": expected " + what + ", it is " +
                    kind_description(target.kind()));
  }
  if (target.name.empty()) {
    throw EditError(quoted(doc, index) + " has no name: a rider can only use a named object (name it first)");
  }
}

/// The clause checks of the reader, with the value refused in the message.
void check_clauses(const RiderObject& r) {
  const auto refuse = [](const std::string& problem, const std::string& value) {
    if (!problem.empty()) throw EditError(problem + ", not " + value);
  };
  refuse(swp_clause_checks::seconds(ObjectKind::Rider, r.seconds), number_text(r.seconds));
  refuse(swp_clause_checks::start(ObjectKind::Rider, r.start), number_text(r.start));
  if (!std::isfinite(r.up.x) || !std::isfinite(r.up.y) || !std::isfinite(r.up.z)) {
    throw EditError("expected a finite up vector");
  }
}

}  // namespace

int add_rider(Document& doc, const std::string& name, int path, int model) {
  const int end = to_int(doc.objects.size());
  check_reference(doc, end, path, "path", is_curve, "a curve");
  check_reference(doc, end, model, "model", is_surface, "a surface");
  check_new_name(doc, -1, name);
  Object rider(ObjectKind::Rider);
  rider.name = name;
  rider.as<RiderObject>().path = path;
  rider.as<RiderObject>().model = model;
  doc.objects.push_back(std::move(rider));
  return end;
}

Change set_rider(Document& doc, int object, const RiderObject& value) {
  check_object_index(doc, object);
  if (!is_rider(doc.objects[to_size(object)].kind())) throw EditError(quoted(doc, object) + " is not a rider");
  check_reference(doc, object, value.path, "path", is_curve, "a curve");
  check_reference(doc, object, value.model, "model", is_surface, "a surface");
  check_clauses(value);
  Object changed = doc.objects[to_size(object)];
  changed.as<RiderObject>() = value;
  const bool repointed = changed.as<RiderObject>().path != doc.objects[to_size(object)].as<RiderObject>().path ||
                         changed.as<RiderObject>().model != doc.objects[to_size(object)].as<RiderObject>().model;
  Change change = commit(doc, object, std::move(changed));
  change.structure = change.structure || repointed;
  return change;
}

}  // namespace sweep
