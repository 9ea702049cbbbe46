#include "io/surface_export.hpp"

#include "base/precondition.hpp"
#include "io/files/atomic_file.hpp"
#include "io/files/file_set.hpp"
#include "io/mesh/gltf_writer.hpp"
#include "io/mesh/mtl_writer.hpp"
#include "io/mesh/obj_writer.hpp"
#include "io/mesh/print_export.hpp"
#include "model/diagnostics_text.hpp"
#include "model/evaluation/rider_keys.hpp"
#include "model/evaluation/riders.hpp"
#include "model/material.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <set>
#include <stdexcept>
#include <system_error>

namespace sweep::io {
namespace {

/// Named surfaces, in document order.
std::vector<std::size_t> exported_objects(const Document& doc) {
  std::vector<std::size_t> out;
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    if (is_surface(doc.objects[i].kind()) && !doc.objects[i].name.empty()) out.push_back(i);
  }
  return out;
}

std::string location_text(const std::string& source, const Object& o) {
  return source + ":" + std::to_string(o.location.line) + ":" + std::to_string(o.location.column);
}

void check_meshes(const Document& doc, const Scene& scene, const std::vector<std::size_t>& objects,
                  const std::string& source) {
  for (std::size_t i : objects) {
    const Object& o = doc.objects[i];
    if (mesh_is_finite(scene.objects[i].mesh)) continue;
    throw ExportError(location_text(source, o) + ": surface '" + o.name +
                      "' has a NaN or infinite coordinate; nothing written");
  }
}

/// A surface's material and the bytes of its images, read before anything is written.
struct SurfaceLook {
  SurfaceMaterial material;
  MaterialImages images;
};

/// The look of surface `i` for `format`: OBJ needs it only with a `material` clause, glb always
/// (the default look without one) but never its bump, STL never. ExportError at the material
/// when an image cannot be read.
SurfaceLook surface_look(const Document& doc, std::size_t i, const std::string& source, ExportFormat format) {
  SurfaceLook look;
  const Object& surface = doc.objects[i];
  if (format == ExportFormat::ThreeMf || format == ExportFormat::Stl ||
      (format == ExportFormat::Obj && surface.as<MaterialPart>().material < 0))
    return look;
  look.material = surface_material(doc, static_cast<int>(i), image_base(source));
  if (format == ExportFormat::Glb) look.material.bump.clear();
  try {
    look.images = read_material_images(look.material);
  } catch (const std::runtime_error& e) {
    const Object& m = doc.objects[static_cast<std::size_t>(surface.as<MaterialPart>().material)];
    std::string message = location_text(source, m);
    message += ": material '";
    message += m.name;
    message += "': ";
    message += e.what();
    message += "; nothing written";
    throw ExportError(message);
  }
  return look;
}

/// A copied image's file name: blanks (which MTL readers split at) become '_'.
std::string image_file_name(const std::filesystem::path& source) {
  std::string name = source.filename().string();
  std::replace_if(
      name.begin(), name.end(), [](char c) { return std::isspace(static_cast<unsigned char>(c)); }, '_');
  return name;
}

std::string file_name(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

/// The OBJ's material library and images, planned into `outputs` and `file.companions`;
/// returns what the OBJ links to.
ObjMaterialLink plan_material(const std::string& stem, const SurfaceLook& look, const std::string& comment,
                              std::vector<ExportOutput>& outputs, ExportedFile& file) {
  const SurfaceMaterial& material = look.material;
  MtlImageFiles images;
  std::string texture_path;
  if (!look.images.texture.empty()) {
    const bool checker = material.texture.empty();
    texture_path = stem + "_" + (checker ? checker_file_name(material.checker) : image_file_name(material.texture));
    images.texture = file_name(texture_path);
    const std::string cells = std::to_string(material.checker);
    file.companions.push_back({texture_path, checker ? cells + " x " + cells + " checker" : std::string("texture")});
  }
  std::string bump_path;
  if (!look.images.bump.empty()) {
    const bool same_file = !material.texture.empty() && material.texture == material.bump;
    bump_path = stem + "_" + image_file_name(material.bump);
    if (!same_file && bump_path == texture_path) bump_path = stem + "_bump_" + image_file_name(material.bump);
    images.bump = file_name(bump_path);
    if (!same_file) file.companions.push_back({bump_path, "bump map"});
  }
  const std::string mtl_path = stem + ".mtl";
  std::string what = "material ";
  what += mtl_material_name(material);
  file.companions.insert(file.companions.begin(), {mtl_path, what});
  outputs.push_back({mtl_path, [material, images, comment](const std::string& staged) {
                       save_mtl_file(staged, material, images, comment);
                     }});
  const MaterialImages* bytes = &look.images;
  if (!texture_path.empty()) {
    outputs.push_back(
        {texture_path, [bytes](const std::string& staged) { write_file_atomically(staged, bytes->texture); }});
  }
  if (!bump_path.empty() && bump_path != texture_path) {
    outputs.push_back({bump_path, [bytes](const std::string& staged) { write_file_atomically(staged, bytes->bump); }});
  }
  return {file_name(mtl_path), mtl_material_name(material)};
}

/// The riders' scene .glb: every named surface no rider carries, still, and every rider moving
/// with its model. Holds what the planned output reads, so it must outlive the writing.
struct RiderScene {
  std::vector<RiderKeys> keys;  // one per rider, in document order
  GlbScene glb;
};

/// The scene's surfaces: every named surface (objects[k], looks[k]), each once, shown still or
/// carried by riders; returns, per object of `doc`, its index among them (-1: not in the scene).
std::vector<int> scene_surfaces(const Document& doc, const Scene& scene, const std::vector<std::size_t>& objects,
                                const std::vector<SurfaceLook>& looks, GlbScene& glb) {
  std::vector<int> surface(doc.objects.size(), -1);
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const std::size_t i = objects[k];
    surface[i] = static_cast<int>(glb.surfaces.size());
    glb.surfaces.push_back({doc.objects[i].name, &scene.objects[i].mesh, &looks[k].material, &looks[k].images});
  }
  return surface;
}

/// Plans PREFIX.glb for the riders of `doc` into `outputs` and reports it (its vertices and
/// triangles: those of the meshes it holds, each once). Preconditions: `doc` has riders; objects
/// and looks as export_surfaces made them for Glb.
void plan_rider_scene(const Document& doc, const Scene& scene, const std::vector<std::size_t>& objects,
                      const std::vector<SurfaceLook>& looks, const std::string& prefix, const GlbOptions& options,
                      RiderScene& plan, std::vector<ExportOutput>& outputs, ExportReport& report) {
  const std::vector<int> riders = riders_of(doc);
  SWEEP_EXPECTS(!riders.empty(), "the document has riders");
  const std::vector<int> surface = scene_surfaces(doc, scene, objects, looks, plan.glb);
  const std::vector<bool> carried = carried_models(doc);
  for (const std::size_t i : objects) {
    if (!carried[i]) plan.glb.nodes.push_back({doc.objects[i].name, surface[i], nullptr});
  }
  plan.keys.reserve(riders.size());  // the nodes point into it
  for (const int r : riders) {
    const int model = doc.objects[static_cast<std::size_t>(r)].as<RiderObject>().model;
    plan.keys.push_back(rider_keys(doc, scene, r));
    plan.glb.nodes.push_back(
        {display_name(doc, r), model < 0 ? -1 : surface[static_cast<std::size_t>(model)], &plan.keys.back()});
  }
  ExportedFile file{prefix + ".glb", 0, 0, {}, options.encoding == GlbEncoding::Quantized};
  for (const GlbSurface& s : plan.glb.surfaces) {
    file.vertices += s.mesh->vertex_count();
    file.triangles += s.mesh->triangle_count();
  }
  const GlbScene* glb = &plan.glb;
  outputs.push_back(
      {file.path, [glb, options](const std::string& staged) { save_glb_scene_file(staged, *glb, options); }});
  report.files.push_back(std::move(file));
}

/// Each format's command-line name, label and file extension: the one place that names them.
struct FormatNames {
  ExportFormat format;
  std::string_view name;  // as --format says it
  const char* label;      // as messages and buttons say it
  const char* extension;
};
constexpr FormatNames kFormatNames[] = {{ExportFormat::Obj, "obj", "OBJ", ".obj"},
                                        {ExportFormat::Stl, "stl", "STL", ".stl"},
                                        {ExportFormat::Glb, "glb", "glb", ".glb"},
                                        {ExportFormat::ThreeMf, "3mf", "3MF", ".3mf"}};

const FormatNames& names_of(ExportFormat format) {
  for (const FormatNames& names : kFormatNames) {
    if (names.format == format) return names;
  }
  return kFormatNames[0];
}

const char* extension(ExportFormat format) {
  return names_of(format).extension;
}

}  // namespace

