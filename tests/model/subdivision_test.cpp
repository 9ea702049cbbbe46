// Subdivision surfaces (core/subdivision.hpp): counts per level against the refinement formulas,
// limit positions against closed forms (Halstead et al. 1993 and Loop 1987 limit masks, the
// uniform bicubic B-spline that Catmull-Clark reproduces on a regular cage, Stam 1998), boundary
// rules, orientation, check_cage's messages, and the cages of grid surfaces.
#include "geometry/subdivision/subdivision.hpp"
#include "geometry/mesh/mesh_topology.hpp"
#include "geometry/surfaces/patch.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"

#include "model/evaluation/curve_evaluation.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

namespace {

using sweep::Cage;
using sweep::CageCounts;
using sweep::SubdivisionOptions;
using sweep::SubdivisionScheme;

constexpr SubdivisionScheme kCatmark = SubdivisionScheme::CatmullClark;
constexpr SubdivisionScheme kLoop = SubdivisionScheme::Loop;

/// The cube [-1, 1]^3, faces counterclockwise seen from outside.
Cage cube() {
  Cage c;
  c.points = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  c.face_sizes = {4, 4, 4, 4, 4, 4};
  c.face_vertices = {0, 3, 2, 1,   // z = -1
                     4, 5, 6, 7,   // z = +1
                     0, 1, 5, 4,   // y = -1
                     3, 7, 6, 2,   // y = +1
                     0, 4, 7, 3,   // x = -1
                     1, 2, 6, 5};  // x = +1
  return c;
}

/// The octahedron of the unit points on the axes, faces counterclockwise seen from outside.
Cage octahedron() {
  Cage c;
  c.points = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (const int sx : {1, -1}) {
    for (const int sy : {1, -1}) {
      for (const int sz : {1, -1}) {
        const int x = sx > 0 ? 0 : 1, y = sy > 0 ? 2 : 3, z = sz > 0 ? 4 : 5;
        c.face_sizes.push_back(3);
        if (sx * sy * sz > 0) {
          c.face_vertices.insert(c.face_vertices.end(), {x, y, z});
        } else {
          c.face_vertices.insert(c.face_vertices.end(), {x, z, y});
        }
      }
    }
  }
  return c;
}

/// A regular tetrahedron centred at the origin, faces counterclockwise seen from outside.
Cage tetrahedron() {
  Cage c;
  c.points = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  c.face_sizes = {3, 3, 3, 3};
  c.face_vertices = {0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2};
  return c;
}

/// A torus cage of rows x columns quads, vertex (i, j) = i * columns + j at angle i around the
/// tube and j around the axis (+z), jittered; faces counterclockwise seen from outside.
Cage torus(int rows, int columns, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> jitter(-0.08, 0.08);
  Cage c;
  for (int i = 0; i < rows; ++i) {
    const double phi = 2.0 * std::numbers::pi * i / rows;
    for (int j = 0; j < columns; ++j) {
      const double theta = 2.0 * std::numbers::pi * j / columns;
      const double radius = 3.0 + std::cos(phi);
      c.points.emplace_back(radius * std::cos(theta) + jitter(rng), radius * std::sin(theta) + jitter(rng),
                            std::sin(phi) + jitter(rng));
    }
  }
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      const int i1 = (i + 1) % rows, j1 = (j + 1) % columns;
      c.face_sizes.push_back(4);
      c.face_vertices.insert(c.face_vertices.end(),
                             {i * columns + j, i * columns + j1, i1 * columns + j1, i1 * columns + j});
    }
  }
  return c;
}

/// An open n x n grid of points (x = i, y = j, z bumped), (n-1)^2 quads facing +z.
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

sweep::Subdivided refine(const Cage& cage, int levels, SubdivisionScheme scheme = kCatmark,
                         bool smooth_boundary = false) {
  SubdivisionOptions options;
  options.levels = levels;
  options.scheme = scheme;
  options.smooth_boundary = smooth_boundary;
  return sweep::subdivide(cage, options);
}

void expect_counts(const CageCounts& actual, std::int64_t v, std::int64_t e, std::int64_t f, const std::string& what) {
  EXPECT_EQ(actual.vertices, v) << what;
  EXPECT_EQ(actual.edges, e) << what;
  EXPECT_EQ(actual.faces, f) << what;
}

/// A closed, outward, unit-normal mesh around the origin: no boundary, consistently oriented,
/// positive volume, every normal unit and pointing away from the origin.
void expect_closed_outward(const sweep::Mesh& mesh, const std::string& what) {
  const sweep::MeshTopology topology = sweep::mesh_topology(mesh);
  EXPECT_EQ(topology.boundary_edges, 0u) << what;
  EXPECT_EQ(topology.non_manifold_edges, 0u) << what;
  EXPECT_GT(sweep::signed_volume(mesh), 0.0) << what;
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size()) << what;
  for (std::size_t k = 0; k < mesh.vertex_count(); ++k) {
    EXPECT_NEAR(glm::length(mesh.normals[k]), 1.0f, 1e-5f) << what;
    EXPECT_GT(glm::dot(mesh.normals[k], mesh.positions[k]), 0.0f) << what << " vertex " << k;
  }
}

TEST(Subdivision, CubeCountsFollowTheCatmullClarkFormulas) {
  const Cage c = cube();
  ASSERT_FALSE(sweep::check_cage(c).has_value());
  expect_counts(sweep::cage_counts(c), 8, 12, 6, "cage");
  expect_counts(refine(c, 0).counts, 8, 12, 6, "level 0");
  expect_counts(refine(c, 1).counts, 26, 48, 24, "level 1");
  expect_counts(refine(c, 2).counts, 98, 192, 96, "level 2");
  for (int level = 0; level <= 4; ++level) {
    const std::string what = "level " + std::to_string(level);
    const sweep::Subdivided s = refine(c, level);
    const CageCounts predicted = sweep::refined_counts(c, level, kCatmark);
    expect_counts(s.counts, predicted.vertices, predicted.edges, predicted.faces, what);
    EXPECT_EQ(s.counts.vertices - s.counts.edges + s.counts.faces, 2) << what;  // a sphere
    EXPECT_EQ(static_cast<std::int64_t>(s.mesh.vertex_count()), s.counts.vertices) << what;
    EXPECT_EQ(static_cast<std::int64_t>(s.mesh.triangle_count()), 2 * s.counts.faces) << what;
    EXPECT_EQ(sweep::mesh_topology(s.mesh).welded_vertices, s.mesh.vertex_count()) << what;
    expect_closed_outward(s.mesh, what);
    for (const glm::vec3& p : s.mesh.positions) {
      // The limit surface lies inside the cage's hull, and out of the inscribed ball (the
      // corners' limits are at distance sqrt(3) / 2).
      EXPECT_LT(std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}), 1.0f) << what;
      EXPECT_GT(glm::length(p), 0.8f) << what;
    }
  }
}

