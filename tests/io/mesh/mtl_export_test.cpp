// OBJ with texture coordinates and a material: vt lines and v/vt/vn faces, mtllib/usemtl, the MTL
// text (Kd, Ks, Ns, map_Kd, map_Bump), the generated checker PNG decoded back, image reading
// errors, and the files read by tinyobjloader (its double build, the one sweep_core links) with
// the right counts, material and texture names and no warning.
#include "io/mesh/mtl_writer.hpp"
#include "io/mesh/obj_writer.hpp"
#include "model/material.hpp"

#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

// sweep_core links tinyobjloader's double-precision library (mesh/obj_import.cpp); the float one has
// the same symbols, so this test reads through the double one too.
#define TINYOBJLOADER_USE_DOUBLE
#include <stb/stb_image.h>
#include <tiny_obj_loader.h>

#include <filesystem>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace sweep {
namespace {

namespace fs = std::filesystem;
using test::read_file;
using test::ScratchFolder;
using test::write_bytes;
using test::write_text;

/// A 2 x 2 grid of 4 positions, two triangles, with texture coordinates.
Mesh square(bool uvs = true) {
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  mesh.normals.assign(4, glm::vec3(0, 0, 1));
  add_quad(mesh.indices, 0, 1, 2, 3, true);
  if (uvs) mesh.uvs = {{0, 0}, {0.5f, 0}, {0, 0.25f}, {0.5f, 0.25f}};
  return mesh;
}

SurfaceMaterial wood() {
  SurfaceMaterial m;
  m.name = "wood";
  m.color = {0.8f, 0.5f, 0.25f};
  m.shininess = 20;
  return m;
}

struct Decoded {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> grey;
  unsigned char at(int x, int y) const { return grey[static_cast<std::size_t>(y * width + x)]; }
};

Decoded decode_grey(const std::string& png) {
  Decoded out;
  int channels = 0;
  const std::unique_ptr<stbi_uc, void (*)(void*)> pixels(
      stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(png.data()), static_cast<int>(png.size()), &out.width,
                            &out.height, &channels, 1),
      stbi_image_free);
  if (!pixels) return out;
  out.grey.assign(pixels.get(), pixels.get() + static_cast<std::size_t>(out.width) * out.height);
  return out;
}

TEST(ObjTextureCoordinates, VtLinesAndFullCorners) {
  EXPECT_EQ(io::obj_text(square()),
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
            "vt 0 0\nvt 0.5 0\nvt 0 0.25\nvt 0.5 0.25\n"
            "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
            "f 1/1/1 2/2/2 3/3/3\nf 2/2/2 4/4/4 3/3/3\n");
  EXPECT_TRUE(io::has_texture_coordinates(square()));
  EXPECT_FALSE(io::has_texture_coordinates(square(false)));
}

TEST(ObjTextureCoordinates, WithoutThemTheTextIsAsBefore) {
  EXPECT_EQ(io::obj_text(square(false), "c"),
            "# c\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
            "f 1//1 2//2 3//3\nf 2//2 4//4 3//3\n");
}

TEST(ObjTextureCoordinates, MaterialLinesAndPolygons) {
  Mesh mesh = square();
  mesh.polygon_sizes = {4};
  mesh.polygon_indices = {0, 1, 3, 2};
  EXPECT_EQ(io::obj_text(mesh, "c", {"out_s.mtl", "wood"}),
            "# c\nmtllib out_s.mtl\n"
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
            "vt 0 0\nvt 0.5 0\nvt 0 0.25\nvt 0.5 0.25\n"
            "vn 0 0 1\nvn 0 0 1\nvn 0 0 1\nvn 0 0 1\n"
            "usemtl wood\nf 1/1/1 2/2/2 4/4/4 3/3/3\n");
}

TEST(ObjTextureCoordinates, ANonFiniteOneIsRefused) {
  Mesh mesh = square();
  mesh.uvs[2].y = std::numeric_limits<float>::infinity();
  EXPECT_FALSE(io::mesh_is_finite(mesh));
}

