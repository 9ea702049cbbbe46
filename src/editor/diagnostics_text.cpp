#include "editor/diagnostics_text.hpp"

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

/// What defines a curve besides STEPS: its points, or its numbers.
std::string curve_numbers(const Object& o) {
  switch (o.kind) {
    case ObjectKind::Circle:
      return printf_string(" radius %g", o.radius);
    case ObjectKind::Helix:
      return printf_string(" radius %g pitch %g turns %g", o.radius, o.pitch, o.turns);
    case ObjectKind::TorusKnot:
      return printf_string(" P %d Q %d R %g r %g", o.knot_p, o.knot_q, o.major_radius, o.radius);
    default:
      return printf_string(" %zu control points", o.points.size());
  }
}

std::string curve_line(const Document& doc, const EvaluatedObject& e, int index) {
  const Object& o = doc.objects[std::size_t(index)];
  std::string line = printf_string("  %-4s %-16s line %-4d steps %-6d", std::string(keyword(o.kind)).c_str(),
                                   display_name(doc, index).c_str(), o.location.line, o.steps);
  line += curve_numbers(o);

  return line + printf_string(", %zu samples%s\n", e.curve.frames.size(), e.curve.closed ? ", closed" : "");
}

std::string surface_lines(const Document& doc, const EvaluatedObject& e, int index) {
  const Object& o = doc.objects[std::size_t(index)];
  std::string line = printf_string("  %-4s %-16s line %-4d", std::string(keyword(o.kind)).c_str(),
                                   display_name(doc, index).c_str(), o.location.line);
  if (o.kind == ObjectKind::SurfaceOfRevolution) {
    line += printf_string(" steps %-6d profile %s", o.steps, display_name(doc, o.profile).c_str());
  } else {
    line += printf_string(" profile %s, sweep %s", display_name(doc, o.profile).c_str(),
                          display_name(doc, o.sweep).c_str());
  }
  line += printf_string(": %zu vertices, %zu triangles\n", e.mesh.vertex_count(), e.mesh.triangle_count());
  if (o.kind == ObjectKind::GeneralizedCylinder) line += "       " + sweep_diagnostics_text(e.diagnostics) + "\n";
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

std::string document_summary(const Document& doc, const Scene& scene, const std::string& file) {
  std::string text = printf_string("%s: %zu objects\n", file.c_str(), doc.objects.size());
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const int index = static_cast<int>(i);
    text += is_curve(doc.objects[i].kind) ? curve_line(doc, scene.objects[i], index)
                                          : surface_lines(doc, scene.objects[i], index);
  }
  return text;
}

}  // namespace sweep::editor
