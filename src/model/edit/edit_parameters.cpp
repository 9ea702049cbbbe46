// Editing the numbers of the curve kinds besides points and STEPS (cr/kb clauses, radii, helix
// pitch and turns, knot P and Q, every curve's tolerance), with the ranges the SWP reader enforces.
#include "base/precondition.hpp"
#include "geometry/curves/adaptive.hpp"
#include "model/clauses.hpp"
#include "model/curve_parameters.hpp"
#include "model/edit/edit.hpp"
#include "model/edit/edit_support.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/file_limits.hpp"

#include <array>
#include <cmath>
#include <functional>
#include <string>
#include <vector>

namespace sweep {

using namespace edit_support;

namespace {

/// Where a parameter of an object is and what may be set there, found in the fixed fields its
/// kind lists (`fields`, object.hpp) or in its clauses (clause.hpp): the reader's own rules.
struct ParameterSlot {
  double* number = nullptr;
  int* integer = nullptr;
  int low = 0, high = 0;  // an integer's range
  /// Every field check of the kind, of the object as it now is (one field's rule may involve
  /// another: a knot's r < R is checked at r, its coprime P and Q at Q).
  std::vector<std::function<std::string()>> checks;
  const SwpClause* clause = nullptr;  // a clause's key and check
  glm::dvec3* vector = nullptr;       // a vector clause's numbers (`number` is one of them)
};

/// The `fields` calls the parameter visitors below pass over: everything but numbers.
struct NumbersOnly {
  void steps(int&) {}
  void points(auto&, const char*) {}
  void samples(std::int64_t) {}
  void samples_by(std::int64_t, const char*) {}
  void reference(const char*, int&, bool) {}
  void vertices(VerticesAt) {}
  void custom(auto&) {}
};

/// A `fields` visitor that finds the field named `name` (FieldName::parameter).
struct ParameterFinder : NumbersOnly {
  std::string_view name;
  ParameterSlot slot;

  template <typename... Check>
  void number(FieldName field, double& value, Check... check) {
    (slot.checks.push_back(check), ...);
    if (field.parameter == name) slot.number = &value;
  }
  template <typename... Check>
  void integer(FieldName field, int& value, int low, int high, Check... check) {
    (slot.checks.push_back(check), ...);
    if (field.parameter != name) return;
    slot.integer = &value;
    slot.low = low;
    slot.high = high;
  }
};

/// The slot of `parameter` in `o` (nothing found: no slot).
ParameterSlot find_slot(Object& o, CurveParameter parameter) {
  ParameterFinder finder{{}, parameter_name(parameter), {}};
  std::visit([&finder](auto& kind) { std::decay_t<decltype(kind)>::fields(kind, finder); }, o.data);
  if (finder.slot.number || finder.slot.integer) return finder.slot;
  for (const SwpClause& clause : swp_clauses(o.kind())) {
    if (clause.key == finder.name && clause.field) {
      return {clause.field(o), nullptr, 0, 0, std::move(finder.slot.checks), &clause};
    }
    // A vector clause's numbers are "KEY x", "KEY y" and "KEY z".
    const std::string_view name = finder.name;
    if (clause.vector && name.size() == clause.key.size() + 2 && name.starts_with(clause.key) &&
        name[clause.key.size()] == ' ') {
      glm::dvec3* vector = clause.vector(o);
      const auto axis = static_cast<glm::length_t>(name.back() - 'x');
      return {&(*vector)[axis], nullptr, 0, 0, std::move(finder.slot.checks), &clause, vector};
    }
  }
  return {};
}

/// Sets `value` in `slot` of the object it was found in, or says why the reader would refuse it.
std::string set_checked(const ParameterSlot& slot, ObjectKind kind, std::string_view name, double value,
                        double extent) {
  if (slot.integer) {
    if (value != std::floor(value) || value < slot.low || value > slot.high) {
      return "expected " + std::string(name) + ", a whole number from " + std::to_string(slot.low) + " to " +
             std::to_string(slot.high);
    }
    *slot.integer = static_cast<int>(value);
  } else if (slot.clause) {
    if (slot.vector) {
      *slot.number = value;
      return slot.clause->vector_check(*slot.vector);
    }
    const bool off = slot.clause->default_means_off && value == slot.clause->default_value;
    if (!off && slot.clause->check) {
      if (std::string problem = slot.clause->check(kind, value); !problem.empty()) return problem;
    }
    // The tolerance's floor is relative to the curve's size, as the reader checks it.
    if (!off && slot.clause->key == swp_clause_checks::kTolerance.key) {
      if (std::string problem = check_tolerance(value, extent, "the curve"); !problem.empty()) return problem;
    }
    *slot.number = value;
  } else {
    if (std::abs(value) > limits::kMaxCoordinate) {
      return "expected a number from -1e12 to 1e12 (" + std::string(name) + ")";
    }
    *slot.number = value;
  }
  for (const auto& check : slot.checks) {
    if (std::string problem = check(); !problem.empty()) return problem;
  }
  return {};
}

}  // namespace

std::string_view parameter_name(CurveParameter parameter) {
  static constexpr std::array<std::string_view, 14> kNames{"alpha", "tension", "continuity", "bias",     "radius",
                                                           "pitch", "turns",   "R",          "P",        "Q",
                                                           "at x",  "at y",    "at z",       "tolerance"};
  return kNames[static_cast<std::size_t>(parameter)];
}

bool has_parameter(ObjectKind kind, CurveParameter parameter) {
  Object example(kind);
  const ParameterSlot slot = find_slot(example, parameter);
  return slot.number || slot.integer;
}

namespace {

/// A `fields` visitor that lists the names of the numbers a kind's fixed fields hold, in order.
struct FieldOrder : NumbersOnly {
  std::vector<std::string_view> names;