TEST(Subdivision, CubeCornersGoToHalfwayByHalsteadsLimitMask) {
  // Limit of a vertex of valence n among quads: (n^2 V + 4 sum E + sum F) / (n (n + 5)) with E
  // its edge neighbours and F the opposite corners of its faces. A cube corner (n = 3):
  // (9 V + 4 (V with one sign flipped, three times) + (V with two signs flipped, three times))
  // / 24 = V / 2.
  const Cage c = cube();
  const sweep::Subdivided s = refine(c, 0);
  ASSERT_EQ(s.mesh.vertex_count(), 8u);
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_LE(sweep::test::distance(glm::dvec3(s.mesh.positions[k]), 0.5 * c.points[k]), 1e-6) << k;
    // By symmetry the normal is along the diagonal.
    EXPECT_GT(glm::dot(glm::dvec3(s.mesh.normals[k]), glm::normalize(c.points[k])), 0.99999) << k;
  }
  // And the cage's vertices come first at every level (Far orders a level's vertices as those
  // of the vertices, then of the faces, then of the edges), with the same limit.
  for (const int level : {1, 3}) {
    const sweep::Subdivided finer = refine(c, level);
    for (std::size_t k = 0; k < 8; ++k) {
      EXPECT_LE(sweep::test::distance(glm::dvec3(finer.mesh.positions[k]), 0.5 * c.points[k]), 1e-6)
          << "level " << level << " vertex " << k;
    }
  }
}

TEST(Subdivision, LevelZeroLimitOfANonQuadCatmullClarkCageIsTheLimitOfItsRefinement) {
  // A vertex's limit point does not depend on how many levels were refined first; the cage's
  // vertices stay first at every level (checked on the cube above). Catmull-Clark limit masks
  // are for quads, though (Far applies a face weight to the corner two places on in each face):
  // on triangles at level 0 they give other points.
  for (const auto& [name, cage] : {std::pair{"tetrahedron", tetrahedron()}, std::pair{"cube", cube()}}) {
    const sweep::Subdivided coarse = refine(cage, 0);
    const sweep::Subdivided fine = refine(cage, 4);
    for (std::size_t k = 0; k < cage.points.size(); ++k) {
      EXPECT_LE(sweep::test::distance(glm::dvec3(coarse.mesh.positions[k]), glm::dvec3(fine.mesh.positions[k])), 1e-5)
          << name << " vertex " << k << ": level 0 limit (" << coarse.mesh.positions[k].x << ", "
          << coarse.mesh.positions[k].y << ", " << coarse.mesh.positions[k].z << "), level 4 ("
          << fine.mesh.positions[k].x << ", " << fine.mesh.positions[k].y << ", " << fine.mesh.positions[k].z << ")";
    }
  }
}

/// The periodic bicubic B-spline surface on the same torus points: rows along j (around the
/// axis), columns along i (around the tube), the first three of each repeated at the end, so
/// du x dv faces out like the cage. (s, t) are real grid coordinates: vertex (i, j) is (i, j).
struct TorusSpline {
  int rows = 0, columns = 0;  // of the cage
  std::vector<glm::dvec3> net;

  TorusSpline(const Cage& cage, int cage_rows, int cage_columns) : rows(cage_rows), columns(cage_columns) {
    for (int a = 0; a < columns + 3; ++a) {
      for (int b = 0; b < rows + 3; ++b)
        net.push_back(cage.points[static_cast<std::size_t>((b % rows) * columns + a % columns)]);
    }
  }
  /// Patch and parameters of grid point (s, t): knot (r + 1, c + 1) of the net is patch (r, c) at 0.
  std::tuple<sweep::PatchPoints, double, double> locate(double s, double t) const {
    const double fs = std::floor(s), ft = std::floor(t);
    const int c = (static_cast<int>(fs) - 1 + rows) % rows;
    const int r = (static_cast<int>(ft) - 1 + columns) % columns;
    return {sweep::bspline_patch_points(net, rows + 3, r, c), t - ft, s - fs};
  }
  glm::dvec3 position(double s, double t) const {
    const auto [patch, u, v] = locate(s, t);
    return sweep::evaluate_patch(patch, sweep::PatchBasis::BSpline, u, v).position;
  }
  glm::dvec3 normal(double s, double t) const {
    const auto [patch, u, v] = locate(s, t);
    return sweep::patch_normal(patch, sweep::PatchBasis::BSpline, u, v);
  }
};

