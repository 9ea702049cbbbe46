// Editing the numbers of the curve kinds besides points and STEPS (cr/kb clauses, radii, helix
// pitch and turns, knot P and Q, every curve's tolerance), with the ranges the SWP reader enforces.
#include "geometry/adaptive.hpp"
#include "geometry/limits.hpp"
#include "geometry/precondition.hpp"
#include "model/curve_evaluation.hpp"
#include "model/curve_parameters.hpp"
#include "model/edit.hpp"
#include "model/edit_support.hpp"

#include <array>
#include <cmath>

namespace sweep {

using namespace edit_support;

namespace {

/// The field of a real-valued parameter (Object or const Object).
template <typename O>
auto& field(O& o, CurveParameter parameter) {
  switch (parameter) {
    case CurveParameter::Alpha:
      return o.template as<AlphaPart>().alpha;
    case CurveParameter::Tension:
      return o.template as<TensionPart>().tension;
    case CurveParameter::Continuity:
      return o.template as<ContinuityBiasPart>().continuity;
    case CurveParameter::Bias:
      return o.template as<ContinuityBiasPart>().bias;
    case CurveParameter::Radius:
      return o.template as<RadiusPart>().radius;
    case CurveParameter::Pitch:
      return o.template as<HelixCurve>().pitch;
    case CurveParameter::Turns:
      return o.template as<HelixCurve>().turns;
    case CurveParameter::Tolerance:
      return o.template as<TolerancePart>().tolerance;
    case CurveParameter::MajorRadius:
    case CurveParameter::KnotP:  // whole numbers: parameter_value and set_parameter read them apart
    case CurveParameter::KnotQ:
      break;
  }
  return o.template as<TorusKnotCurve>().major_radius;
}

/// "" if `value` is a valid `parameter` of `o` (the other fields as they are), else why not.
std::string check(const Object& o, CurveParameter parameter, double value) {
  switch (parameter) {
    case CurveParameter::Alpha:
      return check_alpha(value);
    case CurveParameter::Tension:
      return check_tension(o.kind(), value);
    case CurveParameter::Continuity:
    case CurveParameter::Bias:
      return check_kb_parameter(parameter == CurveParameter::Bias ? "bias" : "continuity", value);
    case CurveParameter::Radius:
      return o.kind() == ObjectKind::TorusKnot ? check_knot_radii(o.as<TorusKnotCurve>().major_radius, value)
                                               : check_radius(value);
    case CurveParameter::Pitch:
      return std::abs(value) <= limits::kMaxCoordinate ? "" : "expected a pitch from -1e12 to 1e12";
    case CurveParameter::Turns:
      return check_turns(value);
    case CurveParameter::MajorRadius:
      return check_knot_radii(value, o.as<RadiusPart>().radius);
    case CurveParameter::Tolerance:
      return value == 0.0 ? "" : check_tolerance(value, curve_extent(o), "the curve");
    case CurveParameter::KnotP:
    case CurveParameter::KnotQ: {
      if (value != std::floor(value) || value < 1.0 || value > double(kMaxKnotWinding)) {
        return "expected a whole number from 1 to " + std::to_string(kMaxKnotWinding);
      }
      const int n = static_cast<int>(value);
      return parameter == CurveParameter::KnotP ? check_knot_pq(n, o.as<TorusKnotCurve>().knot_q)
                                                : check_knot_pq(o.as<TorusKnotCurve>().knot_p, n);
    }
  }
  return {};
}

}  // namespace

std::string_view parameter_name(CurveParameter parameter) {
  static constexpr std::array<std::string_view, 11> kNames{
      "alpha", "tension", "continuity", "bias", "radius", "pitch", "turns", "R", "P", "Q", "tolerance"};
  return kNames[static_cast<std::size_t>(parameter)];
}

bool has_parameter(ObjectKind kind, CurveParameter parameter) {
  // A kind has a parameter when its type has the part that holds it (object.hpp).
  const Object example(kind);
  switch (parameter) {
    case CurveParameter::Alpha:
      return example.find<AlphaPart>() != nullptr;
    case CurveParameter::Tension:
      return example.find<TensionPart>() != nullptr;
    case CurveParameter::Continuity:
    case CurveParameter::Bias:
      return example.find<ContinuityBiasPart>() != nullptr;
    case CurveParameter::Radius:
      return example.find<RadiusPart>() != nullptr;
    case CurveParameter::Pitch:
    case CurveParameter::Turns:
      return example.find<HelixCurve>() != nullptr;
    case CurveParameter::Tolerance:
      return example.find<TolerancePart>() != nullptr;
    case CurveParameter::MajorRadius:
    case CurveParameter::KnotP:
    case CurveParameter::KnotQ:
      return example.find<TorusKnotCurve>() != nullptr;
  }
  return false;
}

double parameter_value(const Object& object, CurveParameter parameter) {
  SWEEP_EXPECTS(has_parameter(object.kind(), parameter), "has_parameter");
  if (parameter == CurveParameter::KnotP) return object.as<TorusKnotCurve>().knot_p;
  if (parameter == CurveParameter::KnotQ) return object.as<TorusKnotCurve>().knot_q;
  return field(object, parameter);
}

Change set_curve_parameter(Document& doc, int object, CurveParameter parameter, double value) {
  check_object_index(doc, object);
  const Object& o = doc.objects[to_size(object)];
  if (!has_parameter(o.kind(), parameter)) {
    throw EditError(quoted(doc, object) + " (" + std::string(keyword(o.kind())) + ") has no " +
                    std::string(parameter_name(parameter)));
  }
  if (!std::isfinite(value)) throw EditError(std::string(parameter_name(parameter)) + " must be a finite number");
  if (const std::string problem = check(o, parameter, value); !problem.empty()) throw EditError(problem);
  Object changed = o;
  if (parameter == CurveParameter::KnotP) {
    changed.as<TorusKnotCurve>().knot_p = static_cast<int>(value);
  } else if (parameter == CurveParameter::KnotQ) {
    changed.as<TorusKnotCurve>().knot_q = static_cast<int>(value);
  } else {
    field(changed, parameter) = value;
  }
  return commit(doc, object, std::move(changed));  // turns change the sample count: caps checked
}

}  // namespace sweep
