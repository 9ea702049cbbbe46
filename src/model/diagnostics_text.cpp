#include "model/diagnostics_text.hpp"

#include "base/precondition.hpp"
#include "model/evaluation/deviation.hpp"
#include "model/file_limits.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>

namespace sweep::editor {
namespace {

constexpr double kDegrees = 180.0 / std::numbers::pi;

/// printf into a std::string of whatever length the text needs.
template <typename... Args>
std::string printf_string(const char* pattern, Args... args) {
  const int n = std::snprintf(nullptr, 0, pattern, args...);
  if (n <= 0) return {};
  std::string text(std::size_t(n) + 1, '\0');
  std::snprintf(text.data(), text.size(), pattern, args...);
  text.pop_back();
  return text;
}

/// "  bsp2 profile          line 1   ": the keyword in a column as wide as the document's longest
/// keyword (at least 4, so files of 4-letter keywords keep their layout), the name in 16.
std::string object_head(const Document& doc, int index, int keyword_width) {
  const Object& o = doc.objects[std::size_t(index)];
  return printf_string("  %-*s %-16s line %-4d", keyword_width, std::string(keyword(o.kind())).c_str(),
                       display_name(doc, index).c_str(), o.location.line);
}

/// What defines a curve besides STEPS: its points, or its numbers.
std::string curve_numbers(const Object& o) {
  if (const auto* helix = o.find<HelixCurve>()) {
    return printf_string(" radius %g pitch %g turns %g", helix->radius, helix->pitch, helix->turns);
  }
  if (const auto* knot = o.find<TorusKnotCurve>()) {
    return printf_string(" P %d Q %d R %g r %g", knot->knot_p, knot->knot_q, knot->major_radius, knot->radius);
  }
  if (const auto* circle = o.find<CircleCurve>()) return printf_string(" radius %g", circle->radius);
  return printf_string(" %zu control points", points_of(o).size());
}

/// "steps 16    ", or "steps -     " for a kind without STEPS (polylines).
std::string steps_column(const Object& o) {
  const int* steps = steps_field(o);
  return steps ? printf_string("steps %-6d", *steps) : std::string("steps -     ");
}

/// ", deviation 0.00098" when sampling for a tolerance, else nothing.
std::string deviation_text(double tolerance, double deviation) {
  if (tolerance > 0.0 && std::isnan(deviation)) return ", deviation not measured (scale, twist or birail)";
  return tolerance > 0.0 ? printf_string(", deviation %.3g", deviation) : std::string();
}

std::string curve_line(const Document& doc, const EvaluatedObject& e, int index, const EvaluationOptions& options,
                       int keyword_width) {
  const Object& o = doc.objects[std::size_t(index)];
  std::string line = object_head(doc, index, keyword_width) + " ";
  line += steps_column(o);
  line += curve_numbers(o);
  if (const auto* place = o.find<PlacePart>(); place && place->at != glm::dvec3(0.0)) {
    line += printf_string(" at %g %g %g", place->at.x, place->at.y, place->at.z);
  }
  const double own = own_tolerance(o);
  if (own > 0.0) line += printf_string(" tolerance %g", own);
  const double tolerance = options.tolerance > 0.0 ? options.tolerance : own;
  const double deviation = tolerance > 0.0 ? curve_deviation(o, e.curve) : 0.0;
  return line + printf_string(", %zu samples%s", e.curve.frames.size(), e.curve.closed ? ", closed" : "") +
         deviation_text(tolerance, deviation) + "\n";
}

}  // namespace

namespace {

std::string surface_sources(const Document& doc, int index) {
  const Object& o = doc.objects[std::size_t(index)];
  if (const auto* patches = o.find<BezierPatchSurface>()) {
    return std::to_string(patches->points.size() / 16) + " Bezier patches, " + std::to_string(patches->steps) +
           " steps";
  }
  if (const auto* patch = o.find<BSplinePatchSurface>()) {
    return std::to_string(patch->rows) + " x " + std::to_string(patch->columns) + " points, " +
           std::to_string(patch->steps) + " steps";
  }
  if (const auto* cage = o.find<PolygonMeshSurface>()) {
    return std::to_string(cage->points.size()) + " points, " + std::to_string(cage->face_sizes.size()) + " faces";
  }
  if (const auto* subd = o.find<SubdivisionSurface>()) {
    return std::string(subd->loop ? "Loop" : "Catmull-Clark") + " of " + display_name(doc, subd->source) + ", level " +
           std::to_string(subd->levels) + (subd->smooth_boundary ? ", smooth boundary" : "");
  }
  std::string text = "profile " + display_name(doc, o.as<ProfilePart>().profile);
  if (const auto* birail = o.find<BirailSurface>()) {
    text += ", rails " + display_name(doc, birail->rail1) + " and " + display_name(doc, birail->rail2);
  } else if (const auto* cylinder = o.find<CylinderSurface>()) {
    text += ", sweep " + display_name(doc, cylinder->sweep);
    if (cylinder->scale >= 0) text += ", scale " + display_name(doc, cylinder->scale);
    if (cylinder->twist_curve >= 0) {
      text += ", twist " + display_name(doc, cylinder->twist_curve);
    } else if (cylinder->twist != 0.0) {
      text += ", twist " + number_text(cylinder->twist) + " deg";
    }
  }
  const auto* caps = o.find<CapsPart>();
  if (caps && caps->caps) text += ", caps";
  const auto* birail = o.find<BirailSurface>();
  if (birail && birail->height) text += ", height";
  return text;
}

}  // namespace

std::string surface_sources_text(const Document& doc, int index) {
  std::string text = surface_sources(doc, index);
  const Object& o = doc.objects[std::size_t(index)];
  if (o.as<MaterialPart>().material >= 0) (text += ", material ") += display_name(doc, o.as<MaterialPart>().material);
  return text;
}

namespace {

std::string surface_lines(const Document& doc, const Scene& scene, int index, const EvaluationOptions& options,
                          int keyword_width) {
  const EvaluatedObject& e = scene.objects[std::size_t(index)];
  const Object& o = doc.objects[std::size_t(index)];
  std::string line = object_head(doc, index, keyword_width);
  if (const auto* revolution = o.find<RevolutionSurface>()) line += printf_string(" steps %-6d", revolution->copies);
  line += ' ';  // appending rather than " " + text, which trips GCC 12's false -Wrestrict at -O3
  line += surface_sources_text(doc, index);
  line += printf_string(": %zu vertices, %zu triangles", e.mesh.vertex_count(), e.mesh.triangle_count());
  if (swept_curves(o).profile < 0) {  // patches, cages, subdivision: built from points, not sampled curves
    if (options.tolerance > 0.0) line += " (STEPS and LEVELS, not the tolerance)";
    return line + "\n";
  }
  const double deviation = options.tolerance > 0.0 ? surface_deviation(doc, scene, index, options, 8) : 0.0;
  line += deviation_text(options.tolerance, deviation) + "\n";
  if (o.kind() == ObjectKind::GeneralizedCylinder) {  // under the name
    line += std::string(std::size_t(keyword_width) + 3, ' ') + sweep_diagnostics_text(e.diagnostics) + "\n";
  }
  return line;
}

}  // namespace

std::string fold_ranges(const std::vector<FoldRange>& folds) {
  std::string text;
  for (const FoldRange& fold : folds) {
    text += printf_string("%st = %.2f to %.2f", text.empty() ? "" : ", ", fold.t_begin, fold.t_end);
  }
  return text;
}

std::string sweep_diagnostics_text(const SweepDiagnostics& d) {
  return printf_string("%s, seam angle %.2f deg, total twist %.2f deg, ", d.closed ? "closed sweep" : "open sweep",
                       d.seam_angle * kDegrees, d.total_twist * kDegrees) +
         (d.folds.empty() ? std::string("no folds") : "folds at " + fold_ranges(d.folds));
}

std::string fold_warning(const std::string& name, const SweepDiagnostics& diagnostics) {
  return "warning: surface '" + name +
         "' folds over itself where the profile reaches beyond the sweep's radius of curvature (" +
         fold_ranges(diagnostics.folds) + ")";
}

/// "  material wood  line 3  color 0.6 0.4 0.2, shininess 20, texture wood.png".
std::string material_line(const Document& doc, int index, int keyword_width) {
  const MaterialLook& m = doc.objects[std::size_t(index)].as<MaterialLook>();
  std::string line = object_head(doc, index, keyword_width) +
                     printf_string(" color %g %g %g, shininess %g", m.color.x, m.color.y, m.color.z, m.shininess);
  if (!m.texture.empty()) (line += ", texture ") += m.texture;
  if (m.checker > 0) line += printf_string(", checker %d", m.checker);
  if (!m.bump.empty()) (line += ", bump ") += m.bump + printf_string(" %g", m.bump_height);
  return line + "\n";
}

/// "  rider  car  line 9  track (length 25.1), model car-body, 10 s a loop, start 0.25, up 0 1 0".
static std::string rider_line(const Document& doc, const Scene& scene, int index, int keyword_width) {
  const RiderObject& r = doc.objects[std::size_t(index)].as<RiderObject>();
  std::string line = object_head(doc, index, keyword_width) + " ";
  line += display_name(doc, r.path);
  line += printf_string(" (length %g), model ", scene.objects[std::size_t(index)].track.length());
  line += display_name(doc, r.model) + printf_string(", %g s a loop", r.seconds);
  if (r.start != 0.0) line += printf_string(", start %g", r.start);
  if (r.up != glm::dvec3(0.0)) line += printf_string(", up %g %g %g", r.up.x, r.up.y, r.up.z);
  return line + "\n";
}

std::string document_summary(const Document& doc, const Scene& scene, const std::string& file,
                             const EvaluationOptions& options) {
  SWEEP_EXPECTS(scene.objects.size() == doc.objects.size(), "scene is evaluated from doc");
  std::string text = printf_string("%s: %zu objects", file.c_str(), doc.objects.size());
  if (options.tolerance > 0.0) {
    text += printf_string(", sampled for a tolerance of %g (deviation: measured against a reference 64 times denser)",
                          options.tolerance);
  }
  text += "\n";
  std::size_t width = 4;
  for (const Object& o : doc.objects) width = std::max(width, keyword(o.kind()).size());
  const int keyword_width = static_cast<int>(width);
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const int index = static_cast<int>(i);
    if (is_material(doc.objects[i].kind())) {
      text += material_line(doc, index, keyword_width);
      continue;
    }
    if (is_rider(doc.objects[i].kind())) {
      text += rider_line(doc, scene, index, keyword_width);
      continue;
    }
    text += is_curve(doc.objects[i].kind()) ? curve_line(doc, scene.objects[i], index, options, keyword_width)
                                            : surface_lines(doc, scene, index, options, keyword_width);
  }
  return text;
}

std::string over_limit_message(const Document& doc, int index, double tolerance) {
  return printf_string(
      "tolerance %g is too small for '%s': it needs more than %lld samples per curve or %lld "
      "vertices per surface; use a larger one",
      tolerance, display_name(doc, index).c_str(), static_cast<long long>(limits::kMaxCurveSamples),
      static_cast<long long>(limits::kMaxMeshVertices));
}

}  // namespace sweep::editor