TEST(MtlText, ColourSpecularShininessAndMaps) {
  SurfaceMaterial m = wood();
  m.bump_height = 0.05f;
  EXPECT_EQ(io::mtl_text(m, {"out_vase_wood.png", "out_vase_grain.png"}, "sweep: vase from m.swp"),
            "# sweep: vase from m.swp\n"
            "newmtl wood\n"
            "Kd 0.8 0.5 0.25\n"
            "Ks 0.45 0.45 0.45\n"
            "Ns 20\n"
            "illum 2\n"
            "map_Kd out_vase_wood.png\n"
            "map_Bump -bm 0.05 out_vase_grain.png\n");
}

TEST(MtlText, TheDefaultLookIsNamedDefault) {
  const SurfaceMaterial m;
  EXPECT_EQ(io::mtl_material_name(m), "default");
  EXPECT_EQ(io::mtl_text(m, {}), "newmtl default\nKd 0.62 0.68 0.8\nKs 0.45 0.45 0.45\nNs 48\nillum 2\n");
}

TEST(CheckerPng, CellsOfTwoGreysLightAtTheOrigin) {
  for (int cells : {1, 3, 8}) {
    const std::string png = io::checker_png(cells);
    ASSERT_TRUE(io::is_png(png));
    const Decoded image = decode_grey(png);
    const int side = cells * kCheckerPixelsPerCell;
    ASSERT_EQ(image.width, side) << cells;
    ASSERT_EQ(image.height, side) << cells;
    for (int row = 0; row < cells; ++row) {  // cell rows from the bottom (v = 0)
      for (int column = 0; column < cells; ++column) {
        const unsigned char expected = (row + column) % 2 == 0 ? io::kCheckerLightGrey : io::kCheckerDarkGrey;
        const int x0 = column * kCheckerPixelsPerCell;
        const int y0 = side - (row + 1) * kCheckerPixelsPerCell;  // image rows from the top
        const std::pair<int, int> probes[] = {
            {0, 0}, {kCheckerPixelsPerCell - 1, kCheckerPixelsPerCell - 1}, {kCheckerPixelsPerCell / 2, 3}};
        for (const auto& [dx, dy] : probes) {
          EXPECT_EQ(image.at(x0 + dx, y0 + dy), expected) << cells << " cells, cell " << column << "," << row;
        }
      }
    }
  }
  EXPECT_EQ(io::checker_file_name(8), "checker8.png");
}

TEST(MaterialImages, TexturesAndBumpsAreReadWholeAndCheckersMade) {
  const ScratchFolder folder("sweep-mtl");
  const std::string texture = io::checker_png(2);
  write_bytes(folder.path() / "wood.png", texture);
  SurfaceMaterial m = wood();
  m.texture = folder.path() / "wood.png";
  m.bump = folder.path() / "wood.png";
  const io::MaterialImages images = io::read_material_images(m);
  EXPECT_EQ(images.texture, texture);
  EXPECT_EQ(images.bump, texture);

  SurfaceMaterial checker = wood();
  checker.checker = 4;
  const io::MaterialImages made = io::read_material_images(checker);
  EXPECT_EQ(made.texture, io::checker_png(4));
  EXPECT_TRUE(made.bump.empty());
  EXPECT_TRUE(io::read_material_images(wood()).texture.empty());
}

TEST(MaterialImages, AMissingOrForeignFileIsNamedWithTheReason) {
  const ScratchFolder folder("sweep-mtl");
  SurfaceMaterial m = wood();
  m.texture = folder.path() / "gone.png";
  try {
    io::read_material_images(m);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read texture " + m.texture.string() + ": No such file or directory");
  }
  write_text(folder.path() / "text.png", "not an image\n");
  m.texture.clear();
  m.bump = folder.path() / "text.png";
  try {
    io::read_material_images(m);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot read bump image " + m.bump.string() + ": not a PNG image");
  }
}

/// What tinyobjloader makes of an OBJ file and its MTL; `warning` and `error` are its messages.
struct Loaded {
  tinyobj::attrib_t attrib;
  std::vector<tinyobj::shape_t> shapes;
  std::vector<tinyobj::material_t> materials;
  std::string warning;
  std::string error;
  bool ok = false;
};

