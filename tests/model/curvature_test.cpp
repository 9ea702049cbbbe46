// Discrete curvature (Meyer, Desbrun, Schroeder and Barr 2003) on meshes built by the real
// pipeline (SWP text, parse_swp, evaluate_document) and on an exact UV sphere; the cool-warm
// colour map and its symmetric range.
#include "geometry/mesh/curvature.hpp"
#include "geometry/mesh/colormap.hpp"
#include "geometry/mesh/mesh_topology.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <numbers>
#include <set>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

namespace {

using sweep::Mesh;

/// The mesh of the last object of an SWP text.
Mesh last_mesh(const std::string& text) {
  const sweep::Document doc = sweep::io::parse_swp(text);
  sweep::Scene scene = sweep::evaluate_document(doc);
  return scene.objects.back().mesh;
}

/// A torus of tube radius 1 around a circle of radius 2 in the xy plane: `steps` around the tube,
/// 2 steps around the axis.
Mesh torus(int steps) {
  std::string text = "circ c ";
  text.append(std::to_string(steps)).append(" 1\ncirc s ").append(std::to_string(2 * steps));
  text.append(" 2\ngcyl t c s\n");
  return last_mesh(text);
}

/// A UV sphere of radius r with positions on the exact sphere (to float), outward unit normals,
/// counterclockwise seen from outside: `rings` latitude bands, `segments` longitudes, a seam
/// column repeated and the poles repeated per segment (as a swept surface would), so it only
/// closes once welded.
Mesh uv_sphere(double r, int rings, int segments) {
  Mesh m;
  for (int i = 0; i <= rings; ++i) {
    const double theta = std::numbers::pi * i / rings;  // from the north pole
    for (int j = 0; j <= segments; ++j) {
      const double phi = 2.0 * std::numbers::pi * (j == segments ? 0 : j) / segments;
      glm::dvec3 n(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      if (i == 0 || i == rings) n = glm::dvec3(0.0, 0.0, i == 0 ? 1.0 : -1.0);
      m.positions.emplace_back(r * n);
      m.normals.emplace_back(n);
    }
  }
  const auto at = [&](int i, int j) { return static_cast<std::uint32_t>(i * (segments + 1) + j); };
  for (int i = 0; i < rings; ++i) {
    for (int j = 0; j < segments; ++j) {
      // (i, j) -> (i + 1, j) goes south, -> (i, j + 1) goes east; south x east points out.
      const std::uint32_t a = at(i, j), b = at(i + 1, j), c = at(i, j + 1), d = at(i + 1, j + 1);
      if (i != 0) m.indices.insert(m.indices.end(), {a, b, c});
      if (i != rings - 1) m.indices.insert(m.indices.end(), {c, b, d});
    }
  }
  return m;
}

/// Index of the vertex nearest to p.
std::size_t nearest(const Mesh& m, const glm::vec3& p) {
  std::size_t best = 0;
  float best_d = std::numeric_limits<float>::max();
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const float d = glm::length(m.positions[i] - p);
    if (d < best_d) best_d = d, best = i;
  }
  return best;
}

/// The same surface seen from the other side: normals turned, triangles reversed.
Mesh turned_over(Mesh m) {
  for (glm::vec3& n : m.normals) n = -n;
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) std::swap(m.indices[t + 1], m.indices[t + 2]);
  return m;
}

/// Euler characteristic V - E + F of a mesh whose vertices at equal positions are welded,
/// without triangles that collapse once welded, counted here independently of curvature.cpp.
/// Precondition: no non-manifold edges (every edge used by 1 or 2 triangles).
int euler_characteristic(const Mesh& m) {
  const sweep::MeshTopology topology = sweep::mesh_topology(m);
  std::map<std::tuple<float, float, float>, std::uint32_t> ids;
  std::vector<std::uint32_t> id(m.positions.size());
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const glm::vec3 p = m.positions[i] + glm::vec3(0.0f);  // -0 + 0 = +0
    id[i] = ids.try_emplace({p.x, p.y, p.z}, static_cast<std::uint32_t>(ids.size())).first->second;
  }
  std::set<std::uint32_t> used;
  long faces = 0;
  for (std::size_t t = 0; t + 2 < m.indices.size(); t += 3) {
    const std::uint32_t a = id[m.indices[t]], b = id[m.indices[t + 1]], c = id[m.indices[t + 2]];
    if (a == b || b == c || c == a) continue;
    ++faces;
    used.insert({a, b, c});
  }
  // 2 E = 3 F + (boundary edges): interior edges are shared by two triangles.
  const long twice_edges = 3 * faces + static_cast<long>(topology.boundary_edges);
  EXPECT_EQ(twice_edges % 2, 0);
  return static_cast<int>(static_cast<long>(used.size()) - twice_edges / 2 + faces);
}