TEST(Subdivision, RegularTorusLimitIsThePeriodicBicubicBSpline) {
  const int rows = 6, columns = 8;
  const Cage cage = torus(rows, columns, 42);
  ASSERT_FALSE(sweep::check_cage(cage).has_value());
  const TorusSpline spline(cage, rows, columns);
  // The B-spline net faces the way the cage does.
  const sweep::Mesh net_mesh = sweep::build_bspline_patch(spline.net, columns + 3, rows + 3, 2);
  EXPECT_GT(sweep::signed_volume(net_mesh), 0.0);
  EXPECT_GT(sweep::signed_volume(sweep::cage_mesh(cage)), 0.0);

  // Level 0: the cage's vertices, at the B-spline's knots.
  const sweep::Subdivided level0 = refine(cage, 0);
  ASSERT_EQ(level0.mesh.vertex_count(), cage.points.size());
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      const auto k = static_cast<std::size_t>(i * columns + j);
      EXPECT_LE(sweep::test::distance(glm::dvec3(level0.mesh.positions[k]), spline.position(i, j)), 1e-6)
          << i << " " << j;
      EXPECT_GT(glm::dot(glm::dvec3(level0.mesh.normals[k]), spline.normal(i, j)), 1.0 - 1e-6) << i << " " << j;
    }
  }

  // Level 1: the cage's vertices first, then one per face at the face's centre (i + 1/2, j + 1/2).
  const sweep::Subdivided level1 = refine(cage, 1);
  const std::size_t n = cage.points.size();
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) {
      const auto k = static_cast<std::size_t>(i * columns + j);
      EXPECT_LE(sweep::test::distance(glm::dvec3(level1.mesh.positions[k]), spline.position(i, j)), 1e-6);
      EXPECT_LE(sweep::test::distance(glm::dvec3(level1.mesh.positions[n + k]), spline.position(i + 0.5, j + 0.5)),
                1e-6)
          << "face " << k;
    }
  }

  // Levels 1 and 2: every limit vertex is the B-spline at a point of the grid of step 2^-level,
  // one vertex per grid point, normals included.
  for (const int level : {1, 2}) {
    const sweep::Subdivided s = refine(cage, level);
    const int per = 1 << level;
    ASSERT_EQ(s.mesh.vertex_count(), static_cast<std::size_t>(rows * columns * per * per));
    std::set<std::size_t> matched;
    for (int a = 0; a < rows * per; ++a) {
      for (int b = 0; b < columns * per; ++b) {
        const double si = double(a) / per, tj = double(b) / per;
        const glm::dvec3 expected = spline.position(si, tj);
        std::size_t best = 0;
        double best_distance = 1e300;
        for (std::size_t k = 0; k < s.mesh.vertex_count(); ++k) {
          const double d = sweep::test::distance(glm::dvec3(s.mesh.positions[k]), expected);
          if (d < best_distance) {
            best_distance = d;
            best = k;
          }
        }
        EXPECT_LE(best_distance, 1e-6) << "level " << level << " at (" << si << ", " << tj << ")";
        EXPECT_GT(glm::dot(glm::dvec3(s.mesh.normals[best]), spline.normal(si, tj)), 1.0 - 1e-6);
        matched.insert(best);
      }
    }
    EXPECT_EQ(matched.size(), s.mesh.vertex_count()) << "level " << level;
    const sweep::MeshTopology topology = sweep::mesh_topology(s.mesh);
    EXPECT_EQ(topology.boundary_edges, 0u);
    EXPECT_EQ(topology.non_manifold_edges, 0u);
    EXPECT_GT(sweep::signed_volume(s.mesh), 0.0);
    EXPECT_EQ(s.counts.vertices - s.counts.edges + s.counts.faces, 0);  // a torus
  }
}

TEST(Subdivision, OpenGridKeepsItsCornersAndFollowsTheBoundaryCurve) {
  const int n = 5;
  const Cage grid = bumpy_grid(n);
  ASSERT_FALSE(sweep::check_cage(grid).has_value());
  const auto at = [&](int i, int j) { return grid.points[static_cast<std::size_t>(i * n + j)]; };
  const sweep::Subdivided s = refine(grid, 0);
  ASSERT_EQ(s.mesh.vertex_count(), grid.points.size());
  const auto limit = [&](int i, int j) { return glm::dvec3(s.mesh.positions[static_cast<std::size_t>(i * n + j)]); };
  for (const auto& [i, j] : {std::pair{0, 0}, std::pair{0, n - 1}, std::pair{n - 1, 0}, std::pair{n - 1, n - 1}}) {
    EXPECT_LE(sweep::test::distance(limit(i, j), at(i, j)), 1e-6) << "corner " << i << " " << j;
  }
  for (int k = 1; k + 1 < n; ++k) {
    // Boundary vertices: the cubic B-spline of the boundary polygon, (P- + 4 P + P+) / 6.
    EXPECT_LE(sweep::test::distance(limit(0, k), (at(0, k - 1) + 4.0 * at(0, k) + at(0, k + 1)) / 6.0), 1e-6);
    EXPECT_LE(sweep::test::distance(limit(n - 1, k), (at(n - 1, k - 1) + 4.0 * at(n - 1, k) + at(n - 1, k + 1)) / 6.0),
              1e-6);
    EXPECT_LE(sweep::test::distance(limit(k, 0), (at(k - 1, 0) + 4.0 * at(k, 0) + at(k + 1, 0)) / 6.0), 1e-6);
    EXPECT_LE(sweep::test::distance(limit(k, n - 1), (at(k - 1, n - 1) + 4.0 * at(k, n - 1) + at(k + 1, n - 1)) / 6.0),
              1e-6);
  }
  for (int i = 1; i + 1 < n; ++i) {
    for (int j = 1; j + 1 < n; ++j) {
      // Interior, regular: the bicubic B-spline's knot mask (16 V + 4 sum E + sum F) / 36.
      const glm::dvec3 expected = (16.0 * at(i, j) + 4.0 * (at(i - 1, j) + at(i + 1, j) + at(i, j - 1) + at(i, j + 1)) +
                                   at(i - 1, j - 1) + at(i - 1, j + 1) + at(i + 1, j - 1) + at(i + 1, j + 1)) /
                                  36.0;
      EXPECT_LE(sweep::test::distance(limit(i, j), expected), 1e-6) << i << " " << j;
    }
  }
  for (const glm::vec3& normal : s.mesh.normals) {
    EXPECT_NEAR(glm::length(normal), 1.0f, 1e-5f);
    EXPECT_GT(normal.z, 0.0f);
  }

  // Smooth boundary: the corners are boundary vertices like the others and move.
  const sweep::Subdivided smooth = refine(grid, 0, kCatmark, true);
  const auto smooth_limit = [&](int i, int j) {
    return glm::dvec3(smooth.mesh.positions[static_cast<std::size_t>(i * n + j)]);
  };
  EXPECT_LE(sweep::test::distance(smooth_limit(0, 0), (at(1, 0) + 4.0 * at(0, 0) + at(0, 1)) / 6.0), 1e-6);
  EXPECT_LE(sweep::test::distance(smooth_limit(n - 1, n - 1),
                                  (at(n - 2, n - 1) + 4.0 * at(n - 1, n - 1) + at(n - 1, n - 2)) / 6.0),
            1e-6);
  EXPECT_GT(sweep::test::distance(smooth_limit(0, 0), at(0, 0)), 0.1);
  // Non-corner boundary vertices follow the same rule either way.
  EXPECT_LE(sweep::test::distance(smooth_limit(0, 2), limit(0, 2)), 1e-9);

  // Refined, the boundary has 4 (n - 1) 2^level edges and the rest is manifold.
  for (const int level : {1, 2, 3}) {
    for (const bool smooth_boundary : {false, true}) {
      const sweep::Subdivided r = refine(grid, level, kCatmark, smooth_boundary);
      const sweep::MeshTopology topology = sweep::mesh_topology(r.mesh);
      EXPECT_EQ(topology.boundary_edges, static_cast<std::size_t>(4 * (n - 1) * (1 << level)));
      EXPECT_EQ(topology.non_manifold_edges, 0u);
      EXPECT_EQ(r.counts.vertices - r.counts.edges + r.counts.faces, 1);  // a disc
      const glm::vec3 corner = r.mesh.positions[0];                       // the cage's vertex 0 stays first
      if (smooth_boundary) {
        EXPECT_GT(glm::length(corner), 0.1f);
      } else {
        EXPECT_LE(glm::length(corner - glm::vec3(at(0, 0))), 1e-6f);
      }
    }
  }
}

