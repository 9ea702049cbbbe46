// Creating objects: curves from templates and surfaces from existing curves.
#include "model/edit.hpp"

#include "geometry/sweep_controls.hpp"
#include "model/edit_support.hpp"
#include "model/file_limits.hpp"
#include "model/surface_validation.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <numbers>
#include <vector>

namespace sweep {

using namespace edit_support;

std::string unique_name(const Document& doc, std::string_view base) {
  // Make the base a valid name first, so the result always is one.
  std::string stem;
  for (char ch : base) {
    const auto c = static_cast<unsigned char>(ch);
    stem += std::isalnum(c) || c == '_' || c == '-' || c == '.' ? ch : '_';
  }
  if (stem.empty()) stem = "object";
  if (!std::isalpha(static_cast<unsigned char>(stem[0])) && stem[0] != '_') stem.insert(stem.begin(), '_');
  stem.resize(std::min(stem.size(), limits::kMaxNameLength - 20));  // room for the number
  if (doc.find(stem) < 0) return stem;
  for (std::uint64_t k = 2;; ++k) {
    std::string candidate = stem + std::to_string(k);
    if (doc.find(candidate) < 0) return candidate;
  }
}

namespace {

/// The templates of the curve kinds added after the first six.
void set_new_kind_template(Object& curve, CurveTemplate shape) {
  using P = glm::dvec3;
  // Open 2D templates are profiles: left of the y axis, top to bottom, as the course's are, so a
  // surface of revolution of one is a solid's side rather than a flat dome.
  const std::vector<P> wave{P(-0.3, 0.6, 0), P(-0.45, 0.3, 0), P(-0.3, 0, 0), P(-0.45, -0.3, 0), P(-0.3, -0.6, 0)};
  switch (shape) {
    case CurveTemplate::CatmullRom2:
      curve.set_kind(ObjectKind::CatmullRom2);
      curve.as<PointsPart>().points = wave;
      break;
    case CurveTemplate::ClosedCatmullRom2:
      curve.set_kind(ObjectKind::CatmullRom2);
      curve.as<PointsPart>().points =
          closed_polygon(ObjectKind::CatmullRom2,
                         {P(0.5, 0, 0), P(0.15, 0.48, 0), P(-0.4, 0.29, 0), P(-0.4, -0.29, 0), P(0.15, -0.48, 0)});
      break;
    case CurveTemplate::CatmullRom3:
      curve.set_kind(ObjectKind::CatmullRom3);
      curve.as<PointsPart>().points = {P(-0.6, 0, -0.3), P(-0.3, 0.25, -0.15), P(0, 0, 0), P(0.3, -0.25, 0.15),
                                       P(0.6, 0, 0.3)};
      break;
    case CurveTemplate::KochanekBartels2:
      curve.set_kind(ObjectKind::KochanekBartels2);
      curve.as<PointsPart>().points = wave;
      break;
    case CurveTemplate::Helix:
      curve.set_kind(ObjectKind::Helix);
      curve.as<StepsPart>().steps = 48;
      curve.as<RadiusPart>().radius = 0.5;
      curve.as<HelixCurve>().pitch = 0.4;
      curve.as<HelixCurve>().turns = 3.0;
      break;
    case CurveTemplate::Star2: {  // outer points at radius 0.5, inner at 0.2, the first at the top
      curve.set_kind(ObjectKind::Polyline2);
      std::vector<P> star;
      for (int k = 0; k < 10; ++k) {
        const double angle = std::numbers::pi / 2.0 + k * std::numbers::pi / 5.0;
        const double r = k % 2 == 0 ? 0.5 : 0.2;
        star.push_back(P(r * std::cos(angle), r * std::sin(angle), 0.0));
      }
      curve.as<PointsPart>().points = closed_polygon(ObjectKind::Polyline2, std::move(star));
      break;
    }
    case CurveTemplate::OpenBSpline2:  // the first six: add_curve
    case CurveTemplate::ClosedBSpline2:
    case CurveTemplate::OpenBSpline3:
    case CurveTemplate::Bezier2:
    case CurveTemplate::Bezier3:
    case CurveTemplate::Circle:
      break;
    case CurveTemplate::TrefoilKnot:
      curve.set_kind(ObjectKind::TorusKnot);
      curve.as<StepsPart>().steps = 240;
      curve.as<TorusKnotCurve>().knot_p = 2;
      curve.as<TorusKnotCurve>().knot_q = 3;
      curve.as<TorusKnotCurve>().major_radius = 1.0;
      curve.as<RadiusPart>().radius = 0.4;
      break;
  }
}

}  // namespace

std::span<const CurveTemplateInfo> curve_templates() {
  static constexpr CurveTemplateInfo kTemplates[] = {
      {CurveTemplate::OpenBSpline2, "open B-spline (2D)", "curve"},
      {CurveTemplate::ClosedBSpline2, "closed B-spline (2D)", "curve"},
      {CurveTemplate::OpenBSpline3, "open B-spline (3D)", "curve"},
      {CurveTemplate::Bezier2, "Bezier (2D)", "curve"},
      {CurveTemplate::Bezier3, "Bezier (3D)", "curve"},
      {CurveTemplate::Circle, "circle", "circle"},
      {CurveTemplate::CatmullRom2, "Catmull-Rom (2D)", "curve"},
      {CurveTemplate::ClosedCatmullRom2, "closed Catmull-Rom (2D)", "curve"},
      {CurveTemplate::CatmullRom3, "Catmull-Rom (3D)", "curve"},
      {CurveTemplate::KochanekBartels2, "Kochanek-Bartels (2D)", "curve"},
      {CurveTemplate::Helix, "helix", "helix"},
      {CurveTemplate::TrefoilKnot, "trefoil knot", "knot"},
      {CurveTemplate::Star2, "star polyline (2D)", "star"},
  };
  return kTemplates;
}

int add_curve(Document& doc, CurveTemplate shape, const std::string& name) {
  check_new_name(doc, -1, name);
  Object curve;
  curve.name = name;
  using P = glm::dvec3;
  switch (shape) {
    case CurveTemplate::OpenBSpline2:
      curve.set_kind(ObjectKind::BSpline2);
      curve.as<PointsPart>().points = {P(-0.2, 0.5, 0),   P(-0.35, 0.35, 0),  P(-0.45, 0.1, 0),
                                       P(-0.45, -0.1, 0), P(-0.35, -0.35, 0), P(-0.2, -0.5, 0)};
      break;
    case CurveTemplate::ClosedBSpline2:
      // A counterclockwise hexagon of radius 0.5 (0.433 ~ 0.5 sin 60 deg) closed by repeating its
      // first three points.
      curve.set_kind(ObjectKind::BSpline2);
      curve.as<PointsPart>().points =
          closed_polygon(ObjectKind::BSpline2, {P(0.5, 0, 0), P(0.25, 0.433, 0), P(-0.25, 0.433, 0), P(-0.5, 0, 0),
                                                P(-0.25, -0.433, 0), P(0.25, -0.433, 0)});
      break;
    case CurveTemplate::OpenBSpline3:
      curve.set_kind(ObjectKind::BSpline3);
      curve.as<PointsPart>().points = {P(-0.5, -0.2, -0.25), P(-0.3, 0.05, -0.15), P(-0.1, 0.15, -0.05),
                                       P(0.1, 0.15, 0.05),   P(0.3, 0.05, 0.15),   P(0.5, -0.2, 0.25)};
      break;
    case CurveTemplate::Bezier2:
      // An S profile of two pieces with a smooth joint at (-0.35, 0) (handles collinear with it).
      curve.set_kind(ObjectKind::Bezier2);
      curve.as<PointsPart>().points = {P(-0.2, 0.5, 0),  P(-0.5, 0.5, 0),  P(-0.5, 0.2, 0), P(-0.35, 0, 0),
                                       P(-0.2, -0.2, 0), P(-0.2, -0.5, 0), P(-0.5, -0.5, 0)};
      break;
    case CurveTemplate::Bezier3:
      curve.set_kind(ObjectKind::Bezier3);
      curve.as<PointsPart>().points = {P(-0.5, 0, -0.25),  P(-0.5, 0.3, -0.15), P(-0.2, 0.3, -0.05), P(0, 0, 0),
                                       P(0.2, -0.3, 0.05), P(0.5, -0.3, 0.15),  P(0.5, 0, 0.25)};
      break;
    case CurveTemplate::Circle:
      curve.set_kind(ObjectKind::Circle);
      curve.as<StepsPart>().steps = 32;
      curve.as<RadiusPart>().radius = 1.0;
      break;
    case CurveTemplate::CatmullRom2:
    case CurveTemplate::ClosedCatmullRom2:
    case CurveTemplate::CatmullRom3:
    case CurveTemplate::KochanekBartels2:
    case CurveTemplate::Helix:
    case CurveTemplate::TrefoilKnot:
    case CurveTemplate::Star2:
      set_new_kind_template(curve, shape);
      break;
  }
  if (auto* steps = curve.find<StepsPart>(); steps && steps->steps == 0) steps->steps = 16;  // the templates' default
  check_caps(doc, -1, nullptr, &curve);
  doc.objects.push_back(std::move(curve));
  return to_int(doc.objects.size() - 1);
}

namespace {

/// Fills a new surface's fixed fields as its kind lists them (`fields`, object.hpp): its STEPS
/// and its references in order (profile, then sweep or rails), each checked by the reader's
/// rule (check_reference_kind) and as the editor needs (in range, named).
struct SurfaceFieldsSetter {
  const Document& doc;
  std::array<int, 3> references;  // in the order the kind lists them
  int steps_value;
  std::size_t next = 0;

