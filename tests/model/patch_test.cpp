// Bicubic patches (core/patch.hpp): Bezier corner interpolation and derivatives checked against
// independent formulas, welding of shared and collapsed edges, B-spline to Bezier conversion,
// periodic B-spline tubes that close, Newell's teapot facing out, and normals at collapsed edges.
#include "geometry/surfaces/patch.hpp"
#include "geometry/mesh/mesh_topology.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/evaluation/scene.hpp"

#include "support/core_test_support.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace {

using sweep::PatchBasis;
using sweep::PatchPoints;

PatchPoints random_net(std::mt19937& rng, double scale = 1.0) {
  std::uniform_real_distribution<double> coordinate(-scale, scale);
  PatchPoints p;
  for (glm::dvec3& q : p) q = {coordinate(rng), coordinate(rng), coordinate(rng)};
  return p;
}

/// A net over the unit square (x from the row, y from the column) with random heights and
/// jitter: a patch whose normal is never degenerate, facing +z (x cross y).
PatchPoints bumpy_net(std::mt19937& rng, glm::dvec3 origin = glm::dvec3(0.0)) {
  std::uniform_real_distribution<double> jitter(-0.05, 0.05);
  std::uniform_real_distribution<double> height(-0.3, 0.3);
  PatchPoints p;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      p[static_cast<std::size_t>(4 * i + j)] =
          origin + glm::dvec3(i / 3.0 + jitter(rng), j / 3.0 + jitter(rng), height(rng));
    }
  }
  return p;
}

double extent(const PatchPoints& p) {
  glm::dvec3 lo = p[0], hi = p[0];
  for (const glm::dvec3& q : p) {
    lo = glm::min(lo, q);
    hi = glm::max(hi, q);
  }
  return glm::length(hi - lo);
}

/// The tensor-product Bezier patch by de Casteljau's algorithm on each row, then on the column
/// of results: independent of evaluate_patch's basis functions.
glm::dvec3 de_casteljau_patch(const PatchPoints& p, double u, double v) {
  std::vector<glm::dvec3> column;
  for (std::size_t i = 0; i < 4; ++i) {
    const std::vector<glm::dvec3> row{p[4 * i], p[4 * i + 1], p[4 * i + 2], p[4 * i + 3]};
    column.push_back(sweep::test::direct_bezier(row, 0, v));
  }
  return sweep::test::direct_bezier(column, 0, u);
}

/// The uniform bicubic B-spline patch (r, c) of a rows x columns net, from the textbook blending
/// functions (independent of bspline_patch_points and evaluate_patch).
glm::dvec3 direct_bspline_patch(const std::vector<glm::dvec3>& net, int columns, int r, int c, double u, double v) {
  const glm::dvec4 wu = sweep::test::bspline_weights(u);
  const glm::dvec4 wv = sweep::test::bspline_weights(v);
  glm::dvec3 sum(0.0);
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) sum += wu[i] * wv[j] * net[static_cast<std::size_t>((r + i) * columns + c + j)];
  }
  return sum;
}

std::vector<glm::dvec3> concat(const PatchPoints& a, const PatchPoints& b) {
  std::vector<glm::dvec3> out(a.begin(), a.end());
  out.insert(out.end(), b.begin(), b.end());
  return out;
}

/// Index of the mesh vertex nearest to p, and its distance.
std::pair<std::size_t, double> nearest_vertex(const sweep::Mesh& mesh, const glm::dvec3& p) {
  std::size_t best = 0;
  double best_distance = 1e300;
  for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
    const double d = glm::length(glm::dvec3(mesh.positions[k]) - p);
    if (d < best_distance) {
      best_distance = d;
      best = k;
    }
  }
  return {best, best_distance};
}