TEST(Subdivision, LoopOnTheOctahedron) {
  const Cage c = octahedron();
  ASSERT_FALSE(sweep::check_cage(c).has_value());
  expect_counts(sweep::cage_counts(c), 6, 12, 8, "cage");
  CageCounts expected = sweep::cage_counts(c);
  for (int level = 0; level <= 4; ++level) {
    const std::string what = "level " + std::to_string(level);
    const sweep::Subdivided s = refine(c, level, kLoop);
    expect_counts(s.counts, expected.vertices, expected.edges, expected.faces, what);
    const CageCounts predicted = sweep::refined_counts(c, level, kLoop);
    expect_counts(predicted, expected.vertices, expected.edges, expected.faces, what + " predicted");
    EXPECT_EQ(s.counts.vertices - s.counts.edges + s.counts.faces, 2) << what;
    EXPECT_EQ(static_cast<std::int64_t>(s.mesh.vertex_count()), s.counts.vertices) << what;
    EXPECT_EQ(static_cast<std::int64_t>(s.mesh.triangle_count()), s.counts.faces) << what;
    expect_closed_outward(s.mesh, what);
    // Loop's limit of a vertex of valence 4 (Loop 1987): (1 - 4 w) V + w sum of its neighbours,
    // w = 1 / (4 + 3 / (8 beta)), beta = (5/8 - (3/8 + cos(pi/2) / 4)^2) / 4 = 31/256, so w =
    // 31/220; the neighbours of an octahedron vertex sum to 0.
    for (std::size_t k = 0; k < 6; ++k) {
      EXPECT_LE(sweep::test::distance(glm::dvec3(s.mesh.positions[k]), (96.0 / 220.0) * c.points[k]), 1e-6) << what;
      EXPECT_GT(glm::dot(glm::dvec3(s.mesh.normals[k]), c.points[k]), 0.99999) << what;
    }
    expected = {expected.vertices + expected.edges, 2 * expected.edges + 3 * expected.faces, 4 * expected.faces};
  }
}

TEST(Subdivision, LoopOnTheTetrahedron) {
  const Cage c = tetrahedron();
  for (int level = 0; level <= 3; ++level) {
    const sweep::Subdivided s = refine(c, level, kLoop);
    const CageCounts predicted = sweep::refined_counts(c, level, kLoop);
    expect_counts(s.counts, predicted.vertices, predicted.edges, predicted.faces, "level " + std::to_string(level));
    EXPECT_EQ(s.counts.vertices - s.counts.edges + s.counts.faces, 2);
    expect_closed_outward(s.mesh, "tetrahedron level " + std::to_string(level));
  }
}

TEST(Subdivision, RefinedCountsForMixedPolygons) {
  // A pyramid: a square and four triangles. Catmull-Clark: V' = V + E + F, E' = 2 E + corners,
  // F' = corners; after that all quads.
  Cage pyramid;
  pyramid.points = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1.5}};
  pyramid.face_sizes = {4, 3, 3, 3, 3};
  pyramid.face_vertices = {0, 3, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  ASSERT_FALSE(sweep::check_cage(pyramid).has_value());
  expect_counts(sweep::cage_counts(pyramid), 5, 8, 5, "cage");
  expect_counts(sweep::refined_counts(pyramid, 1, kCatmark), 5 + 8 + 5, 2 * 8 + 16, 16, "level 1");
  expect_counts(sweep::refined_counts(pyramid, 2, kCatmark), 18 + 32 + 16, 2 * 32 + 64, 64, "level 2");
  for (int level = 0; level <= 3; ++level) {
    const sweep::Subdivided s = refine(pyramid, level);
    const CageCounts predicted = sweep::refined_counts(pyramid, level, kCatmark);
    expect_counts(s.counts, predicted.vertices, predicted.edges, predicted.faces, "level " + std::to_string(level));
    const sweep::MeshTopology topology = sweep::mesh_topology(s.mesh);
    EXPECT_EQ(topology.boundary_edges, 0u);
    EXPECT_EQ(topology.non_manifold_edges, 0u);
    EXPECT_GT(sweep::signed_volume(s.mesh), 0.0);
  }
}

/// PrimvarRefiner's limit at the last level (fullTopologyInLastLevel, Interpolate, Limit, as
/// far_tutorial_2_1 does), what subdivide returned before it read the limit of a Catmull-Clark
/// level from the level before: positions, and unit dP/du x dP/dv (zero where the tangents are
/// parallel).
struct PrimvarLimit {
  std::vector<glm::dvec3> positions, normals;
};

struct FarPoint {
  glm::dvec3 p{0.0};
  void Clear(void* = nullptr) { p = glm::dvec3(0.0); }
  void AddWithWeight(const FarPoint& source, double weight) { p += weight * source.p; }
};

