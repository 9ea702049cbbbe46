// Catmull-Clark evaluated face by face (geometry/subdivision/subdivision_faces.hpp) against Far's refinement
// (subdivide_by_refinement, what subdivide returned before): the same vertex and triangle
// numbering, positions and normals within 1e-6, on closed, open, mixed-polygon and extraordinary
// cages at both boundary rules; the same bytes whatever the thread count; and subdivide taking
// the refinement wherever the faces' path declines.
#include "geometry/subdivision/subdivision_faces.hpp"
#include "geometry/subdivision/subdivision.hpp"
#include "geometry/subdivision/subdivision_limit.hpp"
#include "geometry/surfaces/patch.hpp"
#include "geometry/thread_pool.hpp"
#include "model/evaluation/scene.hpp"

#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <atomic>
#include <cmath>
#include <cstring>
#include <numbers>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace {

using sweep::Cage;
using sweep::Subdivided;
using sweep::SubdivisionOptions;
using sweep::SubdivisionScheme;
using sweep::subdivision_detail::subdivide_by_faces;
using sweep::subdivision_detail::subdivide_by_refinement;

Cage cube() {
  Cage c;
  c.points = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  c.face_sizes = {4, 4, 4, 4, 4, 4};
  c.face_vertices = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 3, 7, 6, 2, 0, 4, 7, 3, 1, 2, 6, 5};
  return c;
}

/// The benchmark's torus (BM_SubdivideTenThousandFaces), `around` x `through` quads, jittered.
Cage torus(int around, int through, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  Cage c;
  for (int i = 0; i < around; ++i) {
    const double u = 2.0 * std::numbers::pi * i / around;
    for (int j = 0; j < through; ++j) {
      const double v = 2.0 * std::numbers::pi * j / through;
      const double r = 3.0 + std::cos(v);
      c.points.emplace_back(r * std::cos(u) + jitter(rng), std::sin(v) + jitter(rng), -r * std::sin(u) + jitter(rng));
    }
  }
  const auto at = [&](int a, int b) { return (a % around) * through + b % through; };
  for (int i = 0; i < around; ++i) {
    for (int j = 0; j < through; ++j) {
      c.face_sizes.push_back(4);
      c.face_vertices.insert(c.face_vertices.end(), {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
    }
  }
  return c;
}

/// A square and four triangles: quads and triangles, extraordinary vertices of valence 3 and 4.
Cage pyramid() {
  Cage c;
  c.points = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1.5}};
  c.face_sizes = {4, 3, 3, 3, 3};
  c.face_vertices = {0, 3, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  return c;
}

/// An open grid of n x n points, bumped: boundary edges, valence-2 corners, valence-3 sides.
Cage bumpy_grid(int n) {
  Cage c;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) c.points.emplace_back(i, j, 0.3 * std::sin(1.7 * i + 0.9 * j) + 0.1 * i * j / n);
  }
  for (int i = 0; i + 1 < n; ++i) {
    for (int j = 0; j + 1 < n; ++j) {
      c.face_sizes.push_back(4);
      c.face_vertices.insert(c.face_vertices.end(), {i * n + j, (i + 1) * n + j, (i + 1) * n + j + 1, i * n + j + 1});
    }
  }
  return c;
}

/// One open pentagon with its corners at two heights: an n-gon on the boundary.
Cage pentagon() {
  Cage c;
  for (int k = 0; k < 5; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 5.0;
    c.points.emplace_back(std::cos(a), std::sin(a), 0.2 * (k % 2));
  }
  c.face_sizes = {5};
  c.face_vertices = {0, 1, 2, 3, 4};
  return c;
}

/// Six triangles around a vertex of valence 6 (an open fan), and a point in no face.
Cage fan() {
  Cage c;
  c.points = {{0, 0, 0.3}};
  for (int k = 0; k < 6; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 6.0;
    c.points.emplace_back(std::cos(a), std::sin(a), 0.1 * k);
  }
  c.points.emplace_back(5, 5, 5);
  for (int k = 0; k < 6; ++k) {
    c.face_sizes.push_back(3);
    c.face_vertices.insert(c.face_vertices.end(), {0, 1 + k, 1 + (k + 1) % 6});
  }
  return c;
}

/// A closed cage of mixed polygons: a hexagonal prism (a hexagon below, quads around), capped by
/// six triangles around an apex: vertices of valence 3, 4 (among triangles) and 6, and a hexagon's
/// centre of valence 6.
Cage mixed_polygons() {
  Cage c;
  for (const double z : {0.0, 1.0}) {
    for (int k = 0; k < 6; ++k) {
      const double a = 2.0 * std::numbers::pi * k / 6.0;
      c.points.emplace_back((1.0 + 0.1 * k) * std::cos(a), std::sin(a), z + 0.05 * k);
    }
  }
  c.points.emplace_back(0.1, 0.0, 1.8);  // the apex, 12
  c.face_sizes.push_back(6);
  c.face_vertices.insert(c.face_vertices.end(), {5, 4, 3, 2, 1, 0});  // seen from below
  for (int k = 0; k < 6; ++k) {
    const int next = (k + 1) % 6;
    c.face_sizes.push_back(4);
    c.face_vertices.insert(c.face_vertices.end(), {k, next, 6 + next, 6 + k});
  }
  for (int k = 0; k < 6; ++k) {
    c.face_sizes.push_back(3);
    c.face_vertices.insert(c.face_vertices.end(), {6 + k, 6 + (k + 1) % 6, 12});
  }
  return c;
}

