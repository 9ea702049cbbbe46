// Scale and twist along a generalized cylinder (sweep_controls.hpp): section areas and
// centroids, the twist angle against the frame, exact extrusions, tilted normals, closed
// sweeps with a whole-turn twist.
#include "geometry/curves/curve.hpp"
#include "geometry/surfaces/surface.hpp"
#include "geometry/surfaces/sweep_controls.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"

#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace {

using sweep::CurveSamples;
using sweep::Frame;
using sweep::Station;

/// A smooth closed profile (a closed B-spline: its last three points repeat its first three)
/// whose centroid is off the origin.
const char* const kSquare =
    "bsp2 square 4 9 [0.3 -0.3] [1.1 -0.4] [1.3 0.3] [0.9 0.8] [0.3 0.6] [0.1 0.1] [0.3 -0.3] [1.1 -0.4] [1.3 0.3]\n";
/// A 4-fold symmetric closed profile: the square's corners as a closed B-spline (a rounded square).
const char* const kRoundedSquare = "bsp2 sq 2 7 [1 1] [-1 1] [-1 -1] [1 -1] [1 1] [-1 1] [-1 -1]\n";

double twice_area(const std::vector<glm::dvec2>& polygon) {
  double a = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2& p = polygon[i];
    const glm::dvec2& q = polygon[(i + 1) % polygon.size()];
    a += p.x * q.y - q.x * p.y;
  }
  return a;
}

glm::dvec2 centroid(const std::vector<glm::dvec2>& polygon) {
  glm::dvec2 c(0.0);
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const glm::dvec2& p = polygon[i];
    const glm::dvec2& q = polygon[(i + 1) % polygon.size()];
    c += (p + q) * (p.x * q.y - q.x * p.y);
  }
  return c / (3.0 * twice_area(polygon));
}

struct Built {
  sweep::Document doc;
  sweep::Scene scene;
  const sweep::Object& surface() const { return doc.objects.back(); }
  const CurveSamples& curve(int index) const { return scene.objects[static_cast<std::size_t>(index)].curve; }
  sweep::SweepControls controls() const {
    sweep::SweepControls c;
    if (surface().as<sweep::CylinderSurface>().scale >= 0)
      c.scale = &curve(surface().as<sweep::CylinderSurface>().scale);
    if (surface().as<sweep::CylinderSurface>().twist_curve >= 0)
      c.twist_curve = &curve(surface().as<sweep::CylinderSurface>().twist_curve);
    c.twist_degrees = surface().as<sweep::CylinderSurface>().twist;
    return c;
  }
};

Built build(const std::string& text) {
  Built b;
  b.doc = sweep::io::parse_swp(text, "test.swp");
  b.scene = sweep::evaluate_document(b.doc);
  return b;
}

/// The profile's distinct samples placed at sweep sample j, projected onto that frame's (N, B)
/// about V: the section as a polygon in its own plane.
std::vector<glm::dvec2> section(const Built& b, std::size_t j, const std::vector<Station>& stations) {
  const CurveSamples& profile = b.curve(b.surface().as<sweep::ProfilePart>().profile);
  const Frame& f = b.curve(b.surface().as<sweep::CylinderSurface>().sweep).frames[j];
  std::vector<glm::dvec2> polygon;
  for (std::size_t i = 0; i + 1 < profile.frames.size(); ++i) {
    const glm::dvec3 p = sweep::place_at_station(f, stations[j], profile.frames[i].V.x, profile.frames[i].V.y);
    polygon.emplace_back(glm::dot(p - f.V, f.N), glm::dot(p - f.V, f.B));
  }
  return polygon;
}

