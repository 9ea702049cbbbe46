#include "model/print/print_model.hpp"

#include "base/precondition.hpp"
#include "geometry/thread_pool.hpp"
#include "model/material.hpp"

#include <cstdio>
#include <functional>
#include <set>

namespace sweep {

std::vector<std::size_t> printable_objects(const Document& doc) {
  std::set<int> cages;
  for (const Object& o : doc.objects) {
    if (const auto* subd = std::get_if<SubdivisionSurface>(&o.data)) cages.insert(subd->source);
  }
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const Object& o = doc.objects[i];
    if (is_surface(o.kind()) && !o.name.empty() && !cages.count(static_cast<int>(i))) out.push_back(i);
  }
  return out;
}

PrintModel print_model(const Document& doc, const Scene& scene, double height_mm) {
  SWEEP_EXPECTS(scene.objects.size() == doc.objects.size(), "scene is evaluated from doc");
  const std::vector<std::size_t> objects = printable_objects(doc);
  std::vector<const Mesh*> meshes;
  for (const std::size_t i : objects) meshes.push_back(&scene.objects[i].mesh);
  PrintModel model;
  model.placement = place_on_plate(meshes, height_mm);
  model.parts.resize(objects.size());
  std::vector<std::function<void()>> tasks;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    PrintPart& part = model.parts[k];
    part.object = objects[k];
    part.name = doc.objects[objects[k]].name;
    part.color = surface_material(doc, static_cast<int>(objects[k]), {}).color;
    tasks.push_back(
        [&part, mesh = meshes[k], &placement = model.placement] { part.shell = welded_shell(*mesh, placement); });
  }
  run_side_by_side(tasks, worker_count());
  return model;
}

std::string model_size_text(const PrintPlacement& placement, bool scaled) {
  char text[160];
  std::snprintf(text, sizeof text, "model size %.1f x %.1f x %.1f mm (%s1 model unit = %.4g mm)", placement.size.x,
                placement.size.y, placement.size.z, scaled ? "scaled to the height asked: " : "", placement.scale);
  return text;
}

}  // namespace sweep