PrimvarLimit primvar_limit(const Cage& cage, int levels, bool smooth_boundary) {
  using namespace OpenSubdiv;
  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(cage.points.size());
  desc.numFaces = static_cast<int>(cage.face_sizes.size());
  desc.numVertsPerFace = cage.face_sizes.data();
  desc.vertIndicesPerFace = cage.face_vertices.data();
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(smooth_boundary ? Sdc::Options::VTX_BOUNDARY_EDGE_ONLY
                                                  : Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  const std::unique_ptr<Far::TopologyRefiner> refiner(
      Factory::Create(desc, Factory::Options(Sdc::SCHEME_CATMARK, sdc)));
  Far::TopologyRefiner::UniformOptions uniform(levels);
  uniform.fullTopologyInLastLevel = true;
  refiner->RefineUniform(uniform);
  std::vector<FarPoint> points(static_cast<std::size_t>(refiner->GetNumVerticesTotal()));
  for (std::size_t i = 0; i < cage.points.size(); ++i) points[i].p = cage.points[i];
  FarPoint* current = points.data();
  const Far::PrimvarRefinerReal<double> primvar(*refiner);
  for (int level = 1; level <= levels; ++level) {
    FarPoint* next = current + refiner->GetLevel(level - 1).GetNumVertices();
    primvar.Interpolate(level, current, next);
    current = next;
  }
  const auto count = static_cast<std::size_t>(refiner->GetLevel(levels).GetNumVertices());
  std::vector<FarPoint> limit(count), du(count), dv(count);
  FarPoint *positions = limit.data(), *tangents_u = du.data(), *tangents_v = dv.data();
  primvar.Limit(current, positions, tangents_u, tangents_v);
  PrimvarLimit out;
  for (std::size_t i = 0; i < count; ++i) {
    out.positions.push_back(limit[i].p);
    const glm::dvec3 n = glm::cross(du[i].p, dv[i].p);
    const bool parallel = !(glm::length(n) > 1e-9 * glm::length(du[i].p) * glm::length(dv[i].p));
    out.normals.push_back(parallel ? glm::dvec3(0.0) : glm::normalize(n));
  }
  return out;
}

TEST(Subdivision, CatmullClarkLimitIsPrimvarRefinersLimit) {
  // subdivide reads each ring of the last level from the level before it, with Sdc's limit masks
  // (a closed form for regular vertices): the same limit as PrimvarRefiner::Limit over the last
  // level's full topology, at regular, extraordinary (valence 3, 5 and 6), boundary and corner
  // vertices, children of triangles and of a pentagon, and a point in no face.
  Cage pyramid;  // a square and four triangles: the apex has valence 4, its level-1 children 3
  pyramid.points = {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1.5}};
  pyramid.face_sizes = {4, 3, 3, 3, 3};
  pyramid.face_vertices = {0, 3, 2, 1, 0, 1, 4, 1, 2, 4, 2, 3, 4, 3, 0, 4};
  Cage pentagon;  // open: a face-child of valence 5, boundary edges, valence-2 corners
  for (int k = 0; k < 5; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 5.0;
    pentagon.points.emplace_back(std::cos(a), std::sin(a), 0.2 * (k % 2));
  }
  pentagon.face_sizes = {5};
  pentagon.face_vertices = {0, 1, 2, 3, 4};
  Cage fan;  // six triangles around a valence-6 vertex, and a point used by no face
  fan.points = {{0, 0, 0.3}};
  for (int k = 0; k < 6; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 6.0;
    fan.points.emplace_back(std::cos(a), std::sin(a), 0.1 * k);
  }
  fan.points.emplace_back(5, 5, 5);
  for (int k = 0; k < 6; ++k) {
    fan.face_sizes.push_back(3);
    fan.face_vertices.insert(fan.face_vertices.end(), {0, 1 + k, 1 + (k + 1) % 6});
  }
  Cage grid = bumpy_grid(5);
  const std::vector<std::pair<std::string, Cage>> cages = {
      {"torus", torus(6, 8, 7)}, {"cube", cube()}, {"pyramid", pyramid},
      {"pentagon", pentagon},    {"fan", fan},     {"grid", grid}};
  for (const auto& [name, cage] : cages) {
    ASSERT_FALSE(sweep::check_cage(cage).has_value()) << name;
    for (const int level : {1, 2, 3}) {
      for (const bool smooth_boundary : {false, true}) {
        const std::string what = name + " level " + std::to_string(level) + (smooth_boundary ? " smooth" : "");
        const sweep::Subdivided s = refine(cage, level, kCatmark, smooth_boundary);
        const PrimvarLimit expected = primvar_limit(cage, level, smooth_boundary);
        ASSERT_EQ(s.mesh.vertex_count(), expected.positions.size()) << what;
        ASSERT_EQ(s.mesh.normals.size(), expected.positions.size()) << what;
        for (std::size_t k = 0; k < expected.positions.size(); ++k) {
          EXPECT_LE(sweep::test::distance(glm::dvec3(s.mesh.positions[k]), expected.positions[k]), 1e-6)
              << what << " vertex " << k;
          EXPECT_NEAR(glm::length(s.mesh.normals[k]), 1.0f, 1e-5f) << what << " vertex " << k;
          if (expected.normals[k] == glm::dvec3(0.0)) continue;  // the fallback, compared below
          EXPECT_GT(glm::dot(glm::dvec3(s.mesh.normals[k]), expected.normals[k]), 1.0 - 1e-6)
              << what << " vertex " << k;
        }
      }
    }
  }
}

TEST(Subdivision, NormalsAtExtraordinaryAndUnusedPointsFollowTheFaces) {
  // Where the limit tangents say nothing (a point in no face), the normal is the default +z; at
  // an extraordinary vertex it is the tangent plane's, close to its faces' average.
  Cage fan;
  fan.points = {{0, 0, 0}};
  for (int k = 0; k < 5; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 5.0;
    fan.points.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  fan.points.emplace_back(3, 3, 3);  // in no face
  for (int k = 0; k < 5; ++k) {
    fan.face_sizes.push_back(3);
    fan.face_vertices.insert(fan.face_vertices.end(), {0, 1 + k, 1 + (k + 1) % 5});
  }
  for (const int level : {1, 2}) {
    const sweep::Subdivided s = refine(fan, level);
    EXPECT_GT(s.mesh.normals[0].z, 1.0f - 1e-6f) << "level " << level;  // flat, facing +z
    EXPECT_EQ(s.mesh.normals[6], glm::vec3(0, 0, 1)) << "level " << level;
    EXPECT_EQ(s.mesh.positions[6], glm::vec3(3, 3, 3)) << "level " << level;
    for (const glm::vec3& n : s.mesh.normals) EXPECT_GT(n.z, 1.0f - 1e-6f) << "level " << level;
  }
}

Cage triangle_pair() {
  Cage c;
  c.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}};
  return c;
}