RC_GTEST_PROP(PatchProperty, BezierPatchInterpolatesItsFourCornerPoints, ()) {
  PatchPoints p;
  for (glm::dvec3& q : p) {
    q = {*rc::gen::inRange(-1000, 1001) / 8.0, *rc::gen::inRange(-1000, 1001) / 8.0,
         *rc::gen::inRange(-1000, 1001) / 8.0};
  }
  const double tolerance = 1e-12 * (extent(p) + 1.0);
  const std::array<std::array<double, 2>, 4> corners{{{0.0, 0.0}, {0.0, 1.0}, {1.0, 0.0}, {1.0, 1.0}}};
  const std::array<std::size_t, 4> index{0, 3, 12, 15};  // P00, P03, P30, P33
  for (std::size_t k = 0; k < 4; ++k) {
    const glm::dvec3 at = sweep::evaluate_patch(p, PatchBasis::Bezier, corners[k][0], corners[k][1]).position;
    RC_ASSERT(glm::length(at - p[index[k]]) <= tolerance);
  }
  // And everywhere else it is the tensor product of Bezier curves.
  const double u = *rc::gen::inRange(0, 1001) / 1000.0;
  const double v = *rc::gen::inRange(0, 1001) / 1000.0;
  RC_ASSERT(glm::length(sweep::evaluate_patch(p, PatchBasis::Bezier, u, v).position - de_casteljau_patch(p, u, v)) <=
            1e-12 * (extent(p) + 1.0));
}

TEST(Patch, BoundaryCurvesAreTheBezierCurvesOfTheOuterRowsAndColumns) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 20; ++trial) {
    const PatchPoints p = random_net(rng, 5.0);
    const std::vector<glm::dvec3> row0{p[0], p[1], p[2], p[3]};
    const std::vector<glm::dvec3> row3{p[12], p[13], p[14], p[15]};
    const std::vector<glm::dvec3> column0{p[0], p[4], p[8], p[12]};
    const std::vector<glm::dvec3> column3{p[3], p[7], p[11], p[15]};
    for (const double t : {0.0, 0.1, 0.37, 0.5, 0.9, 1.0}) {
      const double tolerance = 1e-12 * extent(p);
      EXPECT_LE(sweep::test::distance(sweep::evaluate_patch(p, PatchBasis::Bezier, 0.0, t).position,
                                      sweep::test::direct_bezier(row0, 0, t)),
                tolerance);
      EXPECT_LE(sweep::test::distance(sweep::evaluate_patch(p, PatchBasis::Bezier, 1.0, t).position,
                                      sweep::test::direct_bezier(row3, 0, t)),
                tolerance);
      EXPECT_LE(sweep::test::distance(sweep::evaluate_patch(p, PatchBasis::Bezier, t, 0.0).position,
                                      sweep::test::direct_bezier(column0, 0, t)),
                tolerance);
      EXPECT_LE(sweep::test::distance(sweep::evaluate_patch(p, PatchBasis::Bezier, t, 1.0).position,
                                      sweep::test::direct_bezier(column3, 0, t)),
                tolerance);
    }
  }
}

TEST(Patch, PartialDerivativesMatchCentralDifferences) {
  std::mt19937 rng(2024);
  std::uniform_real_distribution<double> parameter(0.02, 0.98);
  const double h = 1e-5;
  for (const PatchBasis basis : {PatchBasis::Bezier, PatchBasis::BSpline}) {
    for (int trial = 0; trial < 50; ++trial) {
      const PatchPoints p = random_net(rng, 3.0);
      const double u = parameter(rng);
      const double v = parameter(rng);
      const sweep::PatchSample s = sweep::evaluate_patch(p, basis, u, v);
      const glm::dvec3 du =
          (sweep::evaluate_patch(p, basis, u + h, v).position - sweep::evaluate_patch(p, basis, u - h, v).position) /
          (2.0 * h);
      const glm::dvec3 dv =
          (sweep::evaluate_patch(p, basis, u, v + h).position - sweep::evaluate_patch(p, basis, u, v - h).position) /
          (2.0 * h);
      // Central differences of a cubic: error h^2 / 6 * |P'''| plus rounding ~ 1e-16 / h.
      const double tolerance = 1e-7 * extent(p);
      EXPECT_LE(glm::length(s.du - du), tolerance) << "trial " << trial << " u " << u << " v " << v;
      EXPECT_LE(glm::length(s.dv - dv), tolerance) << "trial " << trial << " u " << u << " v " << v;
      // Also at the parameter square's corners, one-sided (the derivative of a cubic there).
      const glm::dvec3 du0 = (-3.0 * sweep::evaluate_patch(p, basis, 0.0, v).position +
                              4.0 * sweep::evaluate_patch(p, basis, h, v).position -
                              sweep::evaluate_patch(p, basis, 2.0 * h, v).position) /
                             (2.0 * h);
      EXPECT_LE(glm::length(sweep::evaluate_patch(p, basis, 0.0, v).du - du0), 1e-6 * extent(p));
    }
  }
}