/// A surface of revolution through the axis, as a subd's cage (grid_cage): triangles at the
/// poles, whose points are extraordinary (valence 12).
Cage sphere_like() {
  const sweep::Document doc =
      sweep::io::parse_swp("bez2 p 4 4 [0 -1] [1.5 -1] [1.5 1] [0 1]\nsrev s 12 p\n", "test.swp");
  const sweep::Scene scene = sweep::evaluate_document(doc);
  return sweep::grid_cage(scene.objects[1].mesh);
}

/// An open tube: a surface of revolution's grid cage (boundary rings at both ends).
Cage tube() {
  const sweep::Document doc =
      sweep::io::parse_swp("bsp2 p 4 5 [1 0] [1.5 1] [1 2] [1.2 3] [1 4]\nsrev s 16 p\n", "test.swp");
  const sweep::Scene scene = sweep::evaluate_document(doc);
  return sweep::grid_cage(scene.objects[1].mesh);
}

/// The teapot's patches as one cage (open at the spout and handle, poles at the lid and bottom,
/// and a vertex where the body's rim meets the lid's: not manifold).
Cage teapot() {
  const sweep::Document doc = sweep::test::load_starter("teapot.swp");
  return sweep::bezier_patch_cage(doc.objects[0].as<sweep::PointsPart>().points,
                                  doc.objects[0].as<sweep::StepsPart>().steps);
}

SubdivisionOptions catmark(int levels, bool smooth_boundary) {
  SubdivisionOptions options;
  options.levels = levels;
  options.smooth_boundary = smooth_boundary;
  return options;
}

double largest_distance(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b) {
  double largest = 0.0;
  for (std::size_t k = 0; k < a.size() && k < b.size(); ++k) {
    largest = std::max(largest, sweep::test::distance(glm::dvec3(a[k]), glm::dvec3(b[k])));
  }
  return largest;
}

bool same_bytes(const sweep::Mesh& a, const sweep::Mesh& b) {
  const auto bytes = [](const auto& x, const auto& y) {
    return x.size() == y.size() && (x.empty() || std::memcmp(x.data(), y.data(), x.size() * sizeof(x[0])) == 0);
  };
  return bytes(a.positions, b.positions) && bytes(a.normals, b.normals) && bytes(a.indices, b.indices) &&
         a.uvs.empty() && b.uvs.empty() && a.polygon_sizes.empty() && b.polygon_sizes.empty();
}

TEST(SubdivisionFaces, MatchesFarsRefinementWithin1e6) {
  const std::vector<std::pair<std::string, Cage>> cages = {{"cube", cube()},
                                                           {"torus", torus(7, 9, 3)},
                                                           {"pyramid", pyramid()},
                                                           {"grid", bumpy_grid(5)},
                                                           {"pentagon", pentagon()},
                                                           {"fan", fan()},
                                                           {"mixed", mixed_polygons()},
                                                           {"sphere-like", sphere_like()},
                                                           {"tube", tube()}};
  for (const auto& [name, cage] : cages) {
    ASSERT_FALSE(sweep::check_cage(cage).has_value()) << name;
    for (const int level : {1, 2, 3, 4}) {
      for (const bool smooth_boundary : {false, true}) {
        const std::string what = name + " level " + std::to_string(level) + (smooth_boundary ? " smooth" : "");
        const SubdivisionOptions options = catmark(level, smooth_boundary);
        const std::optional<Subdivided> faces = subdivide_by_faces(cage, options, 2);
        ASSERT_TRUE(faces.has_value()) << what << ": the faces' path declined";
        const Subdivided refined = subdivide_by_refinement(cage, options);
        EXPECT_EQ(faces->counts.vertices, refined.counts.vertices) << what;
        EXPECT_EQ(faces->counts.edges, refined.counts.edges) << what;
        EXPECT_EQ(faces->counts.faces, refined.counts.faces) << what;
        ASSERT_EQ(faces->mesh.positions.size(), refined.mesh.positions.size()) << what;
        ASSERT_EQ(faces->mesh.normals.size(), refined.mesh.normals.size()) << what;
        EXPECT_EQ(faces->mesh.indices, refined.mesh.indices) << what << ": triangles or their order differ";
        EXPECT_LE(largest_distance(faces->mesh.positions, refined.mesh.positions), 1e-6) << what;
        EXPECT_LE(largest_distance(faces->mesh.normals, refined.mesh.normals), 1e-6) << what;
        // What subdivide returns is the faces' result.
        EXPECT_TRUE(same_bytes(sweep::subdivide(cage, options).mesh, faces->mesh)) << what;
      }
    }
  }
}

