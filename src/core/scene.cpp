#include "core/scene.hpp"

#include <atomic>

namespace sweep {
namespace {

/// Revisions come from one counter so that no two evaluations, even of different scenes, share one.
std::uint64_t next_revision() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}

void evaluate_object(Scene& scene, const Document& doc, std::size_t i, const EvaluationOptions& options) {
  const Object& object = doc.objects[i];
  EvaluatedObject& out = scene.objects[i];
  out.curve = {};
  out.mesh = {};
  out.diagnostics = {};
  if (is_curve(object.kind)) {
    out.curve = evaluate_curve(object, options.frames);
  } else if (object.kind == ObjectKind::SurfaceOfRevolution) {
    out.mesh = build_surface_of_revolution(scene.objects[static_cast<std::size_t>(object.profile)].curve, object.steps);
  } else {
    out.mesh = build_generalized_cylinder(scene.objects[static_cast<std::size_t>(object.profile)].curve,
                                          scene.objects[static_cast<std::size_t>(object.sweep)].curve, options.seam,
                                          &out.diagnostics);
  }
  out.revision = next_revision();
}

}  // namespace

Scene evaluate_document(const Document& doc, const EvaluationOptions& options) {
  Scene scene;
  scene.objects.resize(doc.objects.size());
  for (std::size_t i = 0; i < doc.objects.size(); ++i) evaluate_object(scene, doc, i, options);
  return scene;
}

std::vector<int> dependents_of(const Document& doc, int index) {
  std::vector<bool> affected(doc.objects.size(), false);
  std::vector<int> result;
  if (index < 0 || static_cast<std::size_t>(index) >= doc.objects.size()) return result;
  affected[static_cast<std::size_t>(index)] = true;
  result.push_back(index);
  // References point backwards, so one forward pass finds everything downstream.
  for (std::size_t i = static_cast<std::size_t>(index) + 1; i < doc.objects.size(); ++i) {
    const Object& o = doc.objects[i];
    const bool uses = (o.profile >= 0 && affected[static_cast<std::size_t>(o.profile)]) ||
                      (o.sweep >= 0 && affected[static_cast<std::size_t>(o.sweep)]);
    if (uses) {
      affected[i] = true;
      result.push_back(static_cast<int>(i));
    }
  }
  return result;
}

std::vector<int> reevaluate(Scene& scene, const Document& doc, int index, const EvaluationOptions& options) {
  scene.objects.resize(doc.objects.size());
  const std::vector<int> changed = dependents_of(doc, index);
  for (int i : changed) evaluate_object(scene, doc, static_cast<std::size_t>(i), options);
  return changed;
}

}  // namespace sweep