  template <typename... Check>
  void number(FieldName field, double&, Check...) {
    names.push_back(field.parameter);
  }
  template <typename... Check>
  void integer(FieldName field, int&, int, int, Check...) {
    names.push_back(field.parameter);
  }
};

}  // namespace

std::vector<CurveParameter> parameters_in_file_order(ObjectKind kind) {
  Object example(kind);
  FieldOrder order;
  std::visit([&order](auto& data) { std::decay_t<decltype(data)>::fields(data, order); }, example.data);
  std::vector<std::string> names(order.names.begin(), order.names.end());
  for (const SwpClause& clause : swp_clauses(kind)) {
    if (!clause.vector) names.emplace_back(clause.key);
    for (const char* axis : {" x", " y", " z"}) {
      if (clause.vector) names.push_back(std::string(clause.key) + axis);
    }
  }
  std::vector<CurveParameter> out;
  for (const std::string& name : names) {
    for (int k = 0; k <= static_cast<int>(CurveParameter::Tolerance); ++k) {
      const auto parameter = static_cast<CurveParameter>(k);
      if (parameter_name(parameter) == name && has_parameter(kind, parameter)) out.push_back(parameter);
    }
  }
  return out;
}

double parameter_value(const Object& object, CurveParameter parameter) {
  SWEEP_EXPECTS(has_parameter(object.kind(), parameter), "has_parameter");
  const ParameterSlot slot = find_slot(const_cast<Object&>(object), parameter);  // read only
  return slot.integer ? *slot.integer : *slot.number;
}

Change set_curve_parameter(Document& doc, int object, CurveParameter parameter, double value) {
  check_object_index(doc, object);
  const Object& o = doc.objects[to_size(object)];
  if (!has_parameter(o.kind(), parameter)) {
    throw EditError(quoted(doc, object) + " (" + std::string(keyword(o.kind())) + ") has no " +
                    std::string(parameter_name(parameter)));
  }
  if (!std::isfinite(value)) throw EditError(std::string(parameter_name(parameter)) + " must be a finite number");
  Object changed = o;
  const ParameterSlot slot = find_slot(changed, parameter);
  const std::string problem = set_checked(slot, o.kind(), parameter_name(parameter), value, curve_extent(o));
  if (!problem.empty()) throw EditError(problem);
  return commit(doc, object, std::move(changed));  // turns change the sample count: caps checked
}

}  // namespace sweep
