// Birail surfaces (birail.hpp): the profile's ends ride the rails, `height` keeps the section's
// height, parallel straight rails extrude, closed rails close the surface.
#include "geometry/surfaces/birail.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"

#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>

namespace {

using sweep::CurveSamples;

struct Built {
  sweep::Document doc;
  sweep::Scene scene;
  const CurveSamples& curve(int i) const { return scene.objects[static_cast<std::size_t>(i)].curve; }
  const sweep::Object& surface() const { return doc.objects.back(); }
  const sweep::Mesh& mesh() const { return scene.objects.back().mesh; }
};

Built build(const std::string& text) {
  Built b;
  b.doc = sweep::io::parse_swp(text, "test.swp");
  b.scene = sweep::evaluate_document(b.doc);
  return b;
}

double distance_to_polyline(const glm::dvec3& p, const CurveSamples& curve) {
  double best = 1e300;
  for (std::size_t i = 0; i + 1 < curve.frames.size(); ++i) {
    const glm::dvec3 a = curve.frames[i].V;
    const glm::dvec3 d = curve.frames[i + 1].V - a;
    const double t = std::clamp(glm::dot(p - a, d) / std::max(glm::dot(d, d), 1e-300), 0.0, 1.0);
    best = std::min(best, glm::length(p - (a + t * d)));
  }
  return best;
}

const char* const kHull =
    "bsp2 section 8 6 [-1 0] [-1 -0.6] [-0.5 -1] [0.5 -1] [1 -0.6] [1 0]\n"
    "bsp3 left 8 5 [0 0 0] [-1 0.2 1] [-1.3 0.3 3] [-1 0.2 5] [0 0.5 6]\n"
    "bsp3 right 6 6 [0 0 0] [1 0.2 1] [1.3 0.3 2.5] [1.2 0.3 4] [1 0.2 5] [0 0.5 6]\n";

TEST(Birail, BothProfileEndsRideTheirRailsAtEveryStation) {
  for (const char* height : {"", " height"}) {
    const Built b = build(std::string(kHull) + "birail hull section left right" + height + "\n");
    const CurveSamples& profile = b.curve(0);
    const sweep::ProfileChord chord = sweep::profile_chord(profile);
    const auto stations = sweep::birail_stations(b.curve(1), b.curve(2), chord, height[0] != '\0');
    const double size = 6.0;
    ASSERT_GE(stations.size(), std::max(b.curve(1).frames.size(), b.curve(2).frames.size()));
    for (const sweep::BirailStation& s : stations) {
      const glm::dvec3 first = sweep::place_on_station(s, chord, profile.frames.front().V);
      const glm::dvec3 last = sweep::place_on_station(s, chord, profile.frames.back().V);
      EXPECT_LE(distance_to_polyline(first, b.curve(1)), 1e-9 * size) << s.fraction;
      EXPECT_LE(distance_to_polyline(last, b.curve(2)), 1e-9 * size) << s.fraction;
      // Orthonormal placement frame, the section plane perpendicular to the travel.
      EXPECT_NEAR(glm::dot(s.across, s.up), 0.0, 1e-12);
      EXPECT_NEAR(glm::dot(s.across, s.travel), 0.0, 1e-12);
      EXPECT_NEAR(glm::length(s.up), 1.0, 1e-12);
    }
    // Every rail sample is a station: the rails' own samples are on the surface.
    const sweep::Mesh& mesh = b.mesh();
    const std::size_t ring = profile.frames.size();
    for (const sweep::Frame& f : b.curve(2).frames) {
      double best = 1e300;
      for (std::size_t j = 0; j < mesh.positions.size() / ring; ++j) {
        best = std::min(best, glm::length(glm::dvec3(mesh.positions[j * ring + ring - 1]) - f.V));
      }
      EXPECT_LT(best, 1e-5) << height;
    }
  }
}

TEST(Birail, HeightKeepsTheSectionHeightAndUniformScalingScalesIt) {
  const Built uniform = build(std::string(kHull) + "birail hull section left right\n");
  const Built kept = build(std::string(kHull) + "birail hull section left right height\n");
  const CurveSamples& profile = uniform.curve(0);
  const sweep::ProfileChord chord = sweep::profile_chord(profile);
  double profile_height = 0.0;
  for (const sweep::Frame& f : profile.frames) {
    profile_height = std::max(profile_height, std::abs(glm::dot(f.V - chord.first, chord.left)));
  }
  for (const bool keep : {false, true}) {
    const Built& b = keep ? kept : uniform;
    for (const auto& s : sweep::birail_stations(b.curve(1), b.curve(2), chord, keep)) {
      double section_height = 0.0;
      for (const sweep::Frame& f : profile.frames) {
        const glm::dvec3 p = sweep::place_on_station(s, chord, f.V);
        section_height = std::max(section_height, std::abs(glm::dot(p - s.origin, s.up)));
      }
      const double expected = keep ? profile_height : profile_height * s.along_scale;
      EXPECT_NEAR(section_height, expected, 1e-9 * profile_height) << s.fraction;
    }
  }
}

TEST(Birail, ParallelStraightRailsGiveAPlainExtrusion) {
  const Built b = build(
      "cr2 arc 8 3 [0 0] [1 0.7] [2 0]\n"
      "bez3 r1 4 4 [0 0 0] [0 0 1] [0 0 2] [0 0 3]\n"
      "bez3 r2 5 4 [2 0 0] [2 0 1] [2 0 2] [2 0 3]\n"
      "birail b arc r1 r2\n");
  const sweep::Mesh& mesh = b.mesh();
  const CurveSamples& profile = b.curve(0);
  const std::size_t ring = profile.frames.size();
  ASSERT_EQ(mesh.positions.size() % ring, 0u);
  for (std::size_t j = 0; j < mesh.positions.size() / ring; ++j) {
    const float z = mesh.positions[j * ring].z;
    for (std::size_t i = 0; i < ring; ++i) {
      // Every ring is the profile itself, moved along +z (the chord is +x, the profile's +y is +y).
      EXPECT_NEAR(mesh.positions[j * ring + i].x, profile.frames[i].V.x, 1e-6);
      EXPECT_NEAR(mesh.positions[j * ring + i].y, profile.frames[i].V.y, 1e-6);
      EXPECT_EQ(mesh.positions[j * ring + i].z, z);
      EXPECT_NEAR(mesh.normals[j * ring + i].z, 0.0f, 1e-6f);
    }
  }
  // Normals are the reversed profile normals (right of the profile's travel), as for a
  // generalized cylinder of an open profile: this arch, traced left to right, is clockwise, so
  // they point down into it; a U traced the same way (a hull) gets them outside.
  EXPECT_LT(mesh.normals[ring / 2].y, -0.99f);
}

TEST(Birail, ClosedRailsCloseTheSurface) {
  const Built b = build(
      "bez2 band 2 4 [0 0] [0.3 0.3] [0.7 0.3] [1 0]\n"
      "circ inner 32 1\ncirc outer 48 2\nbirail ring band inner outer\n");
  const sweep::Mesh& mesh = b.mesh();
  const std::size_t ring = b.curve(0).frames.size();
  // No vertex ring is repeated at the seam, and every edge along the rails is shared.
  EXPECT_EQ(mesh.positions.size() % ring, 0u);
  const auto uses = sweep::test::edge_uses(mesh);
  std::size_t boundary = 0;
  for (const auto& [edge, count] : uses) boundary += count == 1 ? 1 : 0;
  EXPECT_EQ(boundary, 2 * mesh.positions.size() / ring);  // only the two rails' edges
  for (const glm::vec3& n : mesh.normals) EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
}

/// The triangles of `mesh` with two corners at one place (of zero area).
std::size_t collapsed_triangles(const sweep::Mesh& mesh) {
  std::size_t count = 0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::vec3 &a = mesh.positions[mesh.indices[t]], &b = mesh.positions[mesh.indices[t + 1]],
                    &c = mesh.positions[mesh.indices[t + 2]];
    count += (a == b || b == c || a == c) ? 1 : 0;
  }
  return count;
}

