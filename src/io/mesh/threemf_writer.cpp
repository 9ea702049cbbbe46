#include "io/mesh/threemf_writer.hpp"

#include "base/precondition.hpp"

#include <Model/COM/NMR_DLLInterfaces.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <vector>

// lib3mf 1.8 (Debian's lib3mf-dev) through its C interface: every handle is released by a
// unique_ptr, every call's result checked, and a failure names the file and the step.

namespace sweep::io {
namespace {

struct Release {
  void operator()(NMR::PLib3MFBase* handle) const { NMR::lib3mf_release(handle); }
};
using Handle = std::unique_ptr<NMR::PLib3MFBase, Release>;

void check(LIB3MFRESULT result, const std::filesystem::path& path, const char* step) {
  if (result != LIB3MF_OK) throw std::runtime_error("cannot write " + path.string() + ": lib3mf could not " + step);
}

std::uint8_t channel(float value) {
  return static_cast<std::uint8_t>(std::lround(std::clamp(value, 0.0f, 1.0f) * 255.0f));
}

/// Every surface in one mesh: placed vertices, triangles with indices moved past the earlier
/// surfaces', and `first[k]` the first triangle of surface k (first.back(): the count).
struct Merged {
  std::vector<NMR::MODELMESHVERTEX> vertices;
  std::vector<NMR::MODELMESHTRIANGLE> triangles;
  std::vector<std::size_t> first;
};

Merged merged(std::span<const PrintPart> parts) {
  Merged out;
  for (const PrintPart& part : parts) {
    const auto base = static_cast<DWORD>(out.vertices.size());
    out.first.push_back(out.triangles.size());
    for (const glm::dvec3& p : part.shell.positions) {
      out.vertices.push_back({{static_cast<float>(p.x), static_cast<float>(p.y), static_cast<float>(p.z)}});
    }
    const std::vector<std::uint32_t>& indices = part.shell.indices;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
      out.triangles.push_back({{base + indices[t], base + indices[t + 1], base + indices[t + 2]}});
    }
  }
  out.first.push_back(out.triangles.size());
  return out;
}

/// Each surface's colour, named after it, in a group added before the mesh (a reader finds
/// every resource before what refers to it); the materials' indices, one per surface.
std::vector<DWORD> add_colours(NMR::PLib3MFModel* model, std::span<const PrintPart> objects, DWORD& group_id,
                               Handle& group, const std::filesystem::path& path) {
  NMR::PLib3MFModelBaseMaterial* raw = nullptr;
  check(NMR::lib3mf_model_addbasematerialgroup(model, &raw), path, "add the colours");
  group.reset(raw);
  check(NMR::lib3mf_basematerial_getresourceid(raw, &group_id), path, "name the colours");
  std::vector<DWORD> materials;
  for (const PrintPart& object : objects) {
    DWORD material = 0;
    check(NMR::lib3mf_basematerial_addmaterialutf8(raw, object.name.c_str(), channel(object.color.r),
                                                   channel(object.color.g), channel(object.color.b), &material),
          path, "add a colour");
    materials.push_back(material);
  }
  return materials;
}

/// Surface k's triangles carry materials[k].
void colour_triangles(NMR::PLib3MFModelMeshObject* mesh, const Merged& geometry, DWORD group_id,
                      const std::vector<DWORD>& materials, const std::filesystem::path& path) {
  // The object's default (3MF asks for one where triangles have properties): the first colour.
  NMR::PLib3MFDefaultPropertyHandler* fallback = nullptr;
  check(NMR::lib3mf_object_createdefaultpropertyhandler(mesh, &fallback), path, "colour the model");
  const Handle keep_fallback(fallback);
  check(NMR::lib3mf_defaultpropertyhandler_setbasematerial(fallback, group_id, materials.front()), path,
        "colour the model");
  NMR::PLib3MFPropertyHandler* handler = nullptr;
  check(NMR::lib3mf_meshobject_createpropertyhandler(mesh, &handler), path, "colour the triangles");
  const Handle properties(handler);
  for (std::size_t k = 0; k < materials.size(); ++k) {
    for (std::size_t t = geometry.first[k]; t < geometry.first[k + 1]; ++t) {
      check(NMR::lib3mf_propertyhandler_setbasematerial(handler, static_cast<DWORD>(t), group_id, materials[k]), path,
            "colour a triangle");
    }
  }
}

}  // namespace

void save_3mf_file(const std::filesystem::path& path, const PrintModel& model, const std::string& name) {
  SWEEP_EXPECTS(!model.parts.empty(), "the model has a part");
  NMR::PLib3MFModel* raw = nullptr;
  check(NMR::lib3mf_createmodel(&raw), path, "make a model");
  const Handle keep_model(raw);
  check(NMR::lib3mf_model_setunit(raw, NMR::MODELUNIT_MILLIMETER), path, "set the unit");
  // One object: a slicer keeps it whole on the plate (a crown on the queen does not become an
  // object of its own floating above it); each surface keeps its name in its colour's.
  Merged geometry = merged(model.parts);
  DWORD group_id = 0;
  Handle group;
  const std::vector<DWORD> materials = add_colours(raw, model.parts, group_id, group, path);
  NMR::PLib3MFModelMeshObject* mesh = nullptr;
  check(NMR::lib3mf_model_addmeshobject(raw, &mesh), path, "add the mesh");
  const Handle keep_mesh(mesh);
  check(NMR::lib3mf_object_setnameutf8(mesh, name.c_str()), path, "name the model");
  check(NMR::lib3mf_meshobject_setgeometry(mesh, geometry.vertices.data(), static_cast<DWORD>(geometry.vertices.size()),
                                           geometry.triangles.data(), static_cast<DWORD>(geometry.triangles.size())),
        path, "set the triangles");
  colour_triangles(mesh, geometry, group_id, materials, path);
  NMR::PLib3MFModelBuildItem* item = nullptr;
  check(NMR::lib3mf_model_addbuilditem(raw, mesh, nullptr, &item), path, "add the build item");
  NMR::lib3mf_release(item);
  NMR::PLib3MFModelWriter* writer = nullptr;
  check(NMR::lib3mf_model_querywriter(raw, "3mf", &writer), path, "make a writer");
  const Handle keep(writer);
  if (NMR::lib3mf_writer_writetofileutf8(writer, path.c_str()) != LIB3MF_OK) {
    DWORD code = 0;
    LPCSTR message = nullptr;
    NMR::lib3mf_getlasterror(writer, &code, &message);
    throw std::runtime_error("cannot write " + path.string() + ": lib3mf could not write the file (" +
                             (message != nullptr ? message : "no reason given") + ")");
  }
}

}  // namespace sweep::io
