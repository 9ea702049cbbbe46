// Binary STL (mesh/stl_writer.hpp) read back byte by byte, and the topology counts
// (mesh_topology.hpp) that decide the export's closed-manifold warning.
#include "geometry/mesh/mesh_topology.hpp"
#include "io/mesh/stl_writer.hpp"

#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <bit>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <limits>
#include <stdexcept>
#include <string>

namespace {

using sweep::Mesh;

/// A unit cube, triangles counterclockwise seen from outside, each face with its own 4 vertices
/// (as caps have their own): closed only once equal positions are welded.
Mesh cube() {
  Mesh m;
  const glm::vec3 corners[8] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
  // Faces as corner quads, counterclockwise seen from outside.
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}};
  for (const auto& f : faces) {
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    for (int k = 0; k < 4; ++k) {
      m.positions.push_back(corners[f[k]]);
      m.normals.emplace_back(0.0f, 0.0f, 1.0f);
    }
    m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return m;
}

std::uint32_t u32_at(const std::string& bytes, std::size_t at) {
  std::uint32_t v = 0;
  for (int k = 3; k >= 0; --k) v = (v << 8) | static_cast<unsigned char>(bytes[at + static_cast<std::size_t>(k)]);
  return v;
}
float f32_at(const std::string& bytes, std::size_t at) {
  return std::bit_cast<float>(u32_at(bytes, at));
}

TEST(MeshTopology, WeldedCubeIsAClosedManifoldOfVolumeOne) {
  const Mesh m = cube();
  const sweep::MeshTopology t = sweep::mesh_topology(m);
  EXPECT_EQ(t.welded_vertices, 8u);
  EXPECT_EQ(t.boundary_edges, 0u);
  EXPECT_EQ(t.non_manifold_edges, 0u);
  EXPECT_TRUE(t.closed_manifold());
  EXPECT_DOUBLE_EQ(sweep::signed_volume(m), 1.0);
}

TEST(MeshTopology, OpenFlippedAndOverusedEdgesAreCounted) {
  Mesh open = cube();
  open.indices.resize(open.indices.size() - 6);  // one face removed: its 4 edges are boundary
  EXPECT_EQ(sweep::mesh_topology(open).boundary_edges, 4u);
  EXPECT_FALSE(sweep::mesh_topology(open).closed_manifold());

  Mesh flipped = cube();
  std::swap(flipped.indices[7], flipped.indices[8]);  // a triangle of the top face turned over
  const sweep::MeshTopology t = sweep::mesh_topology(flipped);
  EXPECT_EQ(t.boundary_edges, 0u);
  EXPECT_EQ(t.non_manifold_edges, 3u);  // its three edges now run the same way as a neighbour's
  EXPECT_LT(sweep::signed_volume(flipped), 1.0);

  Mesh fin = cube();  // a third triangle on the edge (0,0,0)-(1,0,0)
  fin.positions.emplace_back(0.5f, -1.0f, -1.0f);
  fin.normals.emplace_back(0.0f, 0.0f, 1.0f);
  const auto extra = static_cast<std::uint32_t>(fin.positions.size() - 1);
  fin.indices.insert(fin.indices.end(), {0, extra, 3});  // vertex 3 is corner 1 (1,0,0) of face 0
  EXPECT_EQ(sweep::mesh_topology(fin).non_manifold_edges, 1u);
  EXPECT_EQ(sweep::mesh_topology(fin).boundary_edges, 2u);
}