  void steps(int& steps) {
    if (steps_value < 1 || steps_value > limits::kMaxSteps) {
      throw EditError("STEPS must be from 1 to " + std::to_string(limits::kMaxSteps) + ", not " +
                      std::to_string(steps_value));
    }
    steps = steps_value;
  }
  void reference(const char* role, int& index, bool planar_only) {
    index = references[next++];
    if (index < 0 || to_size(index) >= doc.objects.size()) {
      throw EditError(std::string("the ") + role + " " + std::to_string(index) + " is out of range: the document has " +
                      std::to_string(doc.objects.size()) + (doc.objects.size() == 1 ? " object" : " objects"));
    }
    const Object& target = doc.objects[to_size(index)];
    if (const auto problem = check_reference_kind(target, role, planar_only)) {
      throw EditError(quoted(doc, index) + ": " + problem->expected + " (" + problem->note + ")");
    }
    if (target.name.empty()) {
      throw EditError("curve " + quoted(doc, index) +
                      " has no name: a surface can only use a named curve (name it first)");
    }
  }
  void vertices(VerticesAt) {}
  void points(auto&, const char*) {}
  void samples(std::int64_t) {}
  void samples_by(std::int64_t, const char*) {}
  void number(FieldName, double&, auto&&...) {}
  void integer(FieldName, int&, int, int, auto&&...) {}
  void custom(auto&) {}
};

/// Surfaces made of curves: their kinds have a profile (srev, gcyl, birail).
bool is_swept_kind(ObjectKind kind) {
  return Object(kind).find<ProfilePart>() != nullptr;
}

}  // namespace

int add_surface(Document& doc, ObjectKind kind, const std::string& name, int profile, int sweep, int steps, int rail2) {
  if (!is_swept_kind(kind)) {
    std::string swept;
    for (const KindInfo& info : kinds()) {
      if (!is_swept_kind(info.kind)) continue;
      if (!swept.empty()) swept += ", ";
      swept += std::string(info.phrase) + " (" + std::string(info.keyword) + ")";
    }
    if (const auto last = swept.rfind(", "); last != std::string::npos) swept.replace(last, 2, " or ");
    throw EditError("a surface must be " + swept + ", not " + std::string(keyword(kind)));
  }
  check_new_name(doc, -1, name);
  Object surface;
  surface.set_kind(kind);
  surface.name = name;
  SurfaceFieldsSetter setter{doc, {profile, sweep, rail2}, steps};
  std::visit([&setter](auto& data) { std::decay_t<decltype(data)>::fields(data, setter); }, surface.data);
  check_caps(doc, -1, nullptr, &surface);
  if (const std::optional<CurveProblem> problem = check_surface_curves(doc, surface)) {
    throw EditError(problem->expected + (problem->note.empty() ? std::string() : " (" + problem->note + ")"));
  }
  doc.objects.push_back(std::move(surface));
  return to_int(doc.objects.size() - 1);
}

}  // namespace sweep