/// Largest of |K - K*| and |H - H*| at the torus's vertices at p (there is one).
double torus_error(const Mesh& m, const sweep::Curvatures& c, const glm::vec3& p, double k, double h) {
  const std::size_t i = nearest(m, p);
  EXPECT_LT(glm::length(m.positions[i] - p), 1e-5f) << "no vertex at " << p.x << " " << p.y << " " << p.z;
  return std::max(std::fabs(c.gaussian[i] - k), std::fabs(c.mean[i] - h));
}

// ---------------------------------------------------------------------------------------------
// Curvature

// The torus R = 2, r = 1 (gcyl of a circle of radius 1 along a circle of radius 2 in the xy
// plane, the profile in the sweep frame's N, B plane). Principal curvatures: 1/r = 1 around the
// tube and cos(v) / (R + r cos(v)) around the axis, v the angle from the outer equator. Outward
// normals (the generalized cylinder's, out of the tube), H > 0 where the surface bends away from
// them: outer equator (distance 3 from the z axis) K = 1/3, H = (1 + 1/3) / 2 = 2/3; top
// (distance 2, z = 1) K = 0, H = 1/2; inner equator (distance 1) K = -1, H = (1 - 1) / 2 = 0.
//
// Measured max(|K - K*|, |H - H*|) (steps around the tube; twice as many around the axis):
//   steps   outer      top        inner
//      16   4.630e-3   2.301e-3   2.101e-2
//      32   1.140e-3   5.890e-4   5.376e-3
//      64   2.966e-4   1.493e-4   1.358e-3
//     128   7.946e-5   3.994e-5   3.796e-4
// ratios per halving 3.6 to 4.1: observed order log2 = 1.84 to 2.02, second order as expected
// for the cotangent operators on this regular grid (mesh edges aligned with the principal
// directions). At 128 the float positions start to show (about 1e-5 of cotangent noise), so the
// asserted ratio is a margin below what is seen: at least 3 (order >= 1.58) per halving.
TEST(Curvature, TorusValuesConvergeAtSecondOrder) {
  std::array<double, 3> previous{};
  for (const int steps : {16, 32, 64, 128}) {
    const Mesh m = torus(steps);
    ASSERT_TRUE(sweep::mesh_topology(m).closed_manifold()) << steps;
    const sweep::Curvatures c = sweep::vertex_curvatures(m);
    ASSERT_EQ(c.gaussian.size(), m.positions.size());
    ASSERT_EQ(c.mean.size(), m.positions.size());
    const std::array<double, 3> error{torus_error(m, c, {3, 0, 0}, 1.0 / 3.0, 2.0 / 3.0),
                                      torus_error(m, c, {2, 0, 1}, 0.0, 0.5), torus_error(m, c, {1, 0, 0}, -1.0, 0.0)};
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_LT(error[k], 0.03) << steps << " point " << k;
      if (steps > 16) {
        EXPECT_GE(previous[k] / error[k], 3.0) << steps << " point " << k;
      }
    }
    previous = error;
  }
  EXPECT_LT(previous[0], 1e-4);
  EXPECT_LT(previous[1], 1e-4);
  EXPECT_LT(previous[2], 5e-4);
}

// Everywhere on the torus, not only at three vertices: at the vertex at angle v from the outer
// equator K = cos v / (2 + cos v) and H = (1 + cos v / (2 + cos v)) / 2.
TEST(Curvature, TorusEverywhere) {
  const Mesh m = torus(64);
  const sweep::Curvatures c = sweep::vertex_curvatures(m);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    const glm::dvec3 p(m.positions[i]);
    const double rho = std::hypot(p.x, p.y);
    const double cos_v = rho - 2.0;  // tube radius 1
    const double k_axis = cos_v / rho;
    EXPECT_NEAR(c.gaussian[i], k_axis, 2e-3) << i;
    EXPECT_NEAR(c.mean[i], 0.5 * (1.0 + k_axis), 1e-3) << i;
  }
}