Loaded load_with_tinyobjloader(const fs::path& obj) {
  Loaded out;
  const std::string folder = obj.parent_path().string() + "/";
  out.ok = tinyobj::LoadObj(&out.attrib, &out.shapes, &out.materials, &out.warning, &out.error, obj.c_str(),
                            folder.c_str(), false);
  return out;
}

TEST(MtlFiles, TinyObjLoaderReadsThemWithoutAWarning) {
  const ScratchFolder folder("sweep-mtl");
  Mesh mesh = square();
  SurfaceMaterial m = wood();
  m.bump_height = 0.25f;
  io::save_obj_file(folder.path() / "out_s.obj", mesh, "sweep: s", {"out_s.mtl", "wood"});
  io::save_mtl_file(folder.path() / "out_s.mtl", m, {"out_s_checker2.png", "out_s_bumps.png"});
  write_bytes(folder.path() / "out_s_checker2.png", io::checker_png(2));
  write_bytes(folder.path() / "out_s_bumps.png", io::checker_png(1));
  EXPECT_EQ(folder.entries(),
            (std::vector<std::string>{"out_s.mtl", "out_s.obj", "out_s_bumps.png", "out_s_checker2.png"}));

  const Loaded loaded = load_with_tinyobjloader(folder.path() / "out_s.obj");
  ASSERT_TRUE(loaded.ok) << loaded.error;
  EXPECT_EQ(loaded.warning, "");
  EXPECT_EQ(loaded.error, "");
  EXPECT_EQ(loaded.attrib.vertices.size(), 3 * mesh.vertex_count());
  EXPECT_EQ(loaded.attrib.normals.size(), 3 * mesh.vertex_count());
  ASSERT_EQ(loaded.attrib.texcoords.size(), 2 * mesh.vertex_count());
  for (std::size_t i = 0; i < mesh.uvs.size(); ++i) {
    EXPECT_EQ(loaded.attrib.texcoords[2 * i], static_cast<double>(mesh.uvs[i].x));
    EXPECT_EQ(loaded.attrib.texcoords[2 * i + 1], static_cast<double>(mesh.uvs[i].y));
  }
  ASSERT_EQ(loaded.shapes.size(), 1u);
  const tinyobj::mesh_t& faces = loaded.shapes[0].mesh;
  ASSERT_EQ(faces.num_face_vertices.size(), mesh.triangle_count());
  ASSERT_EQ(faces.indices.size(), mesh.indices.size());
  for (std::size_t k = 0; k < faces.indices.size(); ++k) {
    const auto index = static_cast<int>(mesh.indices[k]);
    EXPECT_EQ(faces.indices[k].vertex_index, index);
    EXPECT_EQ(faces.indices[k].texcoord_index, index);
    EXPECT_EQ(faces.indices[k].normal_index, index);
  }
  EXPECT_EQ(faces.material_ids, (std::vector<int>{0, 0}));
  ASSERT_EQ(loaded.materials.size(), 1u);
  const tinyobj::material_t& material = loaded.materials[0];
  EXPECT_EQ(material.name, "wood");
  EXPECT_FLOAT_EQ(static_cast<float>(material.diffuse[0]), 0.8f);
  EXPECT_FLOAT_EQ(static_cast<float>(material.diffuse[1]), 0.5f);
  EXPECT_FLOAT_EQ(static_cast<float>(material.diffuse[2]), 0.25f);
  EXPECT_FLOAT_EQ(static_cast<float>(material.specular[0]), io::kSpecularGrey);
  EXPECT_FLOAT_EQ(static_cast<float>(material.shininess), 20.0f);
  EXPECT_EQ(material.illum, 2);
  EXPECT_EQ(material.diffuse_texname, "out_s_checker2.png");
  EXPECT_EQ(material.bump_texname, "out_s_bumps.png");
  EXPECT_FLOAT_EQ(static_cast<float>(material.bump_texopt.bump_multiplier), 0.25f);
  EXPECT_TRUE(fs::exists(folder.path() / material.diffuse_texname));
  EXPECT_TRUE(fs::exists(folder.path() / material.bump_texname));
}

}  // namespace
}  // namespace sweep
