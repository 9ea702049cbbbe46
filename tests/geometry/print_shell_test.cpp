// The print model's geometry: placement on the plate, welding into shells, their topology and
// where they stand (geometry/mesh/print_placement, shell, shell_topology, shell_contact).
#include "geometry/mesh/print_placement.hpp"
#include "geometry/mesh/shell.hpp"
#include "geometry/mesh/shell_contact.hpp"
#include "geometry/mesh/shell_topology.hpp"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <gtest/gtest.h>

#include <cmath>

namespace sweep {
namespace {

/// A box from `low` to `high` (model coordinates, y up), triangles counterclockwise from outside,
/// every corner once per face (24 vertices), as a surface with split seams is built.
Mesh box_mesh(const glm::vec3& low, const glm::vec3& high) {
  Mesh mesh;
  const glm::vec3 c[8] = {{low.x, low.y, low.z},    {high.x, low.y, low.z}, {high.x, high.y, low.z},
                          {low.x, high.y, low.z},   {low.x, low.y, high.z}, {high.x, low.y, high.z},
                          {high.x, high.y, high.z}, {low.x, high.y, high.z}};
  const int faces[6][4] = {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {1, 2, 6, 5}, {2, 3, 7, 6}, {3, 0, 4, 7}};
  for (const auto& f : faces) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (const int k : f) mesh.positions.push_back(c[k]);
    mesh.indices.insert(mesh.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
  }
  return mesh;
}

/// A cone of `n` sides with its apex copied once per side a hair apart (as a profile sample a
/// hair off the axis is) and an open base.
Mesh open_cone(int n, float hair) {
  Mesh mesh;
  for (int k = 0; k < n; ++k) {
    const float a = glm::two_pi<float>() * float(k) / float(n);
    mesh.positions.push_back({std::cos(a), 0.0f, std::sin(a)});
    mesh.positions.push_back({hair * std::cos(a), 1.0f, hair * std::sin(a)});
  }
  for (int k = 0; k < n; ++k) {
    const auto b0 = std::uint32_t(2 * k), t0 = b0 + 1;
    const auto b1 = std::uint32_t(2 * ((k + 1) % n)), t1 = b1 + 1;
    mesh.indices.insert(mesh.indices.end(), {b0, t0, b1, b1, t0, t1});
  }
  return mesh;
}

TEST(PrintPlacement, TurnsYUpIntoZUpStandsOnThePlateAndScalesToTheHeight) {
  Mesh mesh;
  mesh.positions = {{-1.0f, 2.0f, 0.5f}, {3.0f, 6.0f, -0.5f}};
  const Mesh* meshes[] = {&mesh};
  const PrintPlacement placement = place_on_plate(meshes, 20.0);
  EXPECT_DOUBLE_EQ(placement.scale, 5.0);  // the model is 4 units tall (y 2..6)
  const glm::dvec3 low = placed(placement, mesh.positions[0]);
  const glm::dvec3 high = placed(placement, mesh.positions[1]);
  EXPECT_DOUBLE_EQ(low.z, 0.0);
  EXPECT_DOUBLE_EQ(high.z, 20.0);
  EXPECT_DOUBLE_EQ(low.x + high.x, 0.0);  // centred in x
  EXPECT_DOUBLE_EQ(low.y + high.y, 0.0);  // and in y (model -z)
  EXPECT_DOUBLE_EQ(low.y, -2.5);          // z 0.5 goes to -y: a rotation about x, not a mirror
  EXPECT_EQ(placement.size, glm::dvec3(20.0, 5.0, 20.0));
  EXPECT_DOUBLE_EQ(place_on_plate(meshes, 0.0).scale, 1.0);
  const glm::dvec3 back = unplaced(placement, high);
  EXPECT_NEAR(glm::distance(back, glm::dvec3(mesh.positions[1])), 0.0, 1e-12);
}

TEST(Shell, ABoxBuiltFaceByFaceWeldsIntoOneClosedOutwardShell) {
  const Mesh mesh = box_mesh({0, 0, 0}, {2, 1, 3});
  const Mesh* meshes[] = {&mesh};
  const Shell shell = welded_shell(mesh, place_on_plate(meshes, 0.0));
  EXPECT_EQ(shell.vertex_count(), 8u);
  EXPECT_EQ(shell.triangle_count(), 12u);
  const ShellTopology t = shell_topology(shell);
  EXPECT_TRUE(t.closed_manifold());
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_NEAR(t.volume, 6.0, 1e-9);
  EXPECT_EQ(zero_area_triangles(shell), 0u);
}

TEST(Shell, CopiesOfAPointAHairOffTheAxisBecomeOnePoleAndTheirSliversGo) {
  const Mesh mesh = open_cone(90, 1e-7f);
  const Mesh* meshes[] = {&mesh};
  const Shell shell = welded_shell(mesh, place_on_plate(meshes, 80.0));
  EXPECT_EQ(shell.vertex_count(), 91u);    // the base ring and one apex
  EXPECT_EQ(shell.triangle_count(), 90u);  // the fan; the slivers between the apex copies are gone
  EXPECT_EQ(zero_area_triangles(shell), 0u);
  const ShellTopology t = shell_topology(shell);
  EXPECT_EQ(t.boundary_edges, 90u);  // the open base
  EXPECT_EQ(t.boundary_loops, 1u);
  EXPECT_EQ(t.non_manifold_edges, 0u);
}

TEST(ShellTopology, CountsHolesFlippedTrianglesAndInsideOut) {
  Mesh mesh = box_mesh({0, 0, 0}, {1, 1, 1});
  const Mesh* meshes[] = {&mesh};
  Shell shell = welded_shell(mesh, place_on_plate(meshes, 0.0));
  std::swap(shell.indices[1], shell.indices[2]);  // one triangle flipped
  ShellTopology t = shell_topology(shell);
  EXPECT_TRUE(t.closed_manifold());
  EXPECT_EQ(t.misoriented_edges, 3u);
  for (std::size_t i = 0; i < shell.indices.size(); i += 3) std::swap(shell.indices[i + 1], shell.indices[i + 2]);
  t = shell_topology(shell);  // now every triangle but that one is flipped
  EXPECT_EQ(t.misoriented_edges, 3u);
  std::swap(shell.indices[1], shell.indices[2]);  // all flipped: consistent, inside out
  t = shell_topology(shell);
  EXPECT_TRUE(t.consistently_oriented());
  EXPECT_LT(t.volume, 0.0);
  shell.indices.erase(shell.indices.begin(), shell.indices.begin() + 12);  // two opposite faces gone
  t = shell_topology(shell);
  EXPECT_EQ(t.boundary_edges, 8u);
  EXPECT_EQ(t.boundary_loops, 2u);
}

TEST(ShellContact, ABoxInsideAnotherIsHeldAndOneBesideItIsNot) {
  const Mesh outer_mesh = box_mesh({0, 0, 0}, {4, 4, 4});
  const Mesh inner_mesh = box_mesh({1, 1, 1}, {2, 2, 2});
  const Mesh beside_mesh = box_mesh({5, 1, 1}, {6, 2, 2});
  const Mesh* meshes[] = {&outer_mesh, &inner_mesh, &beside_mesh};
  const PrintPlacement placement = place_on_plate(meshes, 0.0);
  const Shell outer = welded_shell(outer_mesh, placement);
  const Shell inner = welded_shell(inner_mesh, placement);
  const Shell beside = welded_shell(beside_mesh, placement);
  EXPECT_TRUE(holds(outer, inner));
  EXPECT_FALSE(holds(outer, beside));
  EXPECT_FALSE(holds(inner, outer));
  EXPECT_DOUBLE_EQ(lowest_point(outer).z, 0.0);
  EXPECT_DOUBLE_EQ(lowest_point(inner).z, 1.0);
}

}  // namespace
}  // namespace sweep