std::string problem_of(const Cage& cage) {
  const std::optional<sweep::CageProblem> problem = sweep::check_cage(cage);
  return problem ? "face " + std::to_string(problem->face) + ": " + problem->expected : "none";
}

TEST(Subdivision, CheckCageMessages) {
  Cage c = triangle_pair();
  c.face_sizes = {3, 2};
  c.face_vertices = {0, 1, 2, 2, 3};
  EXPECT_EQ(problem_of(c), "face 1: expected at least 3 vertices in face 2, found 2");

  c.face_sizes = {3, 3};
  c.face_vertices = {0, 1, 2, 0, 2, 5};
  EXPECT_EQ(problem_of(c), "face 1: expected a vertex index from 0 to 4 in face 2, found 5");
  c.face_vertices = {0, 1, -1, 0, 2, 3};
  EXPECT_EQ(problem_of(c), "face 0: expected a vertex index from 0 to 4 in face 1, found -1");

  c.face_vertices = {0, 1, 2, 0, 2, 2};
  EXPECT_EQ(problem_of(c), "face 1: expected distinct vertices in face 2, found vertex 2 twice");

  // Edge 0-2 in three faces (two of them running it each way).
  c.face_sizes = {3, 3, 3};
  c.face_vertices = {0, 1, 2, 0, 2, 3, 2, 0, 4};
  EXPECT_EQ(problem_of(c), "face 2: expected a manifold cage, found edge 2-0 in a third face, 3 (after faces 1 and 2)");

  // Face 2 turns the other way: edge 2-0 runs the same way in both.
  c.face_sizes = {3, 3};
  c.face_vertices = {0, 1, 2, 0, 3, 2};
  EXPECT_EQ(problem_of(c),
            "face 1: expected a manifold cage, found edge 2-0 running the same way in faces 1 and 2 (neighbouring "
            "faces must turn the same way)");

  // A consistent pair, and a vertex shared by two faces only at a point, pass.
  c.face_vertices = {0, 1, 2, 0, 2, 3};
  EXPECT_EQ(problem_of(c), "none");
  c.face_vertices = {0, 1, 2, 0, 3, 4};
  EXPECT_EQ(problem_of(c), "none");
  EXPECT_EQ(problem_of(cube()), "none");
  EXPECT_EQ(problem_of(torus(3, 4, 1)), "none");
}

/// Distinct positions of a mesh, rounded to 1e-6.
std::size_t distinct_positions(const sweep::Mesh& mesh) {
  std::set<std::tuple<long long, long long, long long>> seen;
  for (const glm::vec3& p : mesh.positions) {
    seen.emplace(std::llround(p.x * 1e6), std::llround(p.y * 1e6), std::llround(p.z * 1e6));
  }
  return seen.size();
}

TEST(Subdivision, GridCageOfABSplineNetIsItsQuads) {
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  const int rows = 5, columns = 6, steps = 2;
  std::vector<glm::dvec3> net;
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) net.emplace_back(i + jitter(rng), j + jitter(rng), jitter(rng));
  }
  const sweep::Mesh mesh = sweep::build_bspline_patch(net, rows, columns, steps);
  const Cage cage = sweep::grid_cage(mesh);
  const std::size_t quads = static_cast<std::size_t>((rows - 3) * steps * (columns - 3) * steps);
  EXPECT_EQ(cage.face_sizes, std::vector<int>(quads, 4));
  EXPECT_EQ(cage.points.size(), mesh.vertex_count());
  ASSERT_FALSE(sweep::check_cage(cage).has_value());
  expect_counts(sweep::cage_counts(cage), 5 * 7, 4 * 7 + 5 * 6, 24, "cage");
  // Each quad is two of the mesh's triangles: same corners, same orientation.
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> directed;
  std::size_t corner = 0;
  for (const int size : cage.face_sizes) {
    for (int k = 0; k < size; ++k) {
      const auto a = static_cast<std::uint32_t>(cage.face_vertices[corner + static_cast<std::size_t>(k)]);
      const auto b = static_cast<std::uint32_t>(cage.face_vertices[corner + static_cast<std::size_t>((k + 1) % size)]);
      EXPECT_EQ(cage.points[a], glm::dvec3(mesh.positions[a]));
      ++directed[{a, b}];
    }
    corner += static_cast<std::size_t>(size);
  }
  const auto triangle_edges = sweep::test::directed_edge_uses(mesh);
  for (const auto& [edge, uses] : directed) EXPECT_EQ(triangle_edges.count(edge), 1u);
  for (const glm::vec3& n : sweep::cage_mesh(cage).normals) EXPECT_GT(n.z, 0.0f);  // rows along x, columns along y
}

TEST(Subdivision, GridCageOfAPeriodicTubeIsClosedAroundAndRefinesLikeIt) {
  const int ring = 8, columns = 5, steps = 2;
  std::vector<glm::dvec3> net;
  for (int i = 0; i < ring + 3; ++i) {
    const double angle = 2.0 * std::numbers::pi * (i % ring) / ring;
    for (int j = 0; j < columns; ++j) net.emplace_back(2.0 * std::cos(angle), 2.0 * std::sin(angle), 0.5 * j);
  }
  const sweep::Mesh mesh = sweep::build_bspline_patch(net, ring + 3, columns, steps);
  const Cage cage = sweep::grid_cage(mesh);
  const int around = ring * steps, along = (columns - 3) * steps;
  EXPECT_EQ(cage.face_sizes, std::vector<int>(static_cast<std::size_t>(around * along), 4));
  EXPECT_EQ(cage.points.size(), static_cast<std::size_t>(around * (along + 1)));
  EXPECT_EQ(cage.points.size(), distinct_positions(mesh));
  ASSERT_FALSE(sweep::check_cage(cage).has_value());
  for (const int level : {0, 1, 2}) {
    const sweep::Subdivided s = refine(cage, level);
    const sweep::MeshTopology topology = sweep::mesh_topology(s.mesh);
    EXPECT_EQ(topology.boundary_edges, static_cast<std::size_t>(2 * around * (1 << level))) << level;
    EXPECT_EQ(topology.non_manifold_edges, 0u) << level;
    for (std::size_t k = 0; k < s.mesh.vertex_count(); ++k) {
      const glm::vec3 p = s.mesh.positions[k];
      EXPECT_GT(glm::dot(s.mesh.normals[k], glm::vec3(p.x, p.y, 0.0f)), 0.0f) << level << " vertex " << k;
    }
  }
}

