#include "editor/surface_export.hpp"

#include "core/mesh_topology.hpp"
#include "core/obj_writer.hpp"
#include "core/stl_writer.hpp"
#include "editor/diagnostics_text.hpp"

#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace sweep::editor {
namespace {

/// Named surfaces, in document order.
std::vector<std::size_t> exported_objects(const Document& doc) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    if (is_surface(doc.objects[i].kind) && !doc.objects[i].name.empty()) out.push_back(i);
  }
  return out;
}

void check_meshes(const Document& doc, const Scene& scene, const std::vector<std::size_t>& objects,
                  const std::string& source) {
  for (std::size_t i : objects) {
    const Object& o = doc.objects[i];
    if (mesh_is_finite(scene.objects[i].mesh)) continue;
    throw ExportError(source + ":" + std::to_string(o.location.line) + ":" + std::to_string(o.location.column) +
                      ": surface '" + o.name + "' has a NaN or infinite coordinate; nothing written");
  }
}

void remove_quietly(const std::vector<std::string>& paths) {
  std::error_code ignored;
  for (const std::string& path : paths) std::filesystem::remove(path, ignored);
}

std::string manifold_warning(const std::string& name, const MeshTopology& topology, const std::string& path) {
  return "warning: surface '" + name + "' is not a closed manifold (" + std::to_string(topology.boundary_edges) +
         " boundary edges, " + std::to_string(topology.non_manifold_edges) +
         " non-manifold edges); a printer may reject " + path;
}

std::string staged_path(const std::string& path) {
  return path + ".export-tmp";
}

std::string set_aside_path(const std::string& path) {
  return path + ".export-old";
}

/// Renames every staged file over its target. The old targets are set aside first and put back
/// if any rename fails, so the set of files changes all at once or not at all.
void install(const std::vector<std::string>& staged, const std::vector<ExportedFile>& files) {
  namespace fs = std::filesystem;
  for (const ExportedFile& file : files) {  // a folder in the way is the user's: never moved
    if (fs::is_directory(file.path)) throw std::runtime_error("cannot write " + file.path + ": Is a directory");
  }
  std::vector<std::string> set_aside;  // targets that existed, now under set_aside_path
  std::vector<std::string> installed;
  try {
    for (std::size_t k = 0; k < staged.size(); ++k) {
      const std::string& target = files[k].path;
      if (fs::exists(fs::symlink_status(target))) {
        fs::rename(target, set_aside_path(target));
        set_aside.push_back(target);
      }
      fs::rename(staged[k], target);
      installed.push_back(target);
    }
  } catch (...) {
    remove_quietly(installed);
    std::error_code ignored;
    for (const std::string& target : set_aside) fs::rename(set_aside_path(target), target, ignored);
    throw;
  }
  for (const std::string& target : set_aside) remove_quietly({set_aside_path(target)});
}

}  // namespace

ExportReport export_surfaces(const Document& doc, const Scene& scene, const std::string& source,
                             const std::string& prefix, ExportFormat format) {
  const std::vector<std::size_t> objects = exported_objects(doc);
  check_meshes(doc, scene, objects, source);
  ExportReport report;
  std::vector<std::string> staged;
  try {
    for (std::size_t i : objects) {
      const Object& o = doc.objects[i];
      const Mesh& mesh = scene.objects[i].mesh;
      const bool stl = format == ExportFormat::Stl;
      const std::string path = prefix + "_" + o.name + (stl ? ".stl" : ".obj");
      staged.push_back(staged_path(path));
      if (stl) {
        save_stl_file(staged.back(), mesh, o.name + " from " + source);
        const MeshTopology topology = mesh_topology(mesh);
        if (!topology.closed_manifold()) report.warnings.push_back(manifold_warning(o.name, topology, path));
      } else {
        save_obj_file(staged.back(), mesh, "sweep: " + o.name + " from " + source);
      }
      report.files.push_back({path, mesh.vertex_count(), mesh.triangle_count()});
      const SweepDiagnostics& diagnostics = scene.objects[i].diagnostics;
      if (!diagnostics.folds.empty()) report.warnings.push_back(fold_warning(o.name, diagnostics));
    }
    install(staged, report.files);
  } catch (const std::filesystem::filesystem_error& e) {
    remove_quietly(staged);
    throw std::runtime_error(std::string("cannot write ") + e.path2().string() + ": " + e.code().message());
  } catch (...) {
    remove_quietly(staged);
    throw;
  }
  return report;
}

std::string no_surfaces_message(const std::string& source) {
  return source + " has no named surfaces; nothing written";
}

}  // namespace sweep::editor