EvaluationOptions export_evaluation(EvaluationOptions options, ExportFormat format) {
  if (format == ExportFormat::Obj || format == ExportFormat::Glb) {
    options.texture_coordinates = TextureCoordinates::Everywhere;
  }
  return options;
}

ExportReport export_surfaces(const Document& doc, const Scene& scene, const std::string& source,
                             const std::string& prefix, ExportFormat format, GlbEncoding encoding,
                             const PrintOptions& print) {
  SWEEP_EXPECTS(scene.objects.size() == doc.objects.size(), "scene is evaluated from doc");
  const std::vector<std::size_t> objects = exported_objects(doc);
  const bool needs_uvs = format == ExportFormat::Obj || format == ExportFormat::Glb;
  SWEEP_EXPECTS(!needs_uvs || std::all_of(objects.begin(), objects.end(),
                                          [&scene](std::size_t i) {
                                            const Mesh& m = scene.objects[i].mesh;
                                            return m.uvs.size() == m.positions.size();
                                          }),
                "scene is evaluated with export_evaluation(options, format)");
  check_meshes(doc, scene, objects, source);
  std::vector<SurfaceLook> looks;  // read whole before anything is written
  looks.reserve(objects.size());
  for (std::size_t i : objects) looks.push_back(surface_look(doc, i, source, format));

  ExportReport report;
  std::vector<ExportOutput> outputs;
  PrintPlan print_plan;
  const bool for_print = format == ExportFormat::ThreeMf || format == ExportFormat::Stl;
  if (for_print) plan_print_export(doc, scene, source, prefix, format, print, print_plan, outputs, report);
  for (std::size_t k = 0; k < objects.size() && !for_print; ++k) {
    const std::size_t i = objects[k];
    const Object& o = doc.objects[i];
    const Mesh& mesh = scene.objects[i].mesh;
    const std::string stem = prefix + "_" + o.name;
    ExportedFile file{stem + extension(format),
                      mesh.vertex_count(),
                      mesh.triangle_count(),
                      {},
                      format == ExportFormat::Glb && encoding == GlbEncoding::Quantized};
    const std::string comment = "sweep: " + o.name + " from " + source;
    if (format == ExportFormat::Glb) {
      const SurfaceLook* look = &looks[k];
      outputs.push_back(
          {file.path, [&mesh, look, name = o.name, options = GlbOptions{comment, encoding}](const std::string& staged) {
             save_glb_file(staged, mesh, name, look->material, look->images, options);
           }});
    } else {
      outputs.emplace_back();  // the OBJ comes first, then its MTL and images
      const std::size_t obj = outputs.size() - 1;
      ObjMaterialLink link;
      if (o.as<MaterialPart>().material >= 0) link = plan_material(stem, looks[k], comment, outputs, file);
      outputs[obj] = {
          file.path, [&mesh, comment, link](const std::string& staged) { save_obj_file(staged, mesh, comment, link); }};
    }
    report.files.push_back(std::move(file));
  }
  for (const std::size_t i : objects) {
    const SweepDiagnostics& diagnostics = scene.objects[i].diagnostics;
    if (!diagnostics.folds.empty()) report.warnings.push_back(editor::fold_warning(doc.objects[i].name, diagnostics));
  }
  RiderScene rider_scene;
  if (format == ExportFormat::Glb && !riders_of(doc).empty()) {
    const GlbOptions options{"sweep: riders from " + source, encoding};
    plan_rider_scene(doc, scene, objects, looks, prefix, options, rider_scene, outputs, report);
  }
  write_file_set(outputs);
  return report;
}