TEST(Curvature, SphereHasConstantCurvature) {
  for (const double r : {2.0, 0.5}) {
    const Mesh m = uv_sphere(r, 32, 64);
    const sweep::Curvatures c = sweep::vertex_curvatures(m);
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      // Relative errors; about 2.3e-3 for K and 1e-3 for H at worst (edges of about 0.1 r).
      EXPECT_NEAR(c.gaussian[i] * r * r, 1.0, 3e-3) << r << " " << i;
      EXPECT_NEAR(c.mean[i] * r, 1.0, 1.5e-3) << r << " " << i;
    }
  }
}

TEST(Curvature, TurningTheNormalsOverNegatesMeanCurvatureOnly) {
  for (const Mesh& m : {uv_sphere(2.0, 16, 32), torus(16)}) {
    const sweep::Curvatures out = sweep::vertex_curvatures(m);
    const sweep::Curvatures in = sweep::vertex_curvatures(turned_over(m));
    for (std::size_t i = 0; i < m.positions.size(); ++i) {
      EXPECT_FLOAT_EQ(in.gaussian[i], out.gaussian[i]) << i;
      EXPECT_FLOAT_EQ(in.mean[i], -out.mean[i]) << i;
    }
  }
  // On the sphere with inward normals H = -1/r.
  const sweep::Curvatures in = sweep::vertex_curvatures(turned_over(uv_sphere(2.0, 32, 64)));
  for (const float h : in.mean) EXPECT_NEAR(h, -0.5, 1e-3);
}

// The seam column and the poles are repeated in the UV sphere: every copy gets its welded
// vertex's values, and without welding the seam would be a boundary with wrong values.
TEST(Curvature, CopiesAtASeamShareTheirValues) {
  const int rings = 16, segments = 32;
  const Mesh m = uv_sphere(1.0, rings, segments);
  const sweep::Curvatures c = sweep::vertex_curvatures(m);
  for (int i = 0; i <= rings; ++i) {
    const std::size_t first = static_cast<std::size_t>(i * (segments + 1));
    const std::size_t last = first + static_cast<std::size_t>(segments);
    EXPECT_EQ(c.gaussian[first], c.gaussian[last]) << i;
    EXPECT_EQ(c.mean[first], c.mean[last]) << i;
    EXPECT_NEAR(c.gaussian[first], 1.0, 0.02) << i;
    EXPECT_NEAR(c.mean[first], 1.0, 0.02) << i;
  }
  // The poles: all copies alike.
  for (int j = 1; j <= segments; ++j) {
    EXPECT_EQ(c.gaussian[static_cast<std::size_t>(j)], c.gaussian[0]);
    EXPECT_EQ(c.mean[static_cast<std::size_t>(j)], c.mean[0]);
  }
}

// A sphere from the real pipeline: a surface of revolution of a semicircle made of two cubic
// Bezier quarter arcs (handles 0.5523; their curvature is within about 2% of the circle's). The
// usual profile, top to bottom at x < 0, gets outward normals: H > 0.
TEST(Curvature, RevolvedSemicircleIsASphere) {
  const Mesh m = last_mesh(
      "bez2 arc 16 7 [0 1] [-0.5523 1] [-1 0.5523] [-1 0] [-1 -0.5523] [-0.5523 -1] [0 -1]\n"
      "srev ball 64 arc\n");
  EXPECT_TRUE(sweep::mesh_topology(m).closed_manifold());
  EXPECT_NEAR(sweep::total_angle_deficit(m), 4.0 * std::numbers::pi, 1e-9);
  const sweep::Curvatures c = sweep::vertex_curvatures(m);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_NEAR(c.gaussian[i], 1.0, 0.06) << i;
    EXPECT_NEAR(c.mean[i], 1.0, 0.03) << i;
  }
}