TEST(Birail, RailsThatMeetAtTheTipsLeaveNoTriangleOfZeroArea) {
  // A leaf: two Bezier edges from one tip to the other. At each tip the section is one point,
  // so the triangle of each profile segment with a side there is left out, the other kept (a fan).
  const std::string rails =
      "bez2 vein 4 4 [0 0] [0.3 0.2] [0.7 0.2] [1 0]\n"
      "bez3 edge1 6 4 [0 0 0] [1 0.8 0] [3 0.8 0] [4 0 0]\n"
      "bez3 edge2 6 4 [0 0 0] [1 -0.5 0] [3 -0.9 0] [4 0 0]\n";
  const Built b = build(rails + "birail leaf vein edge1 edge2\n");
  const sweep::Mesh& mesh = b.mesh();
  const std::size_t ring = b.curve(0).frames.size();
  const std::size_t stations = mesh.vertex_count() / ring;
  EXPECT_EQ(collapsed_triangles(mesh), 0u);
  EXPECT_EQ(mesh.triangle_count(), 2 * (ring - 1) * (stations - 1) - 2 * (ring - 1));
  // Every tip copy a kept triangle uses has a unit normal facing the way its triangles face.
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a(mesh.positions[mesh.indices[t]]), b2(mesh.positions[mesh.indices[t + 1]]),
        c(mesh.positions[mesh.indices[t + 2]]);
    const glm::dvec3 face = glm::cross(b2 - a, c - a);
    for (std::size_t k = 0; k < 3; ++k) {
      const glm::vec3& n = mesh.normals[mesh.indices[t + k]];
      EXPECT_NEAR(glm::length(n), 1.0f, 1e-5f);
      EXPECT_GT(glm::dot(glm::dvec3(n), face), 0.0) << "triangle " << t / 3;
    }
  }
  // With `height` the tips are a segment, not a point: nothing has zero area, nothing is left out.
  const Built tall = build(rails + "birail leaf vein edge1 edge2 height\n");
  EXPECT_EQ(collapsed_triangles(tall.mesh()), 0u);
  EXPECT_EQ(tall.mesh().triangle_count(), 2 * (ring - 1) * (tall.mesh().vertex_count() / ring - 1));
}

}  // namespace
