#include "model/curve_evaluation.hpp"

#include "geometry/unit_vector.hpp"

#include <glm/common.hpp>

namespace sweep {
namespace {

CurveBasis basis_of(ObjectKind kind) {
  switch (kind) {
    case ObjectKind::Bezier2:
    case ObjectKind::Bezier3:
      return CurveBasis::Bezier;
    case ObjectKind::BSpline2:
    case ObjectKind::BSpline3:
      return CurveBasis::BSpline;
    case ObjectKind::CatmullRom2:
    case ObjectKind::CatmullRom3:
      return CurveBasis::CatmullRom;
    case ObjectKind::KochanekBartels2:
    case ObjectKind::KochanekBartels3:
      return CurveBasis::KochanekBartels;
    case ObjectKind::Circle:
      return CurveBasis::Circle;
    case ObjectKind::Helix:
      return CurveBasis::Helix;
    case ObjectKind::Polyline2:
    case ObjectKind::Polyline3:
      return CurveBasis::Polyline;
    default:
      return CurveBasis::TorusKnot;
  }
}

/// The box of a curve or net (lo, hi); false for objects without one.
bool object_box(const Object& o, glm::dvec3& lo, glm::dvec3& hi) {
  if (is_curve(o.kind)) return curve_box(describe_curve(o), lo, hi);
  if (!has_control_net(o.kind)) return false;
  CurveDescriptor net;  // a net bounds its surface as a control polygon bounds a curve
  net.points = o.points;
  return curve_box(net, lo, hi);
}

}  // namespace

CurveDescriptor describe_curve(const Object& o) {
  CurveDescriptor d;
  d.basis = basis_of(o.kind);
  d.planar = is_planar_curve(o.kind);
  d.points = o.points;
  d.steps = o.steps;
  d.tolerance = o.tolerance;
  d.alpha = o.alpha;
  d.spline = {o.tension, o.continuity, o.bias};
  d.radius = o.radius;
  d.pitch = o.pitch;
  d.turns = o.turns;
  d.knot_p = o.knot_p;
  d.knot_q = o.knot_q;
  d.major_radius = o.major_radius;
  return d;
}

CurveSamples evaluate_curve(const Object& object, const FrameOptions& options, const AdaptiveTolerance& tolerance) {
  if (!is_curve(object.kind)) return {};
  return evaluate_curve(describe_curve(object), options, tolerance);
}

CurveSamples evaluate_curve_at(const Object& object, std::span<const double> parameters, const FrameOptions& options) {
  return evaluate_curve_at(describe_curve(object), parameters, options);
}

glm::dvec3 curve_position(const Object& object, double parameter) {
  return curve_position(describe_curve(object), parameter);
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
  return {mesh.points, mesh.face_sizes, mesh.face_vertices};
}

}  // namespace sweep