// Gauss-Bonnet: the angle deficits add up to 2 pi chi exactly (a combinatorial identity once the
// angles of every triangle add up to pi), so to rounding.
TEST(Curvature, GaussBonnetOnClosedSurfaces) {
  for (const int steps : {16, 64}) {
    EXPECT_NEAR(sweep::total_angle_deficit(torus(steps)), 0.0, 1e-9) << steps;
  }
  for (const double r : {2.0, 0.5}) {
    EXPECT_NEAR(sweep::total_angle_deficit(uv_sphere(r, 32, 64)), 4.0 * std::numbers::pi, 1e-9) << r;
  }
  // A capped cylinder: a tube with flat caps whose rims copy the tube's end rings.
  const Mesh can = last_mesh("circ c 32 0.5\nbez3 up 4 4 [0 0 0] [0 1 0] [0 2 0] [0 3 0]\ngcyl g c up caps\n");
  ASSERT_TRUE(sweep::mesh_topology(can).closed_manifold());
  EXPECT_NEAR(sweep::total_angle_deficit(can), 4.0 * std::numbers::pi, 1e-9);
  // Its side is a cylinder of radius 1/2 (K = 0, H = 1) and its caps are flat (K = H = 0), away
  // from the rims where the curvature of the edge sits.
  const sweep::Curvatures c = sweep::vertex_curvatures(can);
  int side = 0;
  for (std::size_t i = 0; i < can.positions.size(); ++i) {
    const glm::vec3 p = can.positions[i];
    if (p.y > 0.3f && p.y < 2.7f) {
      EXPECT_NEAR(c.gaussian[i], 0.0, 1e-3) << i;
      EXPECT_NEAR(c.mean[i], 1.0, 5e-3) << i;
      ++side;
    }
  }
  EXPECT_GT(side, 32);
  // A capped cup of revolution: closed at the bottom by the axis, at the top by a fan from the
  // axis whose centre is flat.
  const Mesh cup = last_mesh("bez2 cup 8 4 [0 -1] [-1.2 -1] [-1 0] [-1 1]\nsrev s 64 cup caps\n");
  ASSERT_TRUE(sweep::mesh_topology(cup).closed_manifold());
  EXPECT_NEAR(sweep::total_angle_deficit(cup), 4.0 * std::numbers::pi, 1e-9);
  const std::size_t centre = nearest(cup, {0, 1, 0});
  ASSERT_EQ(cup.positions[centre], glm::vec3(0, 1, 0));
  const sweep::Curvatures cc = sweep::vertex_curvatures(cup);
  EXPECT_NEAR(cc.gaussian[centre], 0.0, 1e-4);
  EXPECT_NEAR(cc.mean[centre], 0.0, 1e-4);
}

// Every surface of every starter file without non-manifold edges, open or closed: the deficits
// (boundary vertices with pi - sum) add up to 2 pi (V - E + F) of the welded mesh.
TEST(Curvature, GaussBonnetOnEveryStarterSurface) {
  int checked = 0, closed = 0;
  for (const auto& path : sweep::test::starter_files()) {
    const sweep::Document doc = sweep::io::load_swp_file(path);
    const sweep::Scene scene = sweep::evaluate_document(doc);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      const Mesh& m = scene.objects[i].mesh;
      if (m.indices.empty()) continue;
      const sweep::MeshTopology topology = sweep::mesh_topology(m);
      if (topology.non_manifold_edges != 0) continue;
      const int chi = euler_characteristic(m);
      EXPECT_NEAR(sweep::total_angle_deficit(m), 2.0 * std::numbers::pi * chi, 1e-8)
          << path.filename() << " object " << i << " chi " << chi;
      const sweep::Curvatures c = sweep::vertex_curvatures(m);
      for (std::size_t v = 0; v < m.positions.size(); ++v) {
        ASSERT_TRUE(std::isfinite(c.gaussian[v]) && std::isfinite(c.mean[v])) << path.filename() << " " << i;
      }
      ++checked;
      if (topology.closed_manifold()) ++closed;
    }
  }
  EXPECT_GT(checked, 30);  // 40 when written, 26 of them closed
  EXPECT_GT(closed, 20);
}