TEST(Subdivision, GridCageOfABezierPatchWithACollapsedRowHasTrianglesAtThePole) {
  // Row 0 of the net is one point: the first row of quads collapses at the pole, and the cage a
  // subd refines (bezier_patch_cage, taken from the sample grid before welding) keeps each as a
  // triangle around the pole ("a quad at a pole becomes a triangle").
  std::vector<glm::dvec3> net;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) net.push_back(i == 0 ? glm::dvec3(0, 0, 1) : glm::dvec3(i, j, 0.1 * i * j));
  }
  const int steps = 4;
  const sweep::Mesh mesh = sweep::build_bezier_patches(net, steps);
  ASSERT_EQ(mesh.vertex_count(), static_cast<std::size_t>(steps * (steps + 1) + 1));
  const Cage cage = sweep::bezier_patch_cage(net, steps);
  ASSERT_FALSE(sweep::check_cage(cage).has_value());
  EXPECT_EQ(cage.points.size(), mesh.vertex_count());
  EXPECT_EQ(std::count(cage.face_sizes.begin(), cage.face_sizes.end(), 4), steps * (steps - 1));
  EXPECT_EQ(std::count(cage.face_sizes.begin(), cage.face_sizes.end(), 3), steps);
  // The pole is a corner of `steps` faces.
  const std::size_t pole = static_cast<std::size_t>(
      std::find(cage.points.begin(), cage.points.end(), glm::dvec3(0, 0, 1)) - cage.points.begin());
  ASSERT_LT(pole, cage.points.size());
  EXPECT_EQ(std::count(cage.face_vertices.begin(), cage.face_vertices.end(), static_cast<int>(pole)), steps);

  // The teapot: 32 patches of 8 x 8 quads, the 4 lid and 4 bottom patches with a collapsed row.
  const sweep::Document doc = sweep::test::load_starter("teapot.swp");
  const sweep::Scene scene = sweep::evaluate_document(doc);
  const Cage teapot = sweep::bezier_patch_cage(doc.objects[0].as<sweep::PointsPart>().points,
                                               doc.objects[0].as<sweep::StepsPart>().steps);
  EXPECT_EQ(teapot.points.size(), scene.objects[0].mesh.vertex_count());
  EXPECT_FALSE(sweep::check_cage(teapot).has_value());
  EXPECT_EQ(std::count(teapot.face_sizes.begin(), teapot.face_sizes.end(), 3), 8 * 8);
  EXPECT_EQ(std::count(teapot.face_sizes.begin(), teapot.face_sizes.end(), 4), 32 * 64 - 8 * 8);
}

sweep::Scene scene_of(const std::string& text, sweep::Document& doc) {
  doc = sweep::io::parse_swp(text, "test.swp");
  return sweep::evaluate_document(doc);
}

TEST(Subdivision, GridCageOfASurfaceOfRevolutionWeldsItsSeam) {
  sweep::Document doc;
  const sweep::Scene scene = scene_of("bsp2 p 4 5 [1 0] [1.5 1] [1 2] [1.2 3] [1 4]\nsrev s 16 p\nsubd d 2 s\n", doc);
  const sweep::Mesh& mesh = scene.objects[1].mesh;
  const Cage cage = sweep::grid_cage(mesh);
  // 2 pieces of 4 steps: 9 profile samples, 16 turns.
  EXPECT_EQ(cage.points.size(), distinct_positions(mesh));
  EXPECT_EQ(cage.points.size(), 16u * 9u);
  EXPECT_EQ(cage.face_sizes, std::vector<int>(16u * 8u, 4));
  ASSERT_FALSE(sweep::check_cage(cage).has_value());
  // The subd refines that cage: a tube open at both ends.
  const sweep::Mesh& refined = scene.objects[2].mesh;
  EXPECT_EQ(refined.vertex_count(), static_cast<std::size_t>(sweep::refined_counts(cage, 2, kCatmark).vertices));
  const sweep::MeshTopology topology = sweep::mesh_topology(refined);
  EXPECT_EQ(topology.boundary_edges, 2u * 16u * 4u);
  EXPECT_EQ(topology.non_manifold_edges, 0u);
}

TEST(Subdivision, GridCageOfASurfaceOfRevolutionThroughTheAxisHasTrianglesAtThePoles) {
  sweep::Document doc;
  const sweep::Scene scene = scene_of("bez2 p 4 4 [0 -1] [1.5 -1] [1.5 1] [0 1]\nsrev s 12 p\nsubd d 2 s\n", doc);
  const Cage cage = sweep::grid_cage(scene.objects[1].mesh);
  // 5 profile samples: 3 rings of 12 and two poles; 12 triangles at each pole, 24 quads between.
  EXPECT_EQ(cage.points.size(), 3u * 12u + 2u);
  EXPECT_EQ(std::count(cage.face_sizes.begin(), cage.face_sizes.end(), 3), 24);
  EXPECT_EQ(std::count(cage.face_sizes.begin(), cage.face_sizes.end(), 4), 24);
  EXPECT_EQ(cage.face_sizes.size(), 48u);
  ASSERT_FALSE(sweep::check_cage(cage).has_value());
  expect_counts(sweep::cage_counts(cage), 38, 36 + 36 + 12, 48, "cage");  // Euler 2
  const sweep::Mesh& refined = scene.objects[2].mesh;
  expect_closed_outward(refined, "subd of a closed srev");
}

