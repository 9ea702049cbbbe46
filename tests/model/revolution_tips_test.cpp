// The normals of a surface of revolution where its profile meets the axis: along the axis at a
// smooth pole (the profile meets it at a right angle), and the faces' own normals at a cone point
// (a cone's apex, a spindle's tips), one vertex per copy, each with the normal of its faces.
#include "geometry/curves/curve.hpp"
#include "geometry/curves/polyline.hpp"
#include "geometry/surfaces/surface.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

namespace {

constexpr int kCopies = 24;

/// The unit normals of the triangles that use vertex v.
std::vector<glm::dvec3> face_normals_at(const sweep::Mesh& mesh, std::uint32_t v) {
  std::vector<glm::dvec3> normals;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    if (a != v && b != v && c != v) continue;
    const glm::dvec3 n = glm::cross(glm::dvec3(mesh.positions[b] - mesh.positions[a]),
                                    glm::dvec3(mesh.positions[c] - mesh.positions[a]));
    if (glm::length(n) > 1e-12) normals.push_back(glm::normalize(n));
  }
  return normals;
}

/// Degrees between the vertex normal and the farthest of the normals of the faces at it.
double worst_angle_to_faces(const sweep::Mesh& mesh, std::uint32_t v) {
  double worst = 0.0;
  for (const glm::dvec3& f : face_normals_at(mesh, v)) {
    const double cosine = std::clamp(glm::dot(glm::normalize(glm::dvec3(mesh.normals[v])), f), -1.0, 1.0);
    worst = std::max(worst, std::acos(cosine) * 180.0 / std::numbers::pi);
  }
  return worst;
}

/// The surface of revolution of `text`'s first curve, and the indices of its vertices on the axis.
struct Revolved {
  sweep::Mesh mesh;
  std::vector<std::uint32_t> on_axis;
};
Revolved revolve(const std::string& text) {
  const sweep::Document doc = sweep::io::parse_swp(text, "tip.swp");
  Revolved r{sweep::build_surface_of_revolution(sweep::evaluate_curve(doc.objects[0]), kCopies), {}};
  for (std::uint32_t v = 0; v < r.mesh.positions.size(); ++v) {
    if (std::abs(r.mesh.positions[v].x) < 1e-9f && std::abs(r.mesh.positions[v].z) < 1e-9f) r.on_axis.push_back(v);
  }
  return r;
}

TEST(RevolutionTips, AConeApexTakesTheNormalsOfTheFacesBesideIt) {
  // A cone of half-angle 45 degrees, apex up at (0, 1, 0), traced from the apex down.
  const Revolved cone = revolve("poly2 side 2 [0 1] [-1 0]\n");
  ASSERT_EQ(cone.on_axis.size(), static_cast<std::size_t>(kCopies)) << "one apex vertex per copy";
  for (const std::uint32_t v : cone.on_axis) {
    const glm::dvec3 n(cone.mesh.normals[v]);
    // 45 degrees up like the cone, less what the flat facets' chords take (cos 7.5 degrees).
    EXPECT_NEAR(n.y, std::sqrt(0.5), 5e-3) << v;
    EXPECT_LT(worst_angle_to_faces(cone.mesh, v), 1e-3) << "the tip shades as the faces at it: " << v;
  }
}

TEST(RevolutionTips, ASpindleHasConeNormalsAtBothTips) {
  // Two straight halves meeting the axis at 60 and 30 degrees.
  const Revolved spindle = revolve("poly2 spindle 3 [0 2] [-1 0.5] [0 0]\n");
  ASSERT_EQ(spindle.on_axis.size(), static_cast<std::size_t>(2 * kCopies));
  for (const std::uint32_t v : spindle.on_axis) {
    const glm::dvec3 n(spindle.mesh.normals[v]);
    EXPECT_GT(std::abs(n.y), 0.2) << v;
    EXPECT_LT(std::abs(n.y), 0.95) << "not the pole normal: " << v;
    EXPECT_LT(worst_angle_to_faces(spindle.mesh, v), 1e-3) << v;
    EXPECT_EQ(n.y > 0.0, spindle.mesh.positions[v].y > 1.0f) << "out of the solid at each tip";
  }
}

TEST(RevolutionTips, ASmoothPoleKeepsTheAxisNormal) {
  // A Bezier quarter circle meeting the axis square at the top: a hemisphere's smooth pole.
  const Revolved dome = revolve("bez2 dome 8 4 [0 1] [-0.5523 1] [-1 0.5523] [-1 0]\n");
  ASSERT_EQ(dome.on_axis.size(), static_cast<std::size_t>(kCopies));
  for (const std::uint32_t v : dome.on_axis) {
    EXPECT_EQ(glm::dvec3(dome.mesh.normals[v]), glm::dvec3(0.0, 1.0, 0.0)) << v;
  }
}

/// The triangles of `mesh` whose corners do not span an area (two of them at one point).
std::size_t zero_area_triangles(const sweep::Mesh& mesh) {
  std::size_t count = 0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3 a = mesh.positions[mesh.indices[t]], b = mesh.positions[mesh.indices[t + 1]],
                    c = mesh.positions[mesh.indices[t + 2]];
    count += glm::length(glm::cross(glm::dvec3(b - a), glm::dvec3(c - a))) > 0.0 ? 0 : 1;
  }
  return count;
}

TEST(RevolutionTips, PolesAreClosedByFansWithoutZeroAreaTriangles) {
  // A dome (one pole), a cone (an apex) and a spindle (two tips): every segment that ends on the
  // axis is one triangle per copy instead of a quad with a collapsed half.
  const Revolved dome = revolve("bez2 dome 8 4 [0 1] [-0.5523 1] [-1 0.5523] [-1 0]\n");
  EXPECT_EQ(zero_area_triangles(dome.mesh), 0u);
  EXPECT_EQ(dome.mesh.triangle_count(), static_cast<std::size_t>(kCopies * (2 * 8 - 1)));
  const Revolved cone = revolve("poly2 side 2 [0 1] [-1 0]\n");
  EXPECT_EQ(zero_area_triangles(cone.mesh), 0u);
  EXPECT_EQ(cone.mesh.triangle_count(), static_cast<std::size_t>(kCopies));
  const Revolved spindle = revolve("poly2 spindle 3 [0 2] [-1 0.5] [0 0]\n");
  EXPECT_EQ(zero_area_triangles(spindle.mesh), 0u);
  EXPECT_EQ(spindle.mesh.triangle_count(), static_cast<std::size_t>(2 * kCopies));
  // Each pole copy is used by its own fan triangle: the pole's normals stay as they were.
  for (const std::uint32_t v : dome.on_axis) {
    EXPECT_EQ(glm::dvec3(dome.mesh.normals[v]), glm::dvec3(0.0, 1.0, 0.0)) << v;
  }
}

}  // namespace