// An open flat grid: K = H = 0 inside; the boundary deficits (pi - sum) add up to 2 pi (a disk).
TEST(Curvature, FlatSheetWithBoundary) {
  Mesh m;
  const int n = 6;
  for (int j = 0; j <= n; ++j) {
    for (int i = 0; i <= n; ++i) {
      m.positions.emplace_back(static_cast<float>(i), static_cast<float>(j) * 0.5f, 0.0f);
      m.normals.emplace_back(0.0f, 0.0f, 1.0f);
    }
  }
  for (int j = 0; j < n; ++j) {
    for (int i = 0; i < n; ++i) {
      const auto at = [&](int a, int b) { return static_cast<std::uint32_t>(b * (n + 1) + a); };
      sweep::add_quad(m.indices, at(i, j), at(i + 1, j), at(i, j + 1), at(i + 1, j + 1), true);
    }
  }
  EXPECT_NEAR(sweep::total_angle_deficit(m), 2.0 * std::numbers::pi, 1e-12);
  const sweep::Curvatures c = sweep::vertex_curvatures(m);
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    const glm::vec3 p = m.positions[v];
    const bool boundary = p.x == 0.0f || p.x == static_cast<float>(n) || p.y == 0.0f || p.y == 0.5f * n;
    if (!boundary) {
      EXPECT_NEAR(c.gaussian[v], 0.0, 1e-5) << v;
      EXPECT_NEAR(c.mean[v], 0.0, 1e-5) << v;
    } else {
      // A straight boundary: half a disk around the vertex, no deficit. (Corners have one.)
      const bool corner = (p.x == 0.0f || p.x == static_cast<float>(n)) && (p.y == 0.0f || p.y == 0.5f * n);
      if (!corner) {
        EXPECT_NEAR(c.gaussian[v], 0.0, 1e-5) << v;
      } else {
        EXPECT_GT(c.gaussian[v], 1.0f) << v;  // pi/2 of deficit over a small area
      }
      EXPECT_TRUE(std::isfinite(c.mean[v]));
    }
  }
}

/// A cone-like fan: apex (0, 0, h) over `n` ring vertices on the unit circle at z = 0,
/// counterclockwise seen from above, normals up.
Mesh fan(int n, double h) {
  Mesh m;
  m.positions.emplace_back(0.0f, 0.0f, static_cast<float>(h));
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * std::numbers::pi * i / n;
    m.positions.emplace_back(static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)), 0.0f);
  }
  m.normals.assign(m.positions.size(), {0.0f, 0.0f, 1.0f});
  for (int i = 0; i < n; ++i) {
    m.indices.insert(m.indices.end(),
                     {0u, static_cast<std::uint32_t>(1 + i), static_cast<std::uint32_t>(1 + (i + 1) % n)});
  }
  return m;
}

// The mixed area at the apex of a fan of isosceles triangles (legs L, apex angle g), against
// closed forms: non-obtuse triangles give the apex their Voronoi region, the kite from the apex
// to the circumcentre, L^2 tan(g / 2) / 4 each; triangles obtuse at the apex give it half their
// area, L^2 sin(g) / 4 each. K = (2 pi - n g) / A.
TEST(Curvature, MixedAreaIsVoronoiOrHalfAnObtuseTriangle) {
  const auto apex_angle = [](int n, double h) {
    const double leg = std::sqrt(1.0 + h * h), half_base = std::sin(std::numbers::pi / n);
    return std::pair{leg, 2.0 * std::asin(half_base / leg)};
  };
  {
    const int n = 6;
    const double h = 2.0;
    const auto [leg, g] = apex_angle(n, h);
    ASSERT_LT(g, std::numbers::pi / 2);  // and the base angles too: (pi - g) / 2
    const double area = n * leg * leg * std::tan(g / 2.0) / 4.0;
    const sweep::Curvatures c = sweep::vertex_curvatures(fan(n, h));
    EXPECT_NEAR(c.gaussian[0], (2.0 * std::numbers::pi - n * g) / area, 1e-5);
    EXPECT_GT(c.mean[0], 0.0f);  // a peak, bending away from its upward normal
  }
  {
    const int n = 3;
    const double h = 0.1;
    const auto [leg, g] = apex_angle(n, h);
    ASSERT_GT(g, std::numbers::pi / 2);  // obtuse at the apex
    const double area = n * leg * leg * std::sin(g) / 4.0;
    const sweep::Curvatures c = sweep::vertex_curvatures(fan(n, h));
    EXPECT_NEAR(c.gaussian[0], (2.0 * std::numbers::pi - n * g) / area, 1e-5);
    EXPECT_GT(c.mean[0], 0.0f);
    // The ring vertices are on the boundary: (pi - their two base angles) over a quarter of each
    // of their two triangles' areas.
    const double base_angle = (std::numbers::pi - g) / 2.0, triangle = leg * leg * std::sin(g) / 2.0;
    EXPECT_NEAR(c.gaussian[1], (std::numbers::pi - 2.0 * base_angle) / (2.0 * triangle / 4.0), 1e-5);
  }
}

