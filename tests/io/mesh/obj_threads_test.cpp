// The OBJ text is formatted on several threads (in chunks, written in order) and must be the
// same bytes whatever the thread count, with and without texture coordinates (issue 44, item 4).
#include "geometry/mesh/mesh.hpp"
#include "geometry/thread_pool.hpp"
#include "io/mesh/obj_writer.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

namespace {

/// A grid of `rows` x `columns` vertices (two triangles a cell) on a wavy sheet: enough items
/// for many chunks of every section, and numbers of many lengths.
sweep::Mesh wavy_grid(std::uint32_t rows, std::uint32_t columns, bool uvs) {
  sweep::Mesh mesh;
  for (std::uint32_t i = 0; i < rows; ++i) {
    for (std::uint32_t j = 0; j < columns; ++j) {
      const float x = 0.01f * float(j);
      const float z = 0.013f * float(i);
      mesh.positions.emplace_back(x, std::sin(3.0f * x) * std::cos(2.0f * z), z);
      mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
      if (uvs) mesh.uvs.emplace_back(float(j) / float(columns - 1), float(i) / float(rows - 1));
    }
  }
  for (std::uint32_t i = 0; i + 1 < rows; ++i) {
    for (std::uint32_t j = 0; j + 1 < columns; ++j) {
      const std::uint32_t a = i * columns + j;
      mesh.indices.insert(mesh.indices.end(), {a, a + columns, a + 1, a + 1, a + columns, a + columns + 1});
    }
  }
  return mesh;
}

/// Restores the worker count the process started with.
class ObjThreads : public ::testing::Test {
 protected:
  void TearDown() override { sweep::set_worker_count(sweep::default_worker_count()); }
};

TEST_F(ObjThreads, TheTextIsTheSameBytesWhateverTheThreadCount) {
  for (const bool uvs : {false, true}) {
    const sweep::Mesh mesh = wavy_grid(300, 400, uvs);  // 120 000 vertices, 238 602 triangles
    sweep::set_worker_count(1);
    const std::string one = sweep::io::obj_text(mesh, "grid", {"grid.mtl", "paint"});
    ASSERT_GT(one.size(), 10'000'000u);
    for (const int threads : {2, 3, 8}) {
      sweep::set_worker_count(threads);
      EXPECT_EQ(sweep::io::obj_text(mesh, "grid", {"grid.mtl", "paint"}), one) << threads << " threads, uvs " << uvs;
    }
  }
}

TEST_F(ObjThreads, ThePiecesComeInOrder) {
  const sweep::Mesh mesh = wavy_grid(300, 400, false);
  sweep::set_worker_count(3);
  const std::string text = sweep::io::obj_text(mesh);
  // The first and the last of each section where they belong, and each section whole.
  EXPECT_EQ(text.rfind("v 0 0 0\n", 0), 0u);
  const std::size_t last_v = text.rfind("\nv ");
  const std::size_t first_vn = text.find("\nvn ");
  const std::size_t first_f = text.find("\nf ");
  EXPECT_LT(last_v, first_vn);
  EXPECT_LT(text.rfind("\nvn "), first_f);
  EXPECT_EQ(text.substr(first_f + 1, text.find('\n', first_f + 1) - first_f - 1), "f 1//1 401//401 2//2");
  std::size_t faces = 0;
  for (std::size_t at = text.find("\nf "); at != std::string::npos; at = text.find("\nf ", at + 1)) ++faces;
  EXPECT_EQ(faces, mesh.indices.size() / 3);
  EXPECT_EQ(text.substr(text.rfind("\nf ") + 1), "f 119600//119600 119999//119999 120000//120000\n");
}

}  // namespace
