#include "editor/adaptive_stats.hpp"

#include "base/precondition.hpp"
#include "geometry/curves/adaptive.hpp"
#include "geometry/surfaces/surface.hpp"
#include "model/diagnostics_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace sweep::editor {
namespace {

bool shown(const std::vector<bool>& visible, std::size_t i) {
  return visible.empty() || (i < visible.size() && visible[i]);
}

/// "N" or "N (by STEPS M)".
std::string count_text(std::int64_t sampled, std::int64_t by_steps, bool adaptive) {
  std::string text = std::to_string(sampled);
  if (adaptive) text += " (by STEPS " + std::to_string(by_steps) + ")";
  return text;
}

}  // namespace

SamplingCounts scene_counts(const Scene& scene, const std::vector<bool>& visible) {
  SamplingCounts counts;
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    if (!shown(visible, i)) continue;
    const EvaluatedObject& e = scene.objects[i];
    counts.vertices += static_cast<std::int64_t>(e.mesh.vertex_count());
    counts.triangles += static_cast<std::int64_t>(e.mesh.triangle_count());
    counts.curve_samples += static_cast<std::int64_t>(e.curve.frames.size());
  }
  return counts;
}

SamplingCounts steps_counts(const Document& doc, const Scene& scene, const std::vector<bool>& visible) {
  SWEEP_EXPECTS(scene.objects.size() == doc.objects.size(), "scene is evaluated from doc");
  SamplingCounts counts;
  std::vector<std::int64_t> samples(doc.objects.size(), 0);
  const auto closed = [&](int index) {
    const auto i = static_cast<std::size_t>(index);
    return i < scene.objects.size() && scene.objects[i].curve.closed;
  };
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const Object& o = doc.objects[i];
    if (is_curve(o.kind())) {
      samples[i] = curve_sample_count(o);  // hidden curves too: their surfaces are built on them
      if (shown(visible, i)) counts.curve_samples += samples[i];
      continue;
    }
    if (!shown(visible, i)) continue;
    const SweptCurves curves = swept_curves(o);
    if (curves.profile < 0) {  // patches, cages, subdivision: the tolerance does not change them
      counts.vertices += static_cast<std::int64_t>(scene.objects[i].mesh.vertex_count());
      counts.triangles += static_cast<std::int64_t>(scene.objects[i].mesh.triangle_count());
      continue;
    }
    const std::int64_t profile = samples[static_cast<std::size_t>(curves.profile)];
    if (const auto* revolution = o.find<RevolutionSurface>()) {
      counts.vertices += revolution_vertex_count(profile, closed(curves.profile), revolution->copies);
      // Less a triangle a copy at each end on the axis (a pole's fan): the ends are the curve's
      // own, sampled alike by STEPS and by tolerance.
      const std::vector<Frame>& frames = scene.objects[static_cast<std::size_t>(curves.profile)].curve.frames;
      const std::int64_t poles =
          frames.empty() ? 0
                         : (on_revolution_axis(frames.front()) ? 1 : 0) + (on_revolution_axis(frames.back()) ? 1 : 0);
      counts.triangles += (2 * (profile - 1) - poles) * revolution->copies;
    } else {
      const std::int64_t sweep = samples[static_cast<std::size_t>(curves.path)];
      // Which corners are bevelled does not depend on the sampling: the scene's count holds.
      const auto bevels = static_cast<std::int64_t>(scene.objects[i].diagnostics.bevels);
      counts.vertices += cylinder_vertex_count(profile, closed(curves.profile), sweep, closed(curves.path), bevels);
      counts.triangles += cylinder_triangle_count(profile, sweep, bevels);
    }
  }
  return counts;
}

bool any_adaptive(const Document& doc, const EvaluationOptions& options) {
  return options.tolerance > 0.0 ||
         std::any_of(doc.objects.begin(), doc.objects.end(), [](const Object& o) { return own_tolerance(o) > 0.0; });
}

std::vector<std::string> over_limit_messages(const Document& doc, const Scene& scene, double tolerance) {
  std::vector<std::string> messages;
  for (std::size_t i = 0; i < doc.objects.size() && i < scene.objects.size(); ++i) {
    if (!scene.objects[i].over_limit) continue;
    const Object& object = doc.objects[i];
    const double used = tolerance > 0.0 ? tolerance : own_tolerance(object);
    // What evaluate_document does instead: a curve takes its STEPS; a surface is built on its
    // curves as the scene samples them (surface_sampling), which the tolerance may not cover.
    messages.push_back(over_limit_message(doc, static_cast<int>(i), used) +
                       (is_curve(object.kind()) ? " (sampled by STEPS instead)"
                                                : " (meshed on its curves' own samples instead, not within it)"));
  }
  return messages;
}

SamplingSummary sampling_summary(const Document& doc, const Scene& scene, const EvaluationOptions& options,
                                 const std::vector<bool>& visible) {
  SWEEP_EXPECTS(scene.objects.size() == doc.objects.size(), "scene is evaluated from doc");
  SamplingSummary summary;
  summary.adaptive = any_adaptive(doc, options);
  summary.sampled = scene_counts(scene, visible);
  summary.by_steps = summary.adaptive ? steps_counts(doc, scene, visible) : summary.sampled;
  summary.over_limit = over_limit_messages(doc, scene, options.tolerance);
  return summary;
}

std::string share_text(std::int64_t part, std::int64_t whole) {
  if (whole <= 0) return "-";
  const double ratio = double(part) / double(whole);
  if (ratio >= 10.0) return std::to_string(static_cast<long long>(std::llround(ratio))) + "x";
  return std::to_string(static_cast<long long>(std::llround(100.0 * ratio))) + " %";
}

std::string summary_line(const SamplingSummary& summary) {
  const SamplingCounts& a = summary.sampled;
  const SamplingCounts& b = summary.by_steps;
  return "vertices " + count_text(a.vertices, b.vertices, summary.adaptive) + " triangles " +
         count_text(a.triangles, b.triangles, summary.adaptive) + " curve samples " +
         count_text(a.curve_samples, b.curve_samples, summary.adaptive);
}

ToleranceRange tolerance_range(double extent) {
  if (!(extent > 0.0)) return {};
  return {kMinRelativeTolerance * extent, 0.1 * extent};
}

double default_tolerance(double extent) {
  return extent > 0.0 ? 1e-3 * extent : 0.0;
}

double tolerance_at(const ToleranceRange& range, double position) {
  SWEEP_EXPECTS(range.low > 0.0 && range.low <= range.high, "0 < range.low <= range.high");
  const auto shown = [](double d) { return std::strtod(tolerance_text(d).c_str(), nullptr); };
  const double t = std::clamp(position, 0.0, 1.0);
  double d = shown(range.low * std::pow(range.high / range.low, t));
  // Rounded past an end: the nearest value shown inside (0.5 % moves past any rounding).
  if (d < range.low) d = shown(range.low * 1.005);
  if (d > range.high) d = shown(range.high * 0.995);
  return std::clamp(d, range.low, range.high);
}

double slider_position(const ToleranceRange& range, double tolerance) {
  SWEEP_EXPECTS(range.low > 0.0 && range.low <= range.high, "0 < range.low <= range.high");
  if (!(range.high > range.low) || !(tolerance > 0.0)) return 0.0;
  return std::clamp(std::log(tolerance / range.low) / std::log(range.high / range.low), 0.0, 1.0);
}

std::string tolerance_text(double tolerance) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2e", tolerance);
  return text;
}

}  // namespace sweep::editor
