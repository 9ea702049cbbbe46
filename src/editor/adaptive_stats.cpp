#include "editor/adaptive_stats.hpp"

#include "core/adaptive.hpp"
#include "editor/diagnostics_text.hpp"

namespace sweep::editor {

SamplingCounts scene_counts(const Scene& scene) {
  SamplingCounts counts;
  for (const EvaluatedObject& e : scene.objects) {
    counts.vertices += static_cast<std::int64_t>(e.mesh.vertex_count());
    counts.triangles += static_cast<std::int64_t>(e.mesh.triangle_count());
    counts.curve_samples += static_cast<std::int64_t>(e.curve.frames.size());
  }
  return counts;
}

SamplingCounts steps_counts(const Document& doc, const Scene& scene) {
  SamplingCounts counts;
  std::vector<std::int64_t> samples(doc.objects.size(), 0);
  const auto closed = [&](int index) {
    const auto i = static_cast<std::size_t>(index);
    return i < scene.objects.size() && scene.objects[i].curve.closed;
  };
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const Object& o = doc.objects[i];
    if (is_curve(o.kind)) {
      samples[i] = curve_sample_count(o);
      counts.curve_samples += samples[i];
      continue;
    }
    const std::int64_t profile = samples[static_cast<std::size_t>(o.profile)];
    if (o.kind == ObjectKind::SurfaceOfRevolution) {
      counts.vertices += revolution_vertex_count(profile, closed(o.profile), o.steps);
      counts.triangles += 2 * (profile - 1) * o.steps;
    } else {
      const std::int64_t sweep = samples[static_cast<std::size_t>(o.sweep)];
      counts.vertices += cylinder_vertex_count(profile, closed(o.profile), sweep, closed(o.sweep));
      counts.triangles += 2 * (profile - 1) * (sweep - 1);
    }
  }
  return counts;
}

std::vector<std::string> over_limit_messages(const Document& doc, const Scene& scene, double tolerance) {
  std::vector<std::string> messages;
  for (std::size_t i = 0; i < doc.objects.size() && i < scene.objects.size(); ++i) {
    if (!scene.objects[i].over_limit) continue;
    const double used = tolerance > 0.0 ? tolerance : doc.objects[i].tolerance;
    messages.push_back(over_limit_message(doc, static_cast<int>(i), used));
  }
  return messages;
}

ToleranceRange tolerance_range(double extent) {
  if (!(extent > 0.0)) return {};
  return {kMinRelativeTolerance * extent, 0.1 * extent};
}

}  // namespace sweep::editor
