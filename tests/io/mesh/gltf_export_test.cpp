// Binary glTF output read back by tinygltf (no error, no warning): exact vertex, normal, texture
// coordinate and index data, position bounds, the material's factors, the embedded texture or
// checker decoded, the default look without a material; every starter surface; a NaN refused with
// nothing written.
#include "io/mesh/gltf_writer.hpp"
#include "io/mesh/obj_writer.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"

#include "support/core_test_support.hpp"
#include "support/file_support.hpp"
#include "support/gltf_test_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>
#include <tiny_gltf.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <set>
#include <string>
#include <vector>

namespace sweep {
namespace {

namespace fs = std::filesystem;
using test::accessor_data;
using test::read_file;
using test::ScratchFolder;
using test::write_bytes;

struct Loaded {
  tinygltf::Model model;
  std::string error;
  std::string warning;
  bool ok = false;
};

Loaded load_glb(const fs::path& path) {
  Loaded out;
  tinygltf::TinyGLTF reader;
  out.ok = reader.LoadBinaryFromFile(&out.model, &out.error, &out.warning, path.string());
  return out;
}

Mesh grid_mesh() {
  // 3 x 2 vertices, 4 triangles, texture coordinates over [0, 1] x [0, 2].
  Mesh mesh;
  for (int j = 0; j < 2; ++j) {
    for (int i = 0; i < 3; ++i) {
      mesh.positions.push_back({0.5f * static_cast<float>(i) - 0.25f, 3.0f * static_cast<float>(j), 1.0f / 3.0f});
      mesh.normals.push_back({0, 0, 1});
      mesh.uvs.push_back({0.5f * static_cast<float>(i), 2.0f * static_cast<float>(j)});
    }
  }
  add_quad(mesh.indices, 0, 1, 3, 4, true);
  add_quad(mesh.indices, 1, 2, 4, 5, true);
  return mesh;
}

TEST(Glb, ReadsBackWithTheMeshAndItsCheckerMaterial) {
  const ScratchFolder folder("sweep-glb");
  const Mesh mesh = grid_mesh();
  SurfaceMaterial material;
  material.name = "tiles";
  material.color = {0.25f, 0.5f, 1.0f};
  material.shininess = 198;
  material.checker = 3;
  const io::MaterialImages images = io::read_material_images(material);
  const fs::path path = folder.path() / "out_grid.glb";
  io::save_glb_file(path, mesh, "grid", material, images, io::GlbOptions{"sweep: grid from test"});
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"out_grid.glb"});
  EXPECT_EQ(read_file(path).substr(0, 4), "glTF");

  const Loaded loaded = load_glb(path);
  ASSERT_TRUE(loaded.ok) << loaded.error;
  EXPECT_EQ(loaded.error, "");
  EXPECT_EQ(loaded.warning, "");
  const tinygltf::Model& model = loaded.model;
  EXPECT_EQ(model.asset.version, "2.0");
  EXPECT_EQ(model.asset.generator, "sweep: grid from test");
  ASSERT_EQ(model.scenes.size(), 1u);
  ASSERT_EQ(model.nodes.size(), 1u);
  EXPECT_EQ(model.nodes[0].name, "grid");
  ASSERT_EQ(model.nodes[0].mesh, 0);
  ASSERT_EQ(model.meshes.size(), 1u);
  ASSERT_EQ(model.meshes[0].primitives.size(), 1u);
  const tinygltf::Primitive& primitive = model.meshes[0].primitives[0];
  EXPECT_EQ(primitive.mode, TINYGLTF_MODE_TRIANGLES);

  const int position = primitive.attributes.at("POSITION");
  const tinygltf::Accessor& positions = model.accessors.at(static_cast<std::size_t>(position));
  EXPECT_EQ(positions.componentType, TINYGLTF_COMPONENT_TYPE_FLOAT);
  EXPECT_EQ(positions.type, TINYGLTF_TYPE_VEC3);
  EXPECT_EQ(positions.count, mesh.vertex_count());
  const double third = 1.0f / 3.0f;
  EXPECT_EQ(positions.minValues, (std::vector<double>{-0.25, 0.0, third}));
  EXPECT_EQ(positions.maxValues, (std::vector<double>{0.75, 3.0, third}));
  EXPECT_EQ(accessor_data<glm::vec3>(model, primitive.attributes.at("NORMAL")).size(), mesh.vertex_count());
  EXPECT_EQ(accessor_data<glm::vec2>(model, primitive.attributes.at("TEXCOORD_0")).size(), mesh.vertex_count());
  const tinygltf::Accessor& indices = model.accessors.at(static_cast<std::size_t>(primitive.indices));
  EXPECT_EQ(indices.componentType, TINYGLTF_COMPONENT_TYPE_UNSIGNED_INT);
  EXPECT_EQ(indices.type, TINYGLTF_TYPE_SCALAR);
  // The same triangles, exactly, each with its winding (v flipped: glTF's v = 0 is the image's top
  // row), in GPU order (mesh/gltf_vertices.hpp).
  EXPECT_EQ(test::read_triangles(model, primitive), test::mesh_triangles(mesh));
  EXPECT_TRUE(test::in_fetch_order(accessor_data<std::uint32_t>(model, primitive.indices)));