const std::string kBox =
    "mesh box 8 6\n[-1 -1 -1] [1 -1 -1] [1 1 -1] [-1 1 -1] [-1 -1 1] [1 -1 1] [1 1 1] [-1 1 1]\n"
    "[0 3 2 1] [4 5 6 7] [0 1 5 4] [3 7 6 2] [0 4 7 3] [1 2 6 5]\n";

TEST(Subdivision, SubdOfAMeshInADocumentIsSubdivideOfItsCage) {
  sweep::Document doc;
  const sweep::Scene scene = scene_of(kBox + "subd s 2 box\nsubd l 1 box smooth-boundary\n", doc);
  EXPECT_EQ(sweep::cage_of(doc.objects[0]).points, cube().points);
  EXPECT_EQ(sweep::cage_of(doc.objects[0]).face_vertices, cube().face_vertices);
  const sweep::Mesh& box = scene.objects[0].mesh;  // the cage drawn: 6 quads, 12 triangles
  EXPECT_EQ(box.triangle_count(), 12u);
  EXPECT_EQ(box.polygon_sizes, std::vector<std::uint32_t>(6, 4));
  expect_closed_outward(box, "cage mesh");
  const sweep::Mesh& s = scene.objects[1].mesh;
  const sweep::Mesh direct = refine(cube(), 2).mesh;
  EXPECT_EQ(s.positions, direct.positions);
  EXPECT_EQ(s.indices, direct.indices);
  EXPECT_EQ(s.normals, direct.normals);
  // A closed cage has no boundary: smooth-boundary changes nothing.
  EXPECT_EQ(scene.objects[2].mesh.positions, refine(cube(), 1).mesh.positions);
}

TEST(Subdivision, LoopOverALoopSubdRefinesItsTriangles) {
  sweep::Document doc;
  const sweep::Scene scene = scene_of(
      "mesh tet 4 4 [1 1 1] [1 -1 -1] [-1 1 -1] [-1 -1 1] [0 1 2] [0 3 1] [0 2 3] [1 3 2]\n"
      "subd s 2 tet loop\nsubd t 1 s loop\n",
      doc);
  const sweep::Mesh& s = scene.objects[1].mesh;
  const Cage triangles = sweep::grid_cage(s);
  EXPECT_EQ(triangles.face_sizes, std::vector<int>(s.triangle_count(), 3));
  const sweep::Mesh& t = scene.objects[2].mesh;
  EXPECT_EQ(static_cast<std::int64_t>(t.vertex_count()), sweep::refined_counts(triangles, 1, kLoop).vertices);
  expect_closed_outward(t, "loop of a loop subd");
}

TEST(Subdivision, LoopOverACatmullClarkSubdRefinesItsTriangles) {
  // The parser takes `loop` over any subd: Loop takes the source's triangles as they are
  // (grid_cage without quads), never pairs of them made into quads, which Far would refuse.
  sweep::Document doc;
  const sweep::Scene scene = scene_of(kBox + "subd s 1 box\nsubd t 1 s loop\n", doc);
  const sweep::Mesh& s = scene.objects[1].mesh;
  ASSERT_EQ(s.triangle_count(), 48u);
  const Cage cage = sweep::grid_cage(s, false);
  EXPECT_EQ(cage.face_sizes, std::vector<int>(48, 3)) << "grid_cage made quads of a subd's triangles";
  // For Catmull-Clark the subd's quads come back as quads.
  EXPECT_EQ(sweep::grid_cage(s).face_sizes, std::vector<int>(24, 4));
  const sweep::Mesh& t = scene.objects[2].mesh;
  EXPECT_EQ(t.vertex_count(), 26u + 72u) << "Loop over the 48 triangles: V + E = 26 + 72";
  if (t.vertex_count() > 0) expect_closed_outward(t, "loop of a Catmull-Clark subd");
}

TEST(Subdivision, CageEdgeLinesDrawEachEdgeOnce) {
  const Cage c = cube();
  const std::vector<glm::vec3> lines = sweep::cage_edge_lines(c);
  ASSERT_EQ(lines.size(), 24u);
  std::set<std::pair<std::tuple<float, float, float>, std::tuple<float, float, float>>> edges;
  for (std::size_t k = 0; k < lines.size(); k += 2) {
    EXPECT_FLOAT_EQ(glm::length(lines[k] - lines[k + 1]), 2.0f);  // cube edges, no diagonals
    auto a = std::tuple{lines[k].x, lines[k].y, lines[k].z};
    auto b = std::tuple{lines[k + 1].x, lines[k + 1].y, lines[k + 1].z};
    if (b < a) std::swap(a, b);
    edges.emplace(a, b);
  }
  EXPECT_EQ(edges.size(), 12u);
}

TEST(Subdivision, CageMeshNormalsAreTheFacesAverage) {
  const sweep::Mesh mesh = sweep::cage_mesh(cube());
  ASSERT_EQ(mesh.vertex_count(), 8u);
  for (std::size_t k = 0; k < 8; ++k) {
    // Three faces of equal area: the normal is along the diagonal.
    EXPECT_GT(glm::dot(glm::dvec3(mesh.normals[k]), glm::normalize(cube().points[k])), 0.99999);
  }
  EXPECT_EQ(mesh.polygon_indices.size(), 24u);
  EXPECT_EQ(std::vector<int>(mesh.polygon_indices.begin(), mesh.polygon_indices.end()), cube().face_vertices);
  // A pentagon becomes a fan of 3 triangles, its polygon kept.
  Cage pentagon;
  for (int k = 0; k < 5; ++k) {
    const double a = 2.0 * std::numbers::pi * k / 5;
    pentagon.points.emplace_back(std::cos(a), std::sin(a), 0.0);
  }
  pentagon.face_sizes = {5};
  pentagon.face_vertices = {0, 1, 2, 3, 4};
  const sweep::Mesh fan = sweep::cage_mesh(pentagon);
  EXPECT_EQ(fan.triangle_count(), 3u);
  EXPECT_EQ(fan.polygon_sizes, std::vector<std::uint32_t>{5});
  for (const glm::vec3& n : fan.normals) EXPECT_NEAR(n.z, 1.0f, 1e-6f);
}

}  // namespace
