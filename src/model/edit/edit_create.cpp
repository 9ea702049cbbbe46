// Creating objects: curves from templates and surfaces from existing curves.
#include "model/edit/edit.hpp"

#include "geometry/surfaces/sweep_controls.hpp"
#include "model/edit/edit_support.hpp"
#include "model/file_limits.hpp"
#include "model/surface_validation.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <type_traits>
#include <utility>
#include <variant>
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

/// Collects one kind's templates (its `templates`, kind_fields.hpp) as type-free rows.
template <std::size_t I>
struct TemplateCollector {
  using Kind = std::variant_alternative_t<I, Payload>;
  std::vector<CurveTemplateInfo>& rows;
  template <typename Fill>
  void add(std::string_view label, std::string_view base_name, int order, Fill) {
    static_assert(std::is_empty_v<Fill>, "a template's fill captures nothing");
    rows.push_back({label, base_name, static_cast<ObjectKind>(I), order, [] {
                      Object curve(static_cast<ObjectKind>(I));
                      Fill{}(curve.as<Kind>());
                      return curve;
                    }});
  }
};

template <std::size_t... I>
std::vector<CurveTemplateInfo> collect_templates(std::index_sequence<I...>) {
  std::vector<CurveTemplateInfo> rows;
  (
      [&] {
        using Kind = std::variant_alternative_t<I, Payload>;
        if constexpr (Kind::traits.family == KindFamily::Curve) {
          static_assert(
              requires(TemplateCollector<I> & t) { Kind::templates(t); },
              "every curve kind declares its Create-panel templates (none: an empty `templates`)");
          TemplateCollector<I> collector{rows};
          Kind::templates(collector);
        }
      }(),
      ...);
  std::stable_sort(rows.begin(), rows.end(),
                   [](const CurveTemplateInfo& a, const CurveTemplateInfo& b) { return a.order < b.order; });
  return rows;
}

}  // namespace

std::span<const CurveTemplateInfo> curve_templates() {
  static const std::vector<CurveTemplateInfo> kTemplates =
      collect_templates(std::make_index_sequence<std::variant_size_v<Payload>>());
  return kTemplates;
}

int add_curve(Document& doc, std::string_view label, const std::string& name) {
  const auto templates = curve_templates();
  const auto chosen = std::find_if(templates.begin(), templates.end(),
                                   [label](const CurveTemplateInfo& row) { return row.label == label; });
  if (chosen == templates.end()) throw EditError("there is no curve template '" + std::string(label) + "'");
  check_new_name(doc, -1, name);
  Object curve = chosen->make();
  curve.name = name;
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
