// 3MF for printing (issue 58, item 1): the placement (millimetres, z up, on the plate, centred,
// scaled to a height) and the file read back with lib3mf's own reader: the unit, one object with
// one build item, a colour named after each printable surface whose triangles carry it, every
// vertex on or above the plate. The chess queen's orb cage stays out.
#include "io/mesh/threemf_writer.hpp"
#include "io/surface_export.hpp"
#include "model/evaluation/scene.hpp"
#include "support/core_test_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <Model/COM/NMR_DLLInterfaces.h>

#include <algorithm>
#include <array>
#include <limits>
#include <string>
#include <vector>

namespace sweep::test {
namespace {

/// One object of a 3MF file as lib3mf reads it.
struct ReadObject {
  std::string name;
  std::vector<NMR::MODELMESHVERTEX> vertices;
  DWORD triangles = 0;
  std::vector<DWORD> triangle_materials;  // each triangle's index in the colour group
};

/// A base material as lib3mf reads it: its name and colour.
struct ReadMaterial {
  std::string name;
  std::array<BYTE, 3> color{};
};

struct ReadModel {
  DWORD unit = 0;
  std::vector<ReadObject> objects;
  std::vector<ReadMaterial> materials;  // of the first colour group
  int build_items = 0;
};

std::vector<ReadMaterial> materials_of(NMR::PLib3MFModel* model) {
  std::vector<ReadMaterial> out;
  NMR::PLib3MFModelResourceIterator* groups = nullptr;
  NMR::lib3mf_model_getbasematerials(model, &groups);
  BOOL more = false;
  if (NMR::lib3mf_resourceiterator_movenext(groups, &more) == LIB3MF_OK && more) {
    NMR::PLib3MFModelResource* group = nullptr;
    NMR::lib3mf_resourceiterator_getcurrent(groups, &group);
    DWORD count = 0;
    NMR::lib3mf_basematerial_getcount(group, &count);
    for (DWORD k = 0; k < count; ++k) {
      ReadMaterial material;
      char name[256] = {};
      ULONG needed = 0;
      NMR::lib3mf_basematerial_getnameutf8(group, k, name, sizeof name, &needed);
      material.name = name;
      BYTE alpha = 0;
      NMR::lib3mf_basematerial_getdisplaycolor(group, k, &material.color[0], &material.color[1], &material.color[2],
                                               &alpha);
      out.push_back(material);
    }
    NMR::lib3mf_release(group);
  }
  NMR::lib3mf_release(groups);
  return out;
}

std::vector<DWORD> triangle_materials(NMR::PLib3MFModelMeshObject* mesh, DWORD triangles) {
  std::vector<DWORD> out(triangles);
  NMR::PLib3MFPropertyHandler* handler = nullptr;
  NMR::lib3mf_meshobject_createpropertyhandler(mesh, &handler);
  for (DWORD t = 0; t < triangles; ++t) {
    DWORD group = 0;
    NMR::lib3mf_propertyhandler_getbasematerial(handler, t, &group, &out[t]);
  }
  NMR::lib3mf_release(handler);
  return out;
}

ReadModel read_3mf(const std::filesystem::path& file) {
  ReadModel out;
  NMR::PLib3MFModel* model = nullptr;
  EXPECT_EQ(NMR::lib3mf_createmodel(&model), LIB3MF_OK);
  NMR::PLib3MFModelReader* reader = nullptr;
  EXPECT_EQ(NMR::lib3mf_model_queryreader(model, "3mf", &reader), LIB3MF_OK);
  EXPECT_EQ(NMR::lib3mf_reader_readfromfileutf8(reader, file.c_str()), LIB3MF_OK) << file;
  NMR::lib3mf_release(reader);
  NMR::lib3mf_model_getunit(model, &out.unit);
  NMR::PLib3MFModelResourceIterator* meshes = nullptr;
  NMR::lib3mf_model_getmeshobjects(model, &meshes);
  BOOL more = false;
  while (NMR::lib3mf_resourceiterator_movenext(meshes, &more) == LIB3MF_OK && more) {
    NMR::PLib3MFModelResource* mesh = nullptr;
    NMR::lib3mf_resourceiterator_getcurrent(meshes, &mesh);
    ReadObject object;
    char name[256] = {};
    ULONG needed = 0;
    NMR::lib3mf_object_getnameutf8(mesh, name, sizeof name, &needed);
    object.name = name;
    DWORD vertices = 0;
    NMR::lib3mf_meshobject_getvertexcount(mesh, &vertices);
    object.vertices.resize(vertices);
    NMR::lib3mf_meshobject_getvertices(mesh, object.vertices.data(), vertices, nullptr);
    NMR::lib3mf_meshobject_gettrianglecount(mesh, &object.triangles);
    object.triangle_materials = triangle_materials(mesh, object.triangles);
    out.objects.push_back(std::move(object));
    NMR::lib3mf_release(mesh);
  }
  NMR::lib3mf_release(meshes);
  out.materials = materials_of(model);
  NMR::PLib3MFModelBuildItemIterator* items = nullptr;
  NMR::lib3mf_model_getbuilditems(model, &items);
  while (NMR::lib3mf_builditemiterator_movenext(items, &more) == LIB3MF_OK && more) ++out.build_items;
  NMR::lib3mf_release(items);
  NMR::lib3mf_release(model);
  return out;
}

/// The box of every vertex of the model.
std::array<float, 6> box_of(const ReadModel& model) {
  std::array<float, 6> box{std::numeric_limits<float>::max(),    std::numeric_limits<float>::max(),
                           std::numeric_limits<float>::max(),    std::numeric_limits<float>::lowest(),
                           std::numeric_limits<float>::lowest(), std::numeric_limits<float>::lowest()};
  for (const ReadObject& o : model.objects) {
    for (const auto& v : o.vertices) {
      for (int c = 0; c < 3; ++c) {
        box[std::size_t(c)] = std::min(box[std::size_t(c)], v.m_fPosition[c]);
        box[std::size_t(c) + 3] = std::max(box[std::size_t(c) + 3], v.m_fPosition[c]);
      }
    }
  }
  return box;
}

TEST(ThreeMf, TheChessQueenIsOneFileOfItsPrintableSurfacesInMillimetresOnThePlate) {
  const ScratchFolder folder("sweep-3mf");
  const std::filesystem::path source = std::filesystem::path(SWEEP_SWP_DIR) / "artifacts" / "chess-queen.swp";
  const Document doc = io::load_swp_file(source);
  const Scene scene = evaluate_document(doc, io::export_evaluation({}, io::ExportFormat::ThreeMf));
  const std::string prefix = (folder.path() / "queen").string();
  const io::ExportReport report =
      io::export_surfaces(doc, scene, source.string(), prefix, io::ExportFormat::ThreeMf, {}, io::PrintOptions{80.0});
  ASSERT_EQ(report.files.size(), 1u);
  EXPECT_EQ(report.files[0].path, prefix + ".3mf");
  ASSERT_EQ(report.notes.size(), 1u);
  EXPECT_EQ(report.notes[0].rfind("model size ", 0), 0u) << report.notes[0];
  EXPECT_NE(report.notes[0].find(" x 80.0 mm (scaled to the height asked: "), std::string::npos) << report.notes[0];

  const ReadModel model = read_3mf(prefix + ".3mf");
  EXPECT_EQ(model.unit, static_cast<DWORD>(NMR::MODELUNIT_MILLIMETER));
  // Every named surface but the orb's cage, each a colour named after it, its triangles in turn.
  std::vector<std::string> expected;
  std::vector<std::size_t> counts;
  int cages = 0;
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const Object& o = doc.objects[i];
    if (o.kind() == ObjectKind::PolygonMesh) ++cages;
    if (!is_surface(o.kind()) || o.name.empty() || o.kind() == ObjectKind::PolygonMesh) continue;
    expected.push_back(o.name);
    counts.push_back(scene.objects[i].mesh.triangle_count());
  }
  EXPECT_EQ(cages, 1);                  // the queen's only mesh is the subd's cage
  ASSERT_EQ(model.objects.size(), 1u);  // one object: the crown stays on the queen
  EXPECT_EQ(model.objects[0].name, "queen");
  EXPECT_EQ(model.build_items, 1);
  std::vector<std::string> names;
  for (const ReadMaterial& m : model.materials) names.push_back(m.name);
  EXPECT_EQ(names, expected);
  std::vector<DWORD> want;
  for (std::size_t k = 0; k < counts.size(); ++k) want.insert(want.end(), counts[k], static_cast<DWORD>(k));
  EXPECT_EQ(model.objects[0].triangle_materials, want);
  EXPECT_EQ(report.files[0].triangles, want.size());
  const auto distinct = std::count_if(model.materials.begin(), model.materials.end(),
                                      [&](const ReadMaterial& m) { return m.color != model.materials[0].color; });
  EXPECT_GT(distinct, 0);  // wood, gold, ebony: the materials' colours
  const std::array<float, 6> box = box_of(model);
  EXPECT_NEAR(box[2], 0.0f, 1e-4f);   // standing on the plate
  EXPECT_NEAR(box[5], 80.0f, 1e-3f);  // 80 mm tall
  EXPECT_NEAR(box[0] + box[3], 0.0f, 1e-3f);
  EXPECT_NEAR(box[1] + box[4], 0.0f, 1e-3f);
}

}  // namespace
}  // namespace sweep::test
