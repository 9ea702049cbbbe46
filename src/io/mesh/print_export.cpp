#include "io/mesh/print_export.hpp"

#include "base/precondition.hpp"
#include "io/mesh/stl_writer.hpp"
#include "io/mesh/threemf_writer.hpp"
#include "model/print/printability.hpp"

#include <filesystem>

namespace sweep::io {
namespace {

/// The triangles of `shells` as one mesh of positions (what an STL file holds), in millimetres
/// on the plate or, `in_model_units`, back where the model has them.
Mesh stl_mesh(std::span<const PrintPart* const> parts, const PrintPlacement& placement, bool in_model_units) {
  Mesh mesh;
  for (const PrintPart* part : parts) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (const glm::dvec3& p : part->shell.positions) {
      mesh.positions.emplace_back(in_model_units ? unplaced(placement, p) : p);
    }
    for (const std::uint32_t i : part->shell.indices) mesh.indices.push_back(base + i);
  }
  return mesh;
}

ExportedFile planned_file(const std::string& path, const Mesh& mesh) {
  return {path, mesh.vertex_count(), mesh.triangle_count(), {}, false};
}

void plan_stl(const std::string& source, const std::string& prefix, const PrintOptions& options, PrintPlan& plan,
              std::vector<ExportOutput>& outputs, ExportReport& report) {
  const bool placed = options.merge || options.height_mm > 0.0;
  std::vector<std::vector<const PrintPart*>> files;
  for (const PrintPart& part : plan.model.parts) {
    if (!options.merge || files.empty()) files.emplace_back();
    files.back().push_back(&part);
  }
  plan.meshes.reserve(files.size());  // the writers point into it
  for (const std::vector<const PrintPart*>& parts : files) {
    plan.meshes.push_back(stl_mesh(parts, plan.model.placement, !placed));
    const std::string name = options.merge ? std::string() : parts.front()->name;
    const std::string path = options.merge ? prefix + ".stl" : prefix + "_" + name + ".stl";
    const std::string header = (options.merge ? std::string("model") : name) + " from " + source;
    outputs.push_back({path, [mesh = &plan.meshes.back(), header](const std::string& staged) {
                         save_stl_file(staged, *mesh, header);
                       }});
    report.files.push_back(planned_file(path, plan.meshes.back()));
  }
  if (placed) report.notes.push_back(model_size_text(plan.model.placement, options.height_mm > 0.0));
}

void plan_3mf(const std::string& prefix, PrintPlan& plan, std::vector<ExportOutput>& outputs, ExportReport& report,
              bool scaled) {
  ExportedFile file{prefix + ".3mf", 0, 0, {}, false};
  for (const PrintPart& part : plan.model.parts) {
    file.vertices += part.shell.vertex_count();
    file.triangles += part.shell.triangle_count();
  }
  report.notes.push_back(model_size_text(plan.model.placement, scaled));
  outputs.push_back({file.path, [model = &plan.model, name = std::filesystem::path(prefix).filename().string()](
                                    const std::string& staged) { save_3mf_file(staged, *model, name); }});
  report.files.push_back(std::move(file));
}

}  // namespace

void plan_print_export(const Document& doc, const Scene& scene, const std::string& source, const std::string& prefix,
                       ExportFormat format, const PrintOptions& options, PrintPlan& plan,
                       std::vector<ExportOutput>& outputs, ExportReport& report) {
  SWEEP_EXPECTS(format == ExportFormat::ThreeMf || format == ExportFormat::Stl, "a print format");
  plan.model = print_model(doc, scene, options.height_mm);
  if (plan.model.parts.empty()) return;
  PrintCheckOptions checks;
  checks.min_wall_mm = options.min_wall_mm;
  checks.together = format == ExportFormat::ThreeMf || options.merge;  // one object on the plate
  report.findings = check_print(doc, plan.model, source, checks);
  for (const PrintFinding& finding : report.findings) report.warnings.push_back(finding.message);
  if (format == ExportFormat::Stl) {
    plan_stl(source, prefix, options, plan, outputs, report);
  } else {
    plan_3mf(prefix, plan, outputs, report, options.height_mm > 0.0);
  }
}

}  // namespace sweep::io