TEST(SubdivisionFaces, TheSameBytesWhateverTheThreadCount) {
  const std::vector<std::pair<std::string, Cage>> cages = {{"torus", torus(40, 30, 5)},
                                                           {"sphere-like", sphere_like()},
                                                           {"mixed", mixed_polygons()},
                                                           {"grid", bumpy_grid(9)},
                                                           {"fan", fan()}};
  for (const auto& [name, cage] : cages) {
    for (const int level : {1, 3}) {
      const SubdivisionOptions options = catmark(level, false);
      const std::optional<Subdivided> one = subdivide_by_faces(cage, options, 1);
      ASSERT_TRUE(one.has_value()) << name;
      for (const int threads : {2, 3, 8}) {
        const std::optional<Subdivided> many = subdivide_by_faces(cage, options, threads);
        ASSERT_TRUE(many.has_value()) << name;
        EXPECT_TRUE(same_bytes(one->mesh, many->mesh)) << name << " level " << level << ", " << threads << " threads";
      }
    }
  }
}

TEST(SubdivisionFaces, DeclinesWhatItDoesNotDoAndSubdivideRefinesInstead) {
  // Level 0 and Loop are the refinement's.
  EXPECT_FALSE(subdivide_by_faces(cube(), catmark(0, false), 1).has_value());
  SubdivisionOptions loop = catmark(1, false);
  loop.scheme = SubdivisionScheme::Loop;
  Cage tetrahedron;
  tetrahedron.points = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  tetrahedron.face_sizes = {3, 3, 3, 3};
  tetrahedron.face_vertices = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
  EXPECT_FALSE(subdivide_by_faces(tetrahedron, loop, 1).has_value());
  // A vertex where two fans of faces meet at a point only is non-manifold: no ring to read.
  Cage bowtie;
  bowtie.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
  bowtie.face_sizes = {3, 3};
  bowtie.face_vertices = {0, 1, 2, 0, 3, 4};
  EXPECT_FALSE(subdivide_by_faces(bowtie, catmark(2, false), 1).has_value());
  EXPECT_TRUE(same_bytes(sweep::subdivide(bowtie, catmark(2, false)).mesh,
                         subdivide_by_refinement(bowtie, catmark(2, false)).mesh));
  // So has the teapot's cage (bezier_patch_cage), at one vertex.
  const Cage pot = teapot();
  ASSERT_FALSE(sweep::check_cage(pot).has_value());
  EXPECT_FALSE(subdivide_by_faces(pot, catmark(1, false), 2).has_value());
  EXPECT_TRUE(
      same_bytes(sweep::subdivide(pot, catmark(1, false)).mesh, subdivide_by_refinement(pot, catmark(1, false)).mesh));
  // A quad folded onto itself (two corners at one point) has parallel tangents there: the
  // normal is the refinement's fallback, so the faces' path declines and subdivide refines.
  Cage folded;
  folded.points = {{0, 0, 0}, {1, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  folded.face_sizes = {4};
  folded.face_vertices = {0, 1, 2, 3};
  for (const int level : {1, 2}) {
    const std::optional<Subdivided> faces = subdivide_by_faces(folded, catmark(level, false), 1);
    const Subdivided refined = subdivide_by_refinement(folded, catmark(level, false));
    const Subdivided chosen = sweep::subdivide(folded, catmark(level, false));
    if (faces) {
      EXPECT_EQ(faces->mesh.indices, refined.mesh.indices);
      EXPECT_LE(largest_distance(faces->mesh.positions, refined.mesh.positions), 1e-6);
      EXPECT_LE(largest_distance(faces->mesh.normals, refined.mesh.normals), 1e-6);
      EXPECT_TRUE(same_bytes(chosen.mesh, faces->mesh));
    } else {
      EXPECT_TRUE(same_bytes(chosen.mesh, refined.mesh));
    }
  }
}

TEST(SubdivisionFaces, ThreadsOnlyForLargeRefinements) {
  EXPECT_EQ(sweep::subdivision_detail::subdivision_threads(cube(), catmark(3, false)), 1);
  EXPECT_EQ(sweep::subdivision_detail::subdivision_threads(torus(100, 100, 1), catmark(3, false)),
            sweep::worker_count());
  EXPECT_EQ(sweep::subdivision_detail::subdivision_threads(torus(100, 100, 1), catmark(0, false)), 1);
  EXPECT_GE(sweep::worker_count(), 1);
}

TEST(SubdivisionFaces, ParallelChunksCoverEveryItemOnceAndRethrow) {
  for (const int threads : {1, 2, 5}) {
    std::vector<std::atomic<int>> seen(1000);
    sweep::parallel_chunks(seen.size(), 7, threads, [&](std::size_t begin, std::size_t end, int worker) {
      EXPECT_GE(worker, 0);
      EXPECT_LT(worker, threads);
      for (std::size_t i = begin; i < end; ++i) ++seen[i];
    });
    for (const std::atomic<int>& count : seen) EXPECT_EQ(count.load(), 1);
    EXPECT_THROW(sweep::parallel_chunks(100, 3, threads,
                                        [](std::size_t begin, std::size_t, int) {
                                          if (begin == 42) throw std::runtime_error("chunk 14");
                                        }),
                 std::runtime_error);
  }
}

}  // namespace