TEST(Patch, BezierDerivativesAtCornersAreThreeTimesTheNetEdges) {
  // dP/du(0,0) = 3 (P10 - P00), dP/dv(0,0) = 3 (P01 - P00): Farin, ch. 16.
  std::mt19937 rng(5);
  for (int trial = 0; trial < 10; ++trial) {
    const PatchPoints p = random_net(rng);
    const sweep::PatchSample s = sweep::evaluate_patch(p, PatchBasis::Bezier, 0.0, 0.0);
    EXPECT_LE(glm::length(s.du - 3.0 * (p[4] - p[0])), 1e-13);
    EXPECT_LE(glm::length(s.dv - 3.0 * (p[1] - p[0])), 1e-13);
    const sweep::PatchSample e = sweep::evaluate_patch(p, PatchBasis::Bezier, 1.0, 1.0);
    EXPECT_LE(glm::length(e.du - 3.0 * (p[15] - p[11])), 1e-13);
    EXPECT_LE(glm::length(e.dv - 3.0 * (p[15] - p[14])), 1e-13);
  }
}

/// Two patches glued along `shared_row` of b (0 or 3): checks the weld and the shared samples.
void expect_welded_pair(const PatchPoints& a, const PatchPoints& b, int steps, bool reversed, const char* what) {
  const sweep::Mesh mesh = sweep::build_bezier_patches(concat(a, b), steps);
  const auto side = static_cast<std::size_t>(steps + 1);
  EXPECT_EQ(mesh.vertex_count(), 2 * side * side - side) << what;
  EXPECT_EQ(mesh.triangle_count(), static_cast<std::size_t>(4 * steps * steps)) << what;
  // The edge of a at u = 1 and that of b: one mesh vertex per sample, at both evaluations.
  for (int j = 0; j <= steps; ++j) {
    const double v = double(j) / steps;
    const glm::dvec3 on_a = sweep::evaluate_patch(a, PatchBasis::Bezier, 1.0, v).position;
    const glm::dvec3 on_b = reversed ? sweep::evaluate_patch(b, PatchBasis::Bezier, 1.0, 1.0 - v).position
                                     : sweep::evaluate_patch(b, PatchBasis::Bezier, 0.0, v).position;
    if (!reversed) {
      EXPECT_EQ(on_a, on_b) << what << " sample " << j;  // the same four points, the same weights
    } else {
      EXPECT_LE(glm::length(on_a - on_b), 1e-14) << what << " sample " << j;
    }
    const auto [index, gap] = nearest_vertex(mesh, on_a);
    EXPECT_LE(gap, 1e-6) << what << " sample " << j;
    EXPECT_EQ(std::count(mesh.positions.begin(), mesh.positions.end(), mesh.positions[index]), 1) << what;
  }
  const sweep::MeshTopology topology = sweep::mesh_topology(mesh);
  EXPECT_EQ(topology.welded_vertices, mesh.vertex_count()) << what;
  EXPECT_EQ(topology.boundary_edges, static_cast<std::size_t>(6 * steps)) << what;
  EXPECT_EQ(topology.non_manifold_edges, 0u) << what;
  for (const glm::vec3& n : mesh.normals) {
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f) << what;
    EXPECT_GT(n.z, 0.0f) << what;  // both nets face +z
  }
}

TEST(Patch, SharedEdgeOfTwoBezierPatchesIsWelded) {
  std::mt19937 rng(7);
  for (int trial = 0; trial < 5; ++trial) {
    const PatchPoints a = bumpy_net(rng);
    PatchPoints b = bumpy_net(rng, glm::dvec3(1.0, 0.0, 0.0));
    for (std::size_t j = 0; j < 4; ++j) b[j] = a[12 + j];  // b's first row is a's last
    // C1 across the edge is not needed for the weld, only the shared row.
    for (const int steps : {1, 4, 7}) expect_welded_pair(a, b, steps, false, "same direction");
  }
}