TEST(ControlledSweep, SectionAreaIsScaleSquaredAndCentroidIsCarried) {
  const Built b = build(std::string(kSquare) +
                        "bsp3 path 6 5 [0 0 0] [1 0 0] [2 1 0.5] [3 1 1] [4 0 1]\n"
                        "cr2 taper 8 3 [0 1] [0.5 1.6] [1 0.4]\n"
                        "gcyl g square path scale taper twist 70\n");
  const CurveSamples& profile = b.curve(0);
  std::vector<glm::dvec2> shape;
  for (std::size_t i = 0; i + 1 < profile.frames.size(); ++i) shape.emplace_back(profile.frames[i].V);
  const double area = twice_area(shape);
  const glm::dvec2 middle = centroid(shape);
  const CurveSamples& sweep_curve = b.curve(1);
  const std::vector<Station> stations = sweep::sweep_stations(sweep_curve.frames, b.controls());
  const sweep::Mesh& mesh = b.scene.objects.back().mesh;
  const std::size_t ring = profile.frames.size() - 1;
  for (std::size_t j = 0; j < sweep_curve.frames.size(); ++j) {
    const std::vector<glm::dvec2> placed = section(b, j, stations);
    const double s = stations[j].scale;
    EXPECT_NEAR(twice_area(placed), s * s * area, 1e-9 * s * s * std::abs(area)) << "station " << j;
    // The centroid is the profile's centroid, scaled and turned like every point.
    const Frame& f = sweep_curve.frames[j];
    const glm::dvec3 carried = sweep::place_at_station(f, stations[j], middle.x, middle.y);
    const glm::dvec2 c = centroid(placed);
    EXPECT_NEAR(c.x, glm::dot(carried - f.V, f.N), 1e-9) << j;
    EXPECT_NEAR(c.y, glm::dot(carried - f.V, f.B), 1e-9) << j;
    // The mesh holds exactly these points (to float).
    for (std::size_t i = 0; i < ring; ++i) {
      const glm::dvec3 p = sweep::place_at_station(f, stations[j], profile.frames[i].V.x, profile.frames[i].V.y);
      EXPECT_LT(sweep::test::distance(glm::dvec3(mesh.positions[j * ring + i]), p), 1e-5) << j << " " << i;
    }
  }
  // The scale reads the graph at the fraction of arc length: 1 at the start, 0.4 at the end.
  EXPECT_DOUBLE_EQ(stations.front().scale, 1.0);
  EXPECT_NEAR(stations.back().scale, 0.4, 1e-12);
}

TEST(ControlledSweep, TwistIsTheAngleFromNToThePlacedXAxis) {
  const Built b = build(std::string(kSquare) +
                        "bsp3 path 6 5 [0 0 0] [1 0 0] [2 1 0.5] [3 1 1] [4 0 1]\n"
                        "cr2 turn 8 3 [0 -30] [0.4 100] [1 45]\n"
                        "gcyl g square path twist turn\n");
  const CurveSamples& sweep_curve = b.curve(1);
  const std::vector<Station> stations = sweep::sweep_stations(sweep_curve.frames, b.controls());
  const std::vector<double> length = sweep::chord_lengths(sweep_curve.frames);
  for (std::size_t j = 0; j < stations.size(); ++j) {
    const Frame& f = sweep_curve.frames[j];
    const glm::dvec3 x_axis = sweep::place_at_station(f, stations[j], 1.0, 0.0) - f.V;
    const double angle = sweep::angle_about(f.T, f.N, x_axis);
    const double expected = sweep::graph_at(b.curve(2), length[j] / length.back()).value;
    EXPECT_NEAR(std::remainder(angle * 180.0 / std::numbers::pi - expected, 360.0), 0.0, 1e-9) << j;
  }
}