TEST(Stl, BytesAreHeaderCountAndFiftyBytesPerTriangle) {
  const Mesh m = cube();
  const std::string bytes = sweep::io::stl_bytes(m, "cube from test.swp");
  ASSERT_EQ(bytes.size(), 84u + 50u * m.triangle_count());
  EXPECT_NE(bytes.compare(0, 5, "solid"), 0);  // ASCII STL starts so; readers would misread it
  EXPECT_EQ(bytes.substr(0, 37), std::string("sweep binary STL: cube from test.swp") + '\0');
  EXPECT_EQ(u32_at(bytes, 80), m.triangle_count());
  for (std::size_t t = 0; t < m.triangle_count(); ++t) {
    const std::size_t at = 84 + 50 * t;
    const glm::vec3 n(f32_at(bytes, at), f32_at(bytes, at + 4), f32_at(bytes, at + 8));
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-6f);
    for (int k = 0; k < 3; ++k) {
      const glm::vec3 p(f32_at(bytes, at + 12 + 12 * static_cast<std::size_t>(k)),
                        f32_at(bytes, at + 16 + 12 * static_cast<std::size_t>(k)),
                        f32_at(bytes, at + 20 + 12 * static_cast<std::size_t>(k)));
      EXPECT_EQ(p, m.positions[m.indices[3 * t + static_cast<std::size_t>(k)]]);
    }
    // The facet normal points out of the cube: away from its centre.
    const glm::vec3 centre =
        (m.positions[m.indices[3 * t]] + m.positions[m.indices[3 * t + 1]] + m.positions[m.indices[3 * t + 2]]) / 3.0f;
    EXPECT_GT(glm::dot(n, centre - glm::vec3(0.5f)), 0.0f);
    EXPECT_EQ(bytes[at + 48], '\0');
    EXPECT_EQ(bytes[at + 49], '\0');
  }
  // A long comment is cut to the header's 80 bytes.
  EXPECT_EQ(sweep::io::stl_bytes(m, std::string(200, 'x')).size(), bytes.size());
}

TEST(Stl, MinusZeroIsWrittenAsZeroSoEqualCornersHaveEqualBytes) {
  // A pole's copies: (0, 1, -0) and (0, 1, +0) are one point, and admesh matches corners by bytes.
  Mesh m;
  m.positions = {{0.0f, 1.0f, -0.0f}, {1.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 1.0f}};
  m.normals.assign(3, glm::vec3(0.0f, 1.0f, 0.0f));
  m.indices = {0, 1, 2};
  const std::string bytes = sweep::io::stl_bytes(m, "pole");
  EXPECT_EQ(u32_at(bytes, 84 + 12 + 8), 0u) << "the first corner's z: +0's bits";
  EXPECT_EQ(u32_at(bytes, 84 + 12), 0u);
}

TEST(Stl, TheSavedFileIsItsBytesAcrossManyChunks) {
  // 1000 cubes: 12,000 triangles, past several of write_stl's 1310-triangle chunks and not a
  // whole number of them, each cube moved so no two chunks are alike.
  Mesh m;
  for (int k = 0; k < 1000; ++k) {
    const Mesh c = cube();
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    for (const glm::vec3& p : c.positions) m.positions.push_back(p + glm::vec3(float(k), 0.5f * float(k % 7), 0.0f));
    m.normals.insert(m.normals.end(), c.normals.begin(), c.normals.end());
    for (const std::uint32_t i : c.indices) m.indices.push_back(base + i);
  }
  const sweep::test::ScratchFolder folder("sweep-stl");
  const std::filesystem::path path = folder.path() / "cubes.stl";
  sweep::io::save_stl_file(path, m, "cubes");
  std::FILE* f = std::fopen(path.c_str(), "rb");
  ASSERT_NE(f, nullptr);
  std::string saved(84 + 50 * m.triangle_count() + 1, '\0');
  saved.resize(std::fread(saved.data(), 1, saved.size(), f));
  std::fclose(f);
  EXPECT_EQ(saved.size(), 84 + 50 * std::size_t{12000});
  EXPECT_TRUE(saved == sweep::io::stl_bytes(m, "cubes"));
}

TEST(Stl, NonFiniteMeshIsRefusedAndNothingWritten) {
  Mesh m = cube();
  m.positions[0].x = std::numeric_limits<float>::quiet_NaN();
  const sweep::test::ScratchFolder folder("sweep-stl");
  const std::filesystem::path path = folder.path() / "nan.stl";
  EXPECT_THROW(sweep::io::save_stl_file(path, m), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