TEST(Patch, SharedEdgeRunningTheOtherWayIsWeldedToo) {
  // b turned half a turn (rows and points in a row both reversed): it still faces +z, and its
  // last row is a's last row backwards, so the welded edge runs the other way in b.
  std::mt19937 rng(8);
  for (int trial = 0; trial < 5; ++trial) {
    const PatchPoints a = bumpy_net(rng);
    const PatchPoints straight = bumpy_net(rng, glm::dvec3(1.0, 0.0, 0.0));
    PatchPoints b;
    for (std::size_t i = 0; i < 4; ++i) {
      for (std::size_t j = 0; j < 4; ++j) b[4 * i + j] = straight[4 * (3 - i) + (3 - j)];
    }
    for (std::size_t j = 0; j < 4; ++j) b[12 + j] = a[12 + (3 - j)];
    for (const int steps : {1, 4, 7}) expect_welded_pair(a, b, steps, true, "reversed");
  }
}

TEST(Patch, MirroredNeighbourIsWeldedButFacesTheOtherWay) {
  // The shared row reversed by mirroring the second patch's points in each row: the edge still
  // welds (2 (s+1)^2 - (s+1) vertices), but that patch faces -z, so the shared edges run the same
  // way in both (non-manifold), as the header warns for data in the other order.
  std::mt19937 rng(9);
  const PatchPoints a = bumpy_net(rng);
  PatchPoints b = bumpy_net(rng, glm::dvec3(1.0, 0.0, 0.0));
  for (std::size_t i = 0; i < 4; ++i)
    std::reverse(b.begin() + 4 * static_cast<std::ptrdiff_t>(i), b.begin() + 4 * static_cast<std::ptrdiff_t>(i + 1));
  for (std::size_t j = 0; j < 4; ++j) b[j] = a[12 + (3 - j)];
  const int steps = 5;
  const sweep::Mesh mesh = sweep::build_bezier_patches(concat(a, b), steps);
  EXPECT_EQ(mesh.vertex_count(), static_cast<std::size_t>(2 * 36 - 6));
  const sweep::MeshTopology topology = sweep::mesh_topology(mesh);
  EXPECT_EQ(topology.non_manifold_edges, static_cast<std::size_t>(steps));
  EXPECT_EQ(topology.boundary_edges, static_cast<std::size_t>(6 * steps));
}

TEST(Patch, BSplineToBezierIsTheSameSurface) {
  std::mt19937 rng(99);
  std::uniform_real_distribution<double> parameter(0.0, 1.0);
  for (int trial = 0; trial < 50; ++trial) {
    const PatchPoints b = random_net(rng, 10.0);
    const PatchPoints z = sweep::bspline_to_bezier(b);
    const double tolerance = 1e-12 * extent(b);
    for (int k = 0; k < 10; ++k) {
      const double u = k == 0 ? 0.0 : k == 1 ? 1.0 : parameter(rng);
      const double v = k == 0 ? 1.0 : k == 1 ? 0.0 : parameter(rng);
      const sweep::PatchSample s = sweep::evaluate_patch(b, PatchBasis::BSpline, u, v);
      const sweep::PatchSample t = sweep::evaluate_patch(z, PatchBasis::Bezier, u, v);
      EXPECT_LE(glm::length(s.position - t.position), tolerance) << trial;
      EXPECT_LE(glm::length(s.du - t.du), 10.0 * tolerance) << trial;
      EXPECT_LE(glm::length(s.dv - t.dv), 10.0 * tolerance) << trial;
      // And it is the textbook B-spline.
      EXPECT_LE(
          glm::length(s.position - direct_bspline_patch(std::vector<glm::dvec3>(b.begin(), b.end()), 4, 0, 0, u, v)),
          tolerance);
    }
  }
}