std::string no_surfaces_message(const std::string& source) {
  return source + " has no named surfaces; nothing written";
}

std::vector<std::string> written_files(const ExportReport& report) {
  std::vector<std::string> paths;
  for (const ExportedFile& file : report.files) {
    paths.push_back(file.path);
    for (const CompanionFile& companion : file.companions) paths.push_back(companion.path);
  }
  return paths;
}

std::vector<std::string> written_lines(const ExportReport& report) {
  std::vector<std::string> lines;
  for (const ExportedFile& file : report.files) {
    lines.push_back("wrote " + file.path + " (" + std::to_string(file.vertices) + " vertices, " +
                    std::to_string(file.triangles) + " triangles" + (file.quantized ? ", quantized)" : ")"));
    for (const CompanionFile& companion : file.companions) {
      lines.push_back("wrote " + companion.path + " (" + companion.what + ")");
    }
  }
  lines.insert(lines.end(), report.notes.begin(), report.notes.end());
  return lines;
}

std::optional<ExportFormat> export_format_named(std::string_view name) {
  for (const FormatNames& names : kFormatNames) {
    if (names.name == name) return names.format;
  }
  return std::nullopt;
}

const char* export_format_label(ExportFormat format) {
  return names_of(format).label;
}

}  // namespace sweep::io