// Degenerate input: a zero-area triangle, a triangle with a repeated vertex, an unused vertex
// and an empty mesh give finite values, and 0 where there is no area.
TEST(Curvature, DegenerateTrianglesGiveNoNaN) {
  Mesh m;
  m.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {5, 5, 5}, {1, 0, 0}};
  m.normals.assign(m.positions.size(), {0, 0, 1});
  m.indices = {0, 1, 2,   // collinear: no area
               0, 5, 1,   // 5 is 1's copy: collapses once welded
               0, 1, 3,   // a real triangle
               2, 2, 2};  // a point
  const sweep::Curvatures c = sweep::vertex_curvatures(m);
  ASSERT_EQ(c.gaussian.size(), m.positions.size());
  for (std::size_t v = 0; v < m.positions.size(); ++v) {
    EXPECT_TRUE(std::isfinite(c.gaussian[v])) << v;
    EXPECT_TRUE(std::isfinite(c.mean[v])) << v;
  }
  // Vertex 2 only has the collinear triangle, vertex 4 nothing: no area, zeros.
  EXPECT_EQ(c.gaussian[2], 0.0f);
  EXPECT_EQ(c.mean[2], 0.0f);
  EXPECT_EQ(c.gaussian[4], 0.0f);
  EXPECT_EQ(c.mean[4], 0.0f);
  // Copies share values.
  EXPECT_EQ(c.gaussian[5], c.gaussian[1]);
  EXPECT_EQ(c.mean[5], c.mean[1]);
  EXPECT_TRUE(std::isfinite(sweep::total_angle_deficit(m)));

  const sweep::Curvatures none = sweep::vertex_curvatures(Mesh{});
  EXPECT_TRUE(none.gaussian.empty());
  EXPECT_TRUE(none.mean.empty());
  EXPECT_EQ(sweep::total_angle_deficit(Mesh{}), 0.0);
}

// A mesh without normals (not the pipeline's, but allowed): the triangles' winding gives the side.
TEST(Curvature, WithoutNormalsTheWindingGivesTheSide) {
  Mesh m = uv_sphere(1.0, 16, 32);
  const sweep::Curvatures with = sweep::vertex_curvatures(m);
  m.normals.clear();
  const sweep::Curvatures without = sweep::vertex_curvatures(m);
  for (std::size_t i = 0; i < m.positions.size(); ++i) {
    EXPECT_EQ(without.mean[i], with.mean[i]) << i;
    EXPECT_GT(without.mean[i], 0.9f) << i;
  }
}

// ---------------------------------------------------------------------------------------------
// Colour map

TEST(ColorMap, EndpointsAndMiddleAreMorelandsEntries) {
  EXPECT_EQ(sweep::cool_warm(-1.0f), sweep::kCoolWarmTable.front());
  EXPECT_EQ(sweep::cool_warm(0.0f), sweep::kCoolWarmTable[16]);
  EXPECT_EQ(sweep::cool_warm(1.0f), sweep::kCoolWarmTable.back());
  const auto near = [](const glm::vec3& a, const glm::vec3& b) { return glm::length(a - b) < 1e-3f; };
  EXPECT_TRUE(near(sweep::cool_warm(-1.0f), {0.230f, 0.299f, 0.754f}));
  EXPECT_TRUE(near(sweep::cool_warm(0.0f), {0.865f, 0.865f, 0.865f}));
  EXPECT_TRUE(near(sweep::cool_warm(1.0f), {0.706f, 0.016f, 0.150f}));
  // Clamped outside [-1, 1]; NaN is the middle.
  EXPECT_EQ(sweep::cool_warm(-7.0f), sweep::cool_warm(-1.0f));
  EXPECT_EQ(sweep::cool_warm(3.0f), sweep::cool_warm(1.0f));
  EXPECT_EQ(sweep::cool_warm(std::numeric_limits<float>::infinity()), sweep::cool_warm(1.0f));
  EXPECT_EQ(sweep::cool_warm(std::numeric_limits<float>::quiet_NaN()), sweep::cool_warm(0.0f));
  // Every entry at its place, and halfway between two entries their mean.
  for (std::size_t i = 0; i < sweep::kCoolWarmTable.size(); ++i) {
    const float t = static_cast<float>(i) / 16.0f - 1.0f;
    EXPECT_EQ(sweep::cool_warm(t), sweep::kCoolWarmTable[i]) << i;
    if (i + 1 < sweep::kCoolWarmTable.size()) {
      EXPECT_TRUE(
          near(sweep::cool_warm(t + 1.0f / 32.0f), 0.5f * (sweep::kCoolWarmTable[i] + sweep::kCoolWarmTable[i + 1])))
          << i;
    }
  }
}