TEST(Patch, BSplineNetMeshSamplesEachPatchOnItsGrid) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  const int rows = 5, columns = 6, steps = 4;
  std::vector<glm::dvec3> net;
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < columns; ++j) net.emplace_back(i + jitter(rng), j + jitter(rng), 2.0 * jitter(rng));
  }
  const sweep::Mesh mesh = sweep::build_bspline_patch(net, rows, columns, steps);
  ASSERT_EQ(static_cast<std::int64_t>(mesh.vertex_count()), sweep::bspline_patch_vertex_count(rows, columns, steps));
  EXPECT_EQ(mesh.vertex_count(), static_cast<std::size_t>((2 * steps + 1) * (3 * steps + 1)));
  EXPECT_EQ(mesh.triangle_count(), static_cast<std::size_t>(2 * (2 * steps) * (3 * steps)));
  for (int r = 0; r < rows - 3; ++r) {
    for (int c = 0; c < columns - 3; ++c) {
      const PatchPoints patch = sweep::bspline_patch_points(net, columns, r, c);
      for (std::size_t k = 0; k < 16; ++k) {
        EXPECT_EQ(patch[k],
                  net[static_cast<std::size_t>((r + static_cast<int>(k / 4)) * columns + c + static_cast<int>(k % 4))]);
      }
      for (int a = 0; a <= steps; ++a) {
        for (int b = 0; b <= steps; ++b) {
          const double u = double(a) / steps, v = double(b) / steps;
          const glm::dvec3 expected = sweep::evaluate_patch(patch, PatchBasis::BSpline, u, v).position;
          EXPECT_LE(glm::length(expected - direct_bspline_patch(net, columns, r, c, u, v)), 1e-12);
          const auto [index, gap] = nearest_vertex(mesh, expected);
          EXPECT_LE(gap, 1e-5) << r << " " << c << " " << a << " " << b;  // float positions
          const glm::dvec3 normal = sweep::patch_normal(patch, PatchBasis::BSpline, u, v);
          EXPECT_GT(glm::dot(glm::dvec3(mesh.normals[index]), normal), 0.9999);
        }
      }
    }
  }
  const sweep::MeshTopology topology = sweep::mesh_topology(mesh);
  EXPECT_EQ(topology.boundary_edges, static_cast<std::size_t>(2 * (2 * steps + 3 * steps)));
  EXPECT_EQ(topology.non_manifold_edges, 0u);
}

TEST(Patch, PeriodicBSplineTubeClosesAroundAndStaysOpenAtTheEnds) {
  // Rows around a circle of radius 2 (8 distinct rings, the first 3 repeated at the end),
  // points in a row along +z: u turns counterclockwise seen from +z, v climbs, so du x dv
  // points away from the axis.
  const int ring = 8, rows = ring + 3, columns = 5, steps = 4;
  std::vector<glm::dvec3> net;
  for (int i = 0; i < rows; ++i) {
    const double angle = 2.0 * std::numbers::pi * (i % ring) / ring;
    for (int j = 0; j < columns; ++j) net.emplace_back(2.0 * std::cos(angle), 2.0 * std::sin(angle), 0.5 * j);
  }
  const sweep::Mesh mesh = sweep::build_bspline_patch(net, rows, columns, steps);
  const std::size_t segments = static_cast<std::size_t>(ring * steps);  // around
  const std::size_t rings = static_cast<std::size_t>((columns - 3) * steps + 1);
  EXPECT_EQ(mesh.vertex_count(), segments * rings);
  const sweep::MeshTopology topology = sweep::mesh_topology(mesh);
  EXPECT_EQ(topology.boundary_edges, 2 * segments);
  EXPECT_EQ(topology.non_manifold_edges, 0u);
  EXPECT_EQ(topology.welded_vertices, mesh.vertex_count());
  for (std::size_t k = 0; k < mesh.vertex_count(); ++k) {
    const glm::dvec3 p(mesh.positions[k]);
    const glm::dvec3 radial = glm::normalize(glm::dvec3(p.x, p.y, 0.0));
    EXPECT_NEAR(glm::length(mesh.normals[k]), 1.0f, 1e-5f);
    EXPECT_GT(glm::dot(glm::dvec3(mesh.normals[k]), radial), 0.999) << k;  // a straight tube: radial
  }
}