  ASSERT_EQ(model.materials.size(), 1u);
  ASSERT_EQ(primitive.material, 0);
  const tinygltf::Material& m = model.materials[0];
  EXPECT_EQ(m.name, "tiles");
  EXPECT_EQ(m.pbrMetallicRoughness.baseColorFactor, (std::vector<double>{0.25, 0.5, 1.0, 1.0}));
  EXPECT_EQ(m.pbrMetallicRoughness.metallicFactor, 0.0);
  EXPECT_FLOAT_EQ(static_cast<float>(m.pbrMetallicRoughness.roughnessFactor), 0.1f);  // sqrt(2 / 200)
  EXPECT_TRUE(m.doubleSided);
  EXPECT_EQ(m.normalTexture.index, -1) << "the bump is not exported";
  ASSERT_EQ(m.pbrMetallicRoughness.baseColorTexture.index, 0);
  ASSERT_EQ(model.textures.size(), 1u);
  ASSERT_EQ(model.images.size(), 1u);
  const tinygltf::Image& image = model.images.at(static_cast<std::size_t>(model.textures[0].source));
  EXPECT_EQ(image.mimeType, "image/png");
  EXPECT_EQ(image.name, "checker3");
  EXPECT_EQ(image.width, 3 * kCheckerPixelsPerCell);
  EXPECT_EQ(image.height, 3 * kCheckerPixelsPerCell);
  ASSERT_GE(image.component, 1);
  ASSERT_EQ(image.image.size(), static_cast<std::size_t>(image.width * image.height * image.component));
  // The top-left pixel is the top-left cell, v = 1 - 1/3 to 1: cell row 2, column 0, light.
  EXPECT_EQ(image.image[0], io::kCheckerLightGrey);
  // The one to its right (column 1, row 2) is dark.
  EXPECT_EQ(image.image[static_cast<std::size_t>(kCheckerPixelsPerCell * image.component)], io::kCheckerDarkGrey);
  const tinygltf::Sampler& sampler = model.samplers.at(static_cast<std::size_t>(model.textures[0].sampler));
  EXPECT_EQ(sampler.wrapS, TINYGLTF_TEXTURE_WRAP_REPEAT);
  EXPECT_EQ(sampler.wrapT, TINYGLTF_TEXTURE_WRAP_REPEAT);
}

TEST(Glb, WithoutMaterialOrTextureCoordinatesTheDefaultLook) {
  const ScratchFolder folder("sweep-glb");
  Mesh mesh = grid_mesh();
  mesh.uvs.clear();
  const fs::path path = folder.path() / "plain.glb";
  io::save_glb_file(path, mesh, "plain", SurfaceMaterial{}, io::MaterialImages{});
  const Loaded loaded = load_glb(path);
  ASSERT_TRUE(loaded.ok) << loaded.error;
  EXPECT_EQ(loaded.warning, "");
  const tinygltf::Primitive& primitive = loaded.model.meshes.at(0).primitives.at(0);
  EXPECT_EQ(primitive.attributes.count("TEXCOORD_0"), 0u);
  EXPECT_EQ(primitive.attributes.size(), 2u);
  ASSERT_EQ(loaded.model.materials.size(), 1u);
  const tinygltf::Material& m = loaded.model.materials[0];
  EXPECT_EQ(m.name, "default");
  // The shortest decimal forms of the colour's floats: 0.62, not 0.62000000476837158.
  EXPECT_EQ(m.pbrMetallicRoughness.baseColorFactor,
            (std::vector<double>{kDefaultColor[0], kDefaultColor[1], kDefaultColor[2], 1.0}));
  EXPECT_EQ(m.pbrMetallicRoughness.roughnessFactor, 0.2);  // sqrt(2 / 50)
  EXPECT_EQ(m.pbrMetallicRoughness.baseColorTexture.index, -1);
  EXPECT_TRUE(loaded.model.images.empty());
  EXPECT_TRUE(loaded.model.textures.empty());
}

