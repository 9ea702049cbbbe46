#include "model/evaluation/curve_evaluation.hpp"

#include "base/precondition.hpp"
#include "geometry/unit_vector.hpp"

#include <glm/common.hpp>

#include <type_traits>
#include <variant>

namespace sweep {
namespace {

/// The box of a curve or net (lo, hi); false for objects without one.
bool object_box(const Object& o, glm::dvec3& lo, glm::dvec3& hi) {
  if (is_curve(o.kind())) return curve_box(describe_curve(o), lo, hi);
  if (!has_control_net(o.kind())) return false;
  CurveDescriptor net;  // a net bounds its surface as a control polygon bounds a curve
  net.points = o.as<PointsPart>().points;
  return curve_box(net, lo, hi);
}

}  // namespace

CurveDescriptor describe_curve(const Object& o) {
  SWEEP_EXPECTS(is_curve(o.kind()), "o is a curve");
  CurveDescriptor d;
  d.planar = is_planar_curve(o.kind());
  std::visit(
      [&d](const auto& curve) {
        using Kind = std::decay_t<decltype(curve)>;
        if constexpr (requires { Kind::basis; }) d.basis = Kind::basis;
        if constexpr (std::is_base_of_v<PointsPart, Kind>) d.points = curve.points;
        if constexpr (std::is_base_of_v<StepsPart, Kind>) d.steps = curve.steps;
        if constexpr (std::is_base_of_v<TolerancePart, Kind>) d.tolerance = curve.tolerance;
        if constexpr (std::is_base_of_v<AlphaPart, Kind>) d.alpha = curve.alpha;
        if constexpr (std::is_base_of_v<TensionPart, Kind>) d.spline.tension = curve.tension;
        if constexpr (std::is_base_of_v<ContinuityBiasPart, Kind>) {
          d.spline.continuity = curve.continuity;
          d.spline.bias = curve.bias;
        }
        if constexpr (std::is_base_of_v<RadiusPart, Kind>) d.radius = curve.radius;
        if constexpr (std::is_base_of_v<PlacePart, Kind>) d.origin = curve.at;
        if constexpr (std::is_same_v<HelixCurve, Kind>) {
          d.pitch = curve.pitch;
          d.turns = curve.turns;
        }
        if constexpr (std::is_same_v<TorusKnotCurve, Kind>) {
          d.knot_p = curve.knot_p;
          d.knot_q = curve.knot_q;
          d.major_radius = curve.major_radius;
        }
      },
      o.data);
  return d;
}

CurveSamples evaluate_curve(const Object& object, const FrameOptions& options, const AdaptiveTolerance& tolerance) {
  if (!is_curve(object.kind())) return {};
  return evaluate_curve(describe_curve(object), options, tolerance);
}

CurveSamples evaluate_curve_at(const Object& object, std::span<const double> parameters, const FrameOptions& options) {
  return evaluate_curve_at(describe_curve(object), parameters, options);
}

glm::dvec3 curve_position(const Object& object, double parameter) {
  return curve_position(describe_curve(object), parameter);
}

PieceDerivatives curve_derivatives(const Object& object, double parameter) {
  return curve_derivatives(describe_curve(object), parameter);
}

double curve_extent(const Object& object) {
  glm::dvec3 lo, hi;
  return object_box(object, lo, hi) ? vector_length(hi - lo) : 0.0;
}

double document_extent(const Document& doc) {
  glm::dvec3 lo(0.0), hi(0.0);
  bool any = false;
  for (const Object& o : doc.objects) {
    glm::dvec3 a, b;
    if (!object_box(o, a, b)) continue;
    lo = any ? glm::min(lo, a) : a;
    hi = any ? glm::max(hi, b) : b;
    any = true;
  }
  return any ? vector_length(hi - lo) : 0.0;
}

Cage cage_of(const Object& mesh) {
  const PolygonMeshSurface& cage = mesh.as<PolygonMeshSurface>();
  return {cage.points, cage.face_sizes, cage.face_vertices};
}

}  // namespace sweep