TEST(Patch, BSplineNetPeriodicInBothDirectionsIsAClosedTorus) {
  // Rows around the axis (+z), points in a row around the tube, both wrapped by 3: u turns
  // counterclockwise about +z, v turns about the tube so that du x dv points out of it.
  const int around = 8, tube = 6, steps = 3;
  std::vector<glm::dvec3> net;
  for (int i = 0; i < around + 3; ++i) {
    const double theta = 2.0 * std::numbers::pi * (i % around) / around;
    for (int j = 0; j < tube + 3; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j % tube) / tube;
      const double radius = 3.0 + std::cos(phi);
      net.emplace_back(radius * std::cos(theta), radius * std::sin(theta), std::sin(phi));
    }
  }
  const sweep::Mesh mesh = sweep::build_bspline_patch(net, around + 3, tube + 3, steps);
  EXPECT_EQ(mesh.vertex_count(), static_cast<std::size_t>(around * steps * tube * steps));
  const sweep::MeshTopology topology = sweep::mesh_topology(mesh);
  EXPECT_EQ(topology.boundary_edges, 0u);
  EXPECT_EQ(topology.non_manifold_edges, 0u);
  EXPECT_GT(sweep::signed_volume(mesh), 0.0);
  for (std::size_t k = 0; k < mesh.vertex_count(); ++k) {
    // Away from the tube's centre line (the circle of radius 3 in the xy-plane), within the
    // tilt of a cross-section that is a rounded hexagon rather than a circle.
    const glm::dvec3 p(mesh.positions[k]);
    const glm::dvec3 centre = 3.0 * glm::normalize(glm::dvec3(p.x, p.y, 0.0));
    EXPECT_GT(glm::dot(glm::dvec3(mesh.normals[k]), glm::normalize(p - centre)), 0.8) << k;
  }
}

TEST(Patch, TeapotFacesOutEverywhere) {
  const sweep::Document doc = sweep::test::load_starter("teapot.swp");
  ASSERT_EQ(doc.objects.size(), 1u);
  const sweep::Object& teapot = doc.objects[0];
  ASSERT_EQ(teapot.kind(), sweep::ObjectKind::BezierPatch);
  EXPECT_EQ(teapot.as<sweep::PointsPart>().points.size(), 512u);  // 32 patches
  const sweep::Scene scene = sweep::evaluate_document(doc);
  const sweep::Mesh& mesh = scene.objects[0].mesh;
  ASSERT_GT(mesh.triangle_count(), 0u);
  for (const glm::vec3& n : mesh.normals) {
    ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
    EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
  }
  std::size_t disagree = 0, opposite = 0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a(mesh.positions[mesh.indices[t]]), b(mesh.positions[mesh.indices[t + 1]]),
        c(mesh.positions[mesh.indices[t + 2]]);
    const glm::dvec3 g = glm::cross(b - a, c - a);
    const glm::dvec3 m = glm::dvec3(mesh.normals[mesh.indices[t]]) + glm::dvec3(mesh.normals[mesh.indices[t + 1]]) +
                         glm::dvec3(mesh.normals[mesh.indices[t + 2]]);
    if (glm::length(g) == 0.0) continue;
    const double cosine = glm::dot(g, m) / (glm::length(g) * glm::length(m));
    if (cosine <= 0.0) ++disagree;
    if (cosine < -0.5) ++opposite;
  }
  const double fraction = double(disagree) / double(mesh.triangle_count());
  std::cout << "teapot: " << disagree << " of " << mesh.triangle_count()
            << " triangles disagree with their vertex normals (fraction " << fraction << ")\n";
  RecordProperty("disagreeing_triangles", std::to_string(disagree));
  EXPECT_LT(fraction, 0.005);
  EXPECT_EQ(opposite, 0u);
  EXPECT_GT(sweep::signed_volume(mesh), 0.0);

  // The lid's knob top (y = 3.15) and the bottom's centre (y = 0), both on the axis.
  int top = 0, bottom = 0;
  for (std::size_t k = 0; k < mesh.vertex_count(); ++k) {
    const glm::vec3 p = mesh.positions[k];
    if (std::abs(p.x) >= 1e-9f || std::abs(p.z) >= 1e-9f) continue;
    if (p.y > 3.0f) {
      ++top;
      EXPECT_GT(mesh.normals[k].y, 0.999f) << "lid pole at y " << p.y;
    } else {
      ++bottom;
      EXPECT_NEAR(p.y, 0.0f, 1e-6f);
      EXPECT_LT(mesh.normals[k].y, -0.999f) << "bottom centre";
    }
  }
  EXPECT_EQ(top, 1);
  EXPECT_EQ(bottom, 1);
}

TEST(Patch, TeapotRoundTripsThroughSwp) {
  const sweep::Document doc = sweep::test::load_starter("teapot.swp");
  EXPECT_EQ(sweep::io::parse_swp(sweep::io::write_swp(doc)), doc);
}