TEST(ControlledSweep, ZeroTwistAlongAStraightSweepIsAnExactExtrusion) {
  // A twist graph that stays at 0 takes the controlled path and must change nothing.
  const std::string common = std::string(kSquare) + "bez3 line 4 4 [0 0 0] [0 1 0] [0 2 0] [0 3 0]\n";
  const Built plain = build(common + "gcyl g square line\n");
  const Built zero = build(common + "cr2 flat 4 2 [0 0] [1 0]\n" + "gcyl g square line twist flat\n");
  const sweep::Mesh& a = plain.scene.objects.back().mesh;
  const sweep::Mesh& m = zero.scene.objects.back().mesh;
  ASSERT_EQ(a.positions.size(), m.positions.size());
  EXPECT_EQ(a.positions, m.positions);
  EXPECT_EQ(a.indices, m.indices);
  const std::size_t ring = plain.scene.objects[0].curve.frames.size() - 1;
  ASSERT_EQ(m.positions.size(), 5 * ring);
  for (std::size_t j = 0; j < m.positions.size() / ring; ++j) {
    for (std::size_t i = 0; i < ring; ++i) {
      const glm::vec3 moved = m.positions[j * ring + i] - m.positions[i];
      EXPECT_EQ(moved.x, 0.0f);
      EXPECT_EQ(moved.z, 0.0f);
      EXPECT_NEAR(moved.y, 0.75 * static_cast<double>(j), 1e-6);
      EXPECT_EQ(m.normals[j * ring + i], m.normals[i]);
    }
  }
}

TEST(ControlledSweep, TaperedNormalsAreNormalToTheSurface) {
  // A circle tapering linearly along a straight line is a cone: its normals lean toward the
  // narrow end by the half angle, and stay perpendicular to the mesh's edges along the sweep.
  const Built b = build(
      "circ c 64 1\nbez3 line 8 4 [0 0 0] [0 1 0] [0 2 0] [0 3 0]\n"
      "cr2 taper 4 2 [0 1] [1 0.25]\ngcyl cone c line scale taper\n");
  const sweep::Mesh& mesh = b.scene.objects.back().mesh;
  const std::size_t ring = 64;
  const double lean = std::atan(0.75 / 3.0);  // radius falls by 0.75 over a height of 3
  for (std::size_t j = 0; j < mesh.positions.size() / ring; ++j) {
    for (std::size_t i = 0; i < ring; ++i) {
      const glm::dvec3 n(mesh.normals[j * ring + i]);
      EXPECT_NEAR(n.y, std::sin(lean), 1e-6) << j << " " << i;
      const glm::dvec3 p(mesh.positions[j * ring + i]);
      EXPECT_GT(glm::dot(n, glm::dvec3(p.x, 0.0, p.z)), 0.0);  // out of the axis
    }
  }
}

TEST(ControlledSweep, ClosedSweepTwistOfAWholeSymmetryTurnJoinsTheSeam) {
  // A square (4-fold) swept round a circle with a quarter turn of twist: the last ring joins the
  // first one shifted by a quarter of the ring, with no crack.
  const Built b = build(std::string(kRoundedSquare) +
                        "bsp3 loop 8 7 [4 0 0] [0 4 0] [-4 0 0] [0 -4 0] [4 0 0] [0 4 0] [-4 0 0]\n"
                        "gcyl g sq loop twist 90\n");
  const sweep::Mesh& mesh = b.scene.objects.back().mesh;
  for (const auto& [edge, count] : sweep::test::edge_uses(mesh)) {
    EXPECT_EQ(count, 2) << edge.first << "-" << edge.second;
  }
  // Joined to the right partners: the seam's triangles are no longer than the others (a wrong
  // shift would join corners across the square's side).
  const std::size_t ring = 8;
  const std::size_t last_ring = mesh.positions.size() / ring - 1;
  double seam = 0.0, elsewhere = 0.0;
  for (std::size_t t = 0; t < mesh.indices.size(); t += 3) {
    bool at_seam = false;
    double longest = 0.0;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.indices[t + k], c = mesh.indices[t + (k + 1) % 3];
      longest = std::max(longest, double(glm::length(mesh.positions[a] - mesh.positions[c])));
      at_seam = at_seam || a / ring == last_ring;
    }
    (at_seam ? seam : elsewhere) = std::max(at_seam ? seam : elsewhere, longest);
  }
  EXPECT_LT(seam, 1.1 * elsewhere);
}

}  // namespace
