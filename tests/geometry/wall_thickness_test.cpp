// Thin walls (wall_thickness.hpp) on shapes whose thickness is known: a flat box 0.3 thick, a
// hollow ball with a 0.3 wall, a solid sphere 20 across, a torus whose tube is 2 across, and a
// sphere wound inside out, which has no opposite wall to measure.
#include "geometry/mesh/wall_thickness.hpp"
#include "geometry/thread_pool.hpp"
#include "support/shell_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <utility>
#include <vector>

namespace sweep {
namespace {

using test::sphere;
using test::torus;

/// The box [0, size] split into `cells` squares along each edge, welded, counterclockwise from
/// outside: each face is a grid of lattice points, and a lattice point is one vertex.
Shell box(const glm::dvec3& size, int cells) {
  Shell s;
  std::map<std::array<int, 3>, std::uint32_t> vertices;
  const auto vertex = [&](std::array<int, 3> lattice) {
    const auto [it, added] = vertices.try_emplace(lattice, static_cast<std::uint32_t>(s.positions.size()));
    if (added) s.positions.push_back(glm::dvec3(lattice[0], lattice[1], lattice[2]) * size / double(cells));
    return it->second;
  };
  for (int axis = 0; axis < 3; ++axis) {
    for (const int side : {0, cells}) {
      // In-plane axes u, v with u x v along +axis; swapped on the low side, whose outside is -axis.
      int u = (axis + 1) % 3, v = (axis + 2) % 3;
      if (side == 0) std::swap(u, v);
      const auto at = [&](int a, int b) {
        std::array<int, 3> lattice{};
        lattice[static_cast<std::size_t>(axis)] = side;
        lattice[static_cast<std::size_t>(u)] = a;
        lattice[static_cast<std::size_t>(v)] = b;
        return vertex(lattice);
      };
      for (int a = 0; a < cells; ++a) {
        for (int b = 0; b < cells; ++b) {
          s.indices.insert(s.indices.end(), {at(a, b), at(a + 1, b), at(a + 1, b + 1)});
          s.indices.insert(s.indices.end(), {at(a, b), at(a + 1, b + 1), at(a, b + 1)});
        }
      }
    }
  }
  return s;
}

/// `shell` wound the other way round: its outside turned in.
Shell inside_out(Shell shell) {
  for (std::size_t t = 0; t < shell.indices.size(); t += 3) std::swap(shell.indices[t + 1], shell.indices[t + 2]);
  return shell;
}

/// `outer` and, inside it, `inner` turned inside out: a hollow solid, one shell of two surfaces.
Shell hollow(const Shell& outer, const Shell& inner) {
  Shell s = outer;
  const auto offset = static_cast<std::uint32_t>(s.positions.size());
  s.positions.insert(s.positions.end(), inner.positions.begin(), inner.positions.end());
  for (const std::uint32_t i : inside_out(inner).indices) s.indices.push_back(offset + i);
  return s;
}

TEST(ThinWalls, AFlatBoxIsThinAcrossItsFacesOnly) {
  const Shell slab = box({10.0, 10.0, 0.3}, 4);
  const ThinWalls thin = thin_walls(slab, 0.8);
  EXPECT_EQ(thin.triangles, 2u * 4 * 4 * 2);  // the top's and the bottom's triangles
  EXPECT_NEAR(thin.thinnest, 0.3, 1e-6);
  EXPECT_TRUE(std::abs(thin.where.z) < 1e-12 || std::abs(thin.where.z - 0.3) < 1e-12);
  const ThinWalls none = thin_walls(slab, 0.2);
  EXPECT_EQ(none.triangles, 0u);
  EXPECT_EQ(none.thinnest, 0.0);
}

TEST(ThinWalls, ACubeIsThickAndEveryTriangleMeetsTheOppositeFace) {
  const Shell cube = box({1.0, 1.0, 1.0}, 3);
  EXPECT_EQ(thin_walls(cube, 0.8).triangles, 0u);
  const ThinWalls all = thin_walls(cube, 1.5);
  EXPECT_EQ(all.triangles, cube.triangle_count());
  EXPECT_NEAR(all.thinnest, 1.0, 1e-12);
}

TEST(ThinWalls, ASolidSphereIsItsDiameterThick) {
  const Shell ball = sphere({0, 0, 0}, 10.0, 64, 32);
  EXPECT_EQ(thin_walls(ball, 0.8).triangles, 0u);
  const ThinWalls all = thin_walls(ball, 25.0);
  EXPECT_EQ(all.triangles, ball.triangle_count());
  EXPECT_GT(all.thinnest, 19.5);
  EXPECT_LE(all.thinnest, 20.0);
}

TEST(ThinWalls, AHollowBallIsItsShellThick) {
  const Shell shell = hollow(sphere({0, 0, 0}, 10.0, 96, 48), sphere({0, 0, 0}, 9.7, 96, 48));
  const ThinWalls thin = thin_walls(shell, 0.8);
  EXPECT_EQ(thin.triangles, shell.triangle_count());  // from outside in and from the cavity out
  EXPECT_NEAR(thin.thinnest, 0.3, 0.03);
  EXPECT_EQ(thin_walls(shell, 0.2).triangles, 0u);
}

TEST(ThinWalls, TheResultDoesNotDependOnTheThreadCount) {
  const Shell shell = hollow(sphere({0, 0, 0}, 10.0, 96, 48), sphere({0, 0, 0}, 9.7, 96, 48));  // enough to be split
  set_worker_count(1);
  const ThinWalls one = thin_walls(shell, 0.8);
  set_worker_count(3);
  const ThinWalls three = thin_walls(shell, 0.8);
  set_worker_count(default_worker_count());
  EXPECT_EQ(three.triangles, one.triangles);
  EXPECT_EQ(three.thinnest, one.thinnest);
  EXPECT_EQ(three.where, one.where);
}

TEST(ThinWalls, ATorusIsItsTubeThick) {
  const Shell ring = torus(5.0, 1.0, 96, 48);
  EXPECT_EQ(thin_walls(ring, 1.5).triangles, 0u);
  const ThinWalls all = thin_walls(ring, 2.5);
  EXPECT_EQ(all.triangles, ring.triangle_count());
  EXPECT_NEAR(all.thinnest, 2.0, 0.01);
}

TEST(ThinWalls, AShellWoundInsideOutHasNoWallToMeasure) {
  // Its "inward" rays point out into space, or meet the far side from the front.
  EXPECT_EQ(thin_walls(inside_out(sphere({0, 0, 0}, 1.0, 32, 16)), 5.0).triangles, 0u);
}

TEST(ThinWalls, NoTrianglesNoThinWalls) {
  const ThinWalls none = thin_walls(Shell{}, 1.0);
  EXPECT_EQ(none.triangles, 0u);
  EXPECT_EQ(none.where, glm::dvec3(0.0));
}

}  // namespace
}  // namespace sweep