/// Normals on a (steps + 1)^2 grid are finite and unit, and at each sample agree with the normal
/// of the cross product a short way inside.
void expect_normals_continuous(const PatchPoints& p, const char* what) {
  const int steps = 8;
  for (int a = 0; a <= steps; ++a) {
    for (int b = 0; b <= steps; ++b) {
      const double u = double(a) / steps, v = double(b) / steps;
      const glm::dvec3 n = sweep::patch_normal(p, PatchBasis::Bezier, u, v);
      ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)) << what;
      EXPECT_NEAR(glm::length(n), 1.0, 1e-12) << what;
      const double inside = 1e-4;
      const double su = u + inside * (0.5 - u) * 2.0, sv = v + inside * (0.5 - v) * 2.0;
      const sweep::PatchSample s = sweep::evaluate_patch(p, PatchBasis::Bezier, su, sv);
      const glm::dvec3 near = glm::normalize(glm::cross(s.du, s.dv));
      EXPECT_GT(glm::dot(n, near), 0.999) << what << " at u " << u << " v " << v;
    }
  }
}

TEST(Patch, CollapsedEdgeHasTheNormalFromInside) {
  std::mt19937 rng(17);
  for (int trial = 0; trial < 10; ++trial) {
    PatchPoints p = bumpy_net(rng);
    for (std::size_t j = 1; j < 4; ++j) p[j] = p[0];  // row 0 is one point: dP/dv = 0 along u = 0
    expect_normals_continuous(p, "collapsed row");
    const sweep::Mesh mesh = sweep::build_bezier_patches(std::vector<glm::dvec3>(p.begin(), p.end()), 6);
    EXPECT_EQ(mesh.vertex_count(), static_cast<std::size_t>(7 * 7 - 6));  // the row welds into one vertex
    for (const glm::vec3& n : mesh.normals) {
      ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
      EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
      EXPECT_GT(n.z, 0.0f);
    }
    EXPECT_EQ(sweep::mesh_topology(mesh).non_manifold_edges, 0u);
  }
}

TEST(Patch, CornerWithARepeatedControlPointHasTheNormalFromInside) {
  std::mt19937 rng(19);
  for (int trial = 0; trial < 10; ++trial) {
    PatchPoints p = bumpy_net(rng);
    p[1] = p[0];  // dP/dv(0, 0) = 0
    expect_normals_continuous(p, "P01 = P00");
    p = bumpy_net(rng);
    p[14] = p[15];  // dP/dv(1, 1) = 0
    p[11] = p[15];  // and dP/du(1, 1) = 0
    expect_normals_continuous(p, "P32 = P23 = P33");
  }
}

TEST(Patch, PatchCollapsedToAPointHasAFallbackNormal) {
  PatchPoints p;
  p.fill(glm::dvec3(1.0, 2.0, 3.0));
  const glm::dvec3 n = sweep::patch_normal(p, PatchBasis::Bezier, 0.5, 0.5);
  EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
}

TEST(Patch, NetLinesJoinNeighbouringControlPoints) {
  std::mt19937 rng(23);
  const PatchPoints a = random_net(rng), b = random_net(rng);
  const std::vector<glm::dvec3> points = concat(a, b);
  const std::vector<glm::vec3> lines = sweep::patch_net_lines(points, 4, 0);
  EXPECT_EQ(lines.size(), 2u * 2u * 24u);  // 2 patches, 24 segments of a 4 x 4 grid each
  // Every segment joins two points of one patch that are neighbours in a row or a column.
  for (std::size_t k = 0; k + 1 < lines.size(); k += 2) {
    bool found = false;
    for (std::size_t patch = 0; patch < 2 && !found; ++patch) {
      for (std::size_t i = 0; i < 4 && !found; ++i) {
        for (std::size_t j = 0; j < 4 && !found; ++j) {
          const glm::vec3 p(points[16 * patch + 4 * i + j]);
          if (lines[k] != p) continue;
          if (j + 1 < 4 && lines[k + 1] == glm::vec3(points[16 * patch + 4 * i + j + 1])) found = true;
          if (i + 1 < 4 && lines[k + 1] == glm::vec3(points[16 * patch + 4 * (i + 1) + j])) found = true;
        }
      }
    }
    EXPECT_TRUE(found) << "segment " << k / 2;
  }
  std::vector<glm::dvec3> net;
  for (int i = 0; i < 5 * 6; ++i) net.emplace_back(i, i * i, 0.0);
  EXPECT_EQ(sweep::patch_net_lines(net, 5, 6).size(), 2u * (5u * 5u + 6u * 4u));
}

}  // namespace