// The map runs blue -> grey -> red: red rises monotonically over [-1, 0] (0.230 to 0.865), and
// green and blue fall monotonically over [0, 1]. (Red is not monotone over [0, 1]: Moreland's
// warm half peaks at 0.970 near t = 0.38 and ends at 0.706.) Lightness (Rec. 709 luma of the
// components) falls away from the middle on both sides.
TEST(ColorMap, MonotoneChannels) {
  const auto luma = [](const glm::vec3& c) { return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b; };
  glm::vec3 previous = sweep::cool_warm(-1.0f);
  for (int k = 1; k <= 1000; ++k) {
    const float t = -1.0f + static_cast<float>(k) / 1000.0f;  // up to 0
    const glm::vec3 c = sweep::cool_warm(t);
    EXPECT_GE(c.r, previous.r) << t;
    EXPECT_GE(luma(c), luma(previous)) << t;
    previous = c;
  }
  previous = sweep::cool_warm(0.0f);
  for (int k = 1; k <= 1000; ++k) {
    const float t = static_cast<float>(k) / 1000.0f;
    const glm::vec3 c = sweep::cool_warm(t);
    EXPECT_LE(c.g, previous.g) << t;
    EXPECT_LE(c.b, previous.b) << t;
    EXPECT_LE(luma(c), luma(previous)) << t;
    previous = c;
  }
  EXPECT_GT(sweep::cool_warm(-0.5f).b, sweep::cool_warm(-0.5f).r);  // blue side
  EXPECT_GT(sweep::cool_warm(0.5f).r, sweep::cool_warm(0.5f).b);    // red side
}

TEST(ColorMap, SymmetricRangeIgnoresASpike) {
  // 100 values with |v| <= 0.99 and one spike of 1000: the 98th percentile of |v| is 0.98.
  std::vector<float> values;
  for (int i = 1; i <= 99; ++i) values.push_back((i % 2 == 0 ? 1.0f : -1.0f) * static_cast<float>(i) / 100.0f);
  values.push_back(1000.0f);
  EXPECT_FLOAT_EQ(sweep::symmetric_range(values), 0.98f);
  // A negative spike alike.
  values.back() = -1000.0f;
  EXPECT_FLOAT_EQ(sweep::symmetric_range(values), 0.98f);
  // Symmetric: negating everything changes nothing.
  for (float& v : values) v = -v;
  EXPECT_FLOAT_EQ(sweep::symmetric_range(values), 0.98f);
}

TEST(ColorMap, SymmetricRangeIsNeverZeroAndAlwaysFinite) {
  EXPECT_EQ(sweep::symmetric_range({}), 1.0f);
  EXPECT_EQ(sweep::symmetric_range({0.0f, 0.0f, -0.0f}), 1.0f);
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  EXPECT_EQ(sweep::symmetric_range({inf, -inf, nan}), 1.0f);
  EXPECT_EQ(sweep::symmetric_range({0.5f, inf, nan, -0.25f}), 0.5f);  // finite values only
  EXPECT_EQ(sweep::symmetric_range({-3.0f}), 3.0f);
  // Mostly zeros: the percentile is 0, so the largest magnitude keeps the rest visible.
  std::vector<float> sparse(200, 0.0f);
  sparse[7] = -2.0f;
  EXPECT_EQ(sweep::symmetric_range(sparse), 2.0f);
  // Real curvatures: the torus's, whose |K| and |H| are at most 1.
  const sweep::Curvatures c = sweep::vertex_curvatures(torus(32));
  const float k = sweep::symmetric_range(c.gaussian), h = sweep::symmetric_range(c.mean);
  EXPECT_GT(k, 0.5f);
  EXPECT_LE(k, 1.01f);
  EXPECT_GT(h, 0.5f);
  EXPECT_LE(h, 0.7f);
}

}  // namespace