TEST(Glb, ATextureFileIsEmbeddedAsItIs) {
  const ScratchFolder folder("sweep-glb");
  io::MaterialImages images;
  images.texture = io::checker_png(2);
  SurfaceMaterial material;
  material.name = "wood";
  material.texture = folder.path() / "wood grain.png";
  const std::string bytes = io::glb_bytes(grid_mesh(), "g", material, images);
  const fs::path path = folder.path() / "g.glb";
  write_bytes(path, bytes);
  const Loaded loaded = load_glb(path);
  ASSERT_TRUE(loaded.ok) << loaded.error;
  EXPECT_EQ(loaded.warning, "");
  ASSERT_EQ(loaded.model.images.size(), 1u);
  const tinygltf::Image& image = loaded.model.images[0];
  EXPECT_EQ(image.name, "wood grain");
  const tinygltf::BufferView& view = loaded.model.bufferViews.at(static_cast<std::size_t>(image.bufferView));
  const auto& data = loaded.model.buffers.at(0).data;
  EXPECT_EQ(std::string(data.begin() + static_cast<std::ptrdiff_t>(view.byteOffset),
                        data.begin() + static_cast<std::ptrdiff_t>(view.byteOffset + view.byteLength)),
            images.texture);
}

TEST(Glb, AMeshWithoutTrianglesIsANodeWithoutAMesh) {
  const ScratchFolder folder("sweep-glb");
  const fs::path path = folder.path() / "empty.glb";
  io::save_glb_file(path, Mesh{}, "empty", SurfaceMaterial{}, io::MaterialImages{});
  const Loaded loaded = load_glb(path);
  ASSERT_TRUE(loaded.ok) << loaded.error;
  EXPECT_EQ(loaded.warning, "");
  ASSERT_EQ(loaded.model.nodes.size(), 1u);
  EXPECT_EQ(loaded.model.nodes[0].mesh, -1);
  EXPECT_TRUE(loaded.model.meshes.empty());
}

TEST(Glb, EveryStarterSurfaceReadsBackWithItsCounts) {
  const ScratchFolder folder("sweep-glb");
  int surfaces = 0;
  for (const auto& file : test::starter_files()) {
    const Document doc = io::load_swp_file(file);
    const Scene scene = evaluate_document(doc);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      if (!is_surface(doc.objects[i].kind())) continue;
      ++surfaces;
      const std::string what = file.filename().string() + " " + display_name(doc, static_cast<int>(i));
      const Mesh& mesh = scene.objects[i].mesh;
      const SurfaceMaterial material = surface_material(doc, static_cast<int>(i), image_base(file));
      const fs::path path = folder.path() / (file.stem().string() + "_" + std::to_string(i) + ".glb");
      io::save_glb_file(path, mesh, what, material, io::read_material_images(material));
      const Loaded loaded = load_glb(path);
      ASSERT_TRUE(loaded.ok) << what << ": " << loaded.error;
      EXPECT_EQ(loaded.warning, "") << what;
      if (mesh.triangle_count() == 0) continue;
      const tinygltf::Primitive& primitive = loaded.model.meshes.at(0).primitives.at(0);
      // The vertices the triangles use (a vertex only on triangles of no area, left out, is not written).
      const std::set<std::uint32_t> used(mesh.indices.begin(), mesh.indices.end());
      EXPECT_EQ(loaded.model.accessors.at(static_cast<std::size_t>(primitive.attributes.at("POSITION"))).count,
                used.size())
          << what;
      EXPECT_EQ(loaded.model.accessors.at(static_cast<std::size_t>(primitive.indices)).count, mesh.indices.size())
          << what;
      EXPECT_EQ(primitive.attributes.count("TEXCOORD_0"), io::has_texture_coordinates(mesh) ? 1u : 0u) << what;
    }
  }
  EXPECT_GT(surfaces, 0);
}

TEST(Glb, ANonFiniteMeshIsRefusedAndTheOldFileKept) {
  const ScratchFolder folder("sweep-glb");
  const fs::path path = folder.path() / "kept.glb";
  io::save_glb_file(path, grid_mesh(), "kept", SurfaceMaterial{}, io::MaterialImages{});
  const std::string before = read_file(path);
  Mesh broken = grid_mesh();
  broken.positions[1].z = std::numeric_limits<float>::quiet_NaN();
  try {
    io::save_glb_file(path, broken, "kept", SurfaceMaterial{}, io::MaterialImages{});
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + path.string() + ": the mesh has a NaN or infinite coordinate");
  }
  EXPECT_EQ(read_file(path), before);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"kept.glb"});
}

TEST(Glb, RoughnessFromShininess) {
  EXPECT_FLOAT_EQ(io::roughness_from_shininess(0.0f), 1.0f);
  EXPECT_FLOAT_EQ(io::roughness_from_shininess(48.0f), 0.2f);
  EXPECT_FLOAT_EQ(io::roughness_from_shininess(1000.0f), std::sqrt(2.0f / 1002.0f));
}

}  // namespace
}  // namespace sweep
