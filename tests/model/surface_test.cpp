// Swept surfaces: outward unit normals, counterclockwise winding seen from outside, closed
// seams, the analytic torus, and the vertex and triangle counts of every starter file.
#include "geometry/surfaces/surface.hpp"
#include "geometry/curves/curve.hpp"
#include "geometry/mesh/mesh_topology.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"

#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>

namespace {

using sweep::test::distance;

glm::dvec3 position(const sweep::Mesh& mesh, std::uint32_t i) {
  return glm::dvec3(mesh.positions[i]);
}
glm::dvec3 normal(const sweep::Mesh& mesh, std::uint32_t i) {
  return glm::dvec3(mesh.normals[i]);
}

double extent(const sweep::Mesh& mesh) {
  glm::dvec3 lo(0.0), hi(0.0);
  if (!mesh.positions.empty()) lo = hi = position(mesh, 0);
  for (const auto& p : mesh.positions) {
    lo = glm::min(lo, glm::dvec3(p));
    hi = glm::max(hi, glm::dvec3(p));
  }
  return glm::length(hi - lo);
}

void expect_unit_normals(const sweep::Mesh& mesh, const std::string& what) {
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size()) << what;
  for (std::uint32_t i = 0; i < mesh.normals.size(); ++i) {
    ASSERT_TRUE(std::isfinite(mesh.normals[i].x) && std::isfinite(mesh.normals[i].y) &&
                std::isfinite(mesh.normals[i].z))
        << what << " vertex " << i;
    EXPECT_NEAR(glm::length(normal(mesh, i)), 1.0, 1e-6) << what << " vertex " << i;
  }
}

/// Counterclockwise seen from the side the normals point to: every triangle that is not
/// degenerate (and not `excused`, given its first vertex) has its geometric normal on the side
/// of its vertex normals. Returns how many triangles were checked.
int expect_counterclockwise(const sweep::Mesh& mesh, const std::string& what,
                            const std::function<bool(std::uint32_t)>& excused = {}) {
  const double size = extent(mesh);
  int checked = 0;
  int wrong = 0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const glm::dvec3 geometric =
        glm::cross(position(mesh, b) - position(mesh, a), position(mesh, c) - position(mesh, a));
    if (glm::length(geometric) <= 1e-9 * size * size) continue;
    if (excused && (excused(a) || excused(b) || excused(c))) continue;
    ++checked;
    const glm::dvec3 average = normal(mesh, a) + normal(mesh, b) + normal(mesh, c);
    if (glm::dot(geometric, average) <= 0.0 && ++wrong <= 5) {
      ADD_FAILURE() << what << ": triangle " << t / 3 << " (" << a << ", " << b << ", " << c
                    << ") is clockwise seen from its normals";
    }
  }
  EXPECT_EQ(wrong, 0) << what;
  return checked;
}

/// Edges used by exactly one triangle.
std::vector<std::pair<std::uint32_t, std::uint32_t>> boundary_edges(const sweep::Mesh& mesh) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> out;
  for (const auto& [edge, uses] : sweep::test::edge_uses(mesh)) {
    if (uses == 1) out.push_back(edge);
  }
  return out;
}

/// Every edge is shared by exactly two triangles that traverse it in opposite directions.
void expect_watertight_and_consistently_oriented(const sweep::Mesh& mesh, const std::string& what) {
  int bad = 0;
  for (const auto& [edge, uses] : sweep::test::edge_uses(mesh)) {
    if (uses != 2 && ++bad <= 5)
      ADD_FAILURE() << what << ": edge " << edge.first << "-" << edge.second << " used " << uses << " times";
  }
  const auto directed = sweep::test::directed_edge_uses(mesh);
  for (const auto& [edge, uses] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    const bool paired = uses == 1 && reverse != directed.end() && reverse->second == 1;
    if (!paired && ++bad <= 10)
      ADD_FAILURE() << what << ": directed edge " << edge.first << "->" << edge.second << " not paired";
  }
  EXPECT_EQ(bad, 0) << what;
}

sweep::CurveSamples bezier2(std::vector<glm::dvec3> points, int steps) {
  return sweep::evaluate_bezier(points, steps, true);
}

std::vector<glm::dvec3> mirrored(std::vector<glm::dvec3> points) {
  for (auto& p : points) p.x = -p.x;
  return points;
}

std::vector<glm::dvec3> reversed(std::vector<glm::dvec3> points) {
  return {points.rbegin(), points.rend()};
}

// A bulging profile at x < 0, traced top to bottom.
const std::vector<glm::dvec3> kLeftProfile{{-1, 2, 0}, {-3, 1, 0}, {-2.5, -1, 0}, {-0.5, -2, 0}};

struct ProfileCase {
  std::string name;
  std::vector<glm::dvec3> points;
};

std::vector<ProfileCase> open_profiles() {
  return {{"left, top to bottom", kLeftProfile},
          {"right, top to bottom", mirrored(kLeftProfile)},
          {"left, bottom to top", reversed(kLeftProfile)},
          {"right, bottom to top", reversed(mirrored(kLeftProfile))}};
}

TEST(Revolution, NormalsPointAwayFromTheAxis) {
  for (const auto& profile : open_profiles()) {
    const sweep::Mesh mesh = sweep::build_surface_of_revolution(bezier2(profile.points, 12), 24);
    expect_unit_normals(mesh, profile.name);
    for (std::uint32_t i = 0; i < mesh.positions.size(); ++i) {
      const glm::dvec3 p = position(mesh, i);
      const glm::dvec3 radial(p.x, 0.0, p.z);
      EXPECT_GT(glm::dot(normal(mesh, i), radial), 0.0) << profile.name << " vertex " << i;
    }
  }
}

TEST(Revolution, WindingIsCounterclockwiseFromOutside) {
  for (const auto& profile : open_profiles()) {
    const sweep::Mesh mesh = sweep::build_surface_of_revolution(bezier2(profile.points, 12), 24);
    EXPECT_EQ(expect_counterclockwise(mesh, profile.name), static_cast<int>(mesh.triangle_count())) << profile.name;
  }
}

TEST(Revolution, TurnsCounterclockwiseAboutYSeenFromAbove) {
  // Copy j is the profile turned by 2 pi j / steps: x -> x cos, z -> -x sin.
  const sweep::CurveSamples profile = bezier2(kLeftProfile, 4);
  const int steps = 12;
  const sweep::Mesh mesh = sweep::build_surface_of_revolution(profile, steps);
  const std::size_t ring = profile.frames.size();
  ASSERT_EQ(mesh.vertex_count(), ring * steps);
  for (int j = 0; j < steps; ++j) {
    const double angle = 2.0 * std::numbers::pi * j / steps;
    for (std::size_t i = 0; i < ring; ++i) {
      const glm::dvec3 v = profile.frames[i].V;
      const glm::dvec3 expected(v.x * std::cos(angle), v.y, -v.x * std::sin(angle));
      EXPECT_LT(distance(position(mesh, static_cast<std::uint32_t>(static_cast<std::size_t>(j) * ring + i)), expected),
                1e-5);
    }
  }
}

TEST(Revolution, SeamAroundTheTurnIsClosed) {
  // An open profile leaves only its two end rings open: every boundary edge joins two copies of
  // the first or of the last profile sample.
  const int steps = 24;
  const sweep::CurveSamples profile = bezier2(kLeftProfile, 12);
  const std::size_t ring = profile.frames.size();
  const sweep::Mesh mesh = sweep::build_surface_of_revolution(profile, steps);
  const auto boundary = boundary_edges(mesh);
  EXPECT_EQ(boundary.size(), 2u * steps);
  for (const auto& [a, b] : boundary) {
    const std::size_t ia = a % ring, ib = b % ring;
    EXPECT_EQ(ia, ib) << a << "-" << b;
    EXPECT_TRUE(ia == 0 || ia == ring - 1) << a << "-" << b;
  }
  for (const auto& [edge, uses] : sweep::test::edge_uses(mesh)) EXPECT_LE(uses, 2);
}

TEST(Revolution, ClosedProfileHasNoBoundary) {
  for (int steps : {3, 30}) {
    const sweep::Mesh mesh = sweep::build_surface_of_revolution(sweep::evaluate_circle(1.0, 30), steps);
    EXPECT_TRUE(boundary_edges(mesh).empty()) << steps;
    EXPECT_EQ(mesh.vertex_count(), 30u * steps);  // the closed profile shares its seam sample
  }
}

TEST(Revolution, ClosedProfileOffTheAxisIsAWatertightOutwardTorus) {
  // A convex closed B-spline around (-3, 0): its revolution is a torus-like solid; normals point
  // away from the profile's center turned with it.
  const std::vector<glm::dvec3> square{{-2, 1, 0}, {-2, -1, 0}, {-4, -1, 0}, {-4, 1, 0},
                                       {-2, 1, 0}, {-2, -1, 0}, {-4, -1, 0}};
  for (const auto& points : {square, reversed(square)}) {
    const sweep::CurveSamples profile = sweep::evaluate_bspline(points, 6, true);
    ASSERT_TRUE(profile.closed);
    const int steps = 20;
    const sweep::Mesh mesh = sweep::build_surface_of_revolution(profile, steps);
    expect_unit_normals(mesh, "square torus");
    expect_watertight_and_consistently_oriented(mesh, "square torus");
    expect_counterclockwise(mesh, "square torus");
    const std::size_t ring = profile.frames.size() - 1;
    for (std::uint32_t i = 0; i < mesh.positions.size(); ++i) {
      const double angle = 2.0 * std::numbers::pi * static_cast<double>(i / ring) / steps;
      const glm::dvec3 center(-3.0 * std::cos(angle), 0.0, 3.0 * std::sin(angle));
      EXPECT_GT(glm::dot(normal(mesh, i), position(mesh, i) - center), 0.0) << i;
    }
  }
}

TEST(Cylinder, CircleAlongCircleIsTheAnalyticTorus) {
  const double r = 0.5, R = 2.0;
  const sweep::Mesh mesh =
      sweep::build_generalized_cylinder(sweep::evaluate_circle(r, 30), sweep::evaluate_circle(R, 60));
  EXPECT_EQ(mesh.vertex_count(), 30u * 60u);
  EXPECT_EQ(mesh.triangle_count(), 2u * 30u * 60u);
  expect_unit_normals(mesh, "torus");
  for (std::uint32_t i = 0; i < mesh.positions.size(); ++i) {
    const glm::dvec3 p = position(mesh, i);
    const double rho = std::hypot(p.x, p.y);
    const glm::dvec3 center_on_circle = R * glm::dvec3(p.x / rho, p.y / rho, 0.0);
    EXPECT_NEAR(distance(p, center_on_circle), r, 1e-6) << "vertex " << i;
    const glm::dvec3 outward = (p - center_on_circle) / r;
    EXPECT_LT(distance(normal(mesh, i), outward), 1e-5) << "vertex " << i;
  }
  expect_watertight_and_consistently_oriented(mesh, "torus");
  EXPECT_EQ(expect_counterclockwise(mesh, "torus"), static_cast<int>(mesh.triangle_count()));
}

TEST(Cylinder, ClockwiseClosedProfileStillHasOutwardNormals) {
  // The tor.swp torus with the profile traced clockwise (a mirrored B-spline circle).
  std::vector<glm::dvec3> ccw;
  for (int i = 0; i < 8; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / 8.0;
    ccw.emplace_back(0.5 * std::cos(angle), 0.5 * std::sin(angle), 0.0);
  }
  ccw.insert(ccw.end(), ccw.begin(), ccw.begin() + 3);
  for (const auto& points : {ccw, reversed(ccw)}) {
    const sweep::Mesh mesh =
        sweep::build_generalized_cylinder(sweep::evaluate_bspline(points, 4, true), sweep::evaluate_circle(2.0, 40));
    for (std::uint32_t i = 0; i < mesh.positions.size(); ++i) {
      const glm::dvec3 p = position(mesh, i);
      const double rho = std::hypot(p.x, p.y);
      EXPECT_GT(glm::dot(normal(mesh, i), p - 2.0 * glm::dvec3(p.x / rho, p.y / rho, 0.0)), 0.0) << i;
    }
    expect_watertight_and_consistently_oriented(mesh, "B-spline torus");
    expect_counterclockwise(mesh, "B-spline torus");
  }
}

TEST(Cylinder, OpenProfileAlongOpenSweepWindsWithItsNormals) {
  const sweep::CurveSamples profile = bezier2({{-1, 0, 0}, {-0.3, 0.5, 0}, {0.3, -0.5, 0}, {1, 0, 0}}, 10);
  const sweep::CurveSamples sweep_curve =
      sweep::evaluate_bezier(std::vector<glm::dvec3>{{0, 0, 0}, {1, 2, 1}, {3, -1, 2}, {4, 1, 3}}, 15, false);
  const sweep::Mesh mesh = sweep::build_generalized_cylinder(profile, sweep_curve);
  EXPECT_EQ(mesh.vertex_count(), 11u * 16u);
  EXPECT_EQ(mesh.triangle_count(), 2u * 10u * 15u);
  expect_unit_normals(mesh, "open sheet");
  expect_counterclockwise(mesh, "open sheet");
  // Open in both directions: the boundary is the outline of the 10 x 15 grid.
  EXPECT_EQ(boundary_edges(mesh).size(), 2u * (10u + 15u));
}

/// Expected mesh size of a surface from its curves' sample counts and closedness.
struct Grid {
  std::int64_t profile_samples;
  bool profile_closed;
  std::int64_t around;  // srev: STEPS copies (always closed); gcyl: sweep samples; birail: stations
  bool around_closed;
  bool revolution;
  std::int64_t cap_vertices = 0;   // caps: gcyl 2 rings; srev the centre and a ring per end off the axis
  std::int64_t cap_triangles = 0;  // gcyl 2 (ring - 2); srev STEPS per end off the axis
  std::int64_t bevels = 0;         // gcyl corners past the mitre limit: a ring and a strip each
  std::int64_t poles = 0;          // srev: profile samples on the axis, a fan (one triangle a copy) each
  std::int64_t collapsed = 0;      // gcyl, birail: triangles with two corners at one place, left out

  std::int64_t vertices() const {
    const std::int64_t ring = profile_closed ? profile_samples - 1 : profile_samples;
    const std::int64_t rings = revolution ? around : around_closed ? around - 1 : around;
    return ring * rings + cap_vertices + bevels * (ring + 4 * (profile_samples - 1));
  }
  std::int64_t triangles() const {
    const std::int64_t segments = profile_samples - 1;  // closed or not: one segment per pair of samples
    const std::int64_t ring_segments = revolution ? around : around - 1;
    return 2 * segments * (ring_segments + bevels) - poles * ring_segments + cap_triangles - collapsed;
  }
};

struct ExpectedSurface {
  int index;  // in the document
  Grid grid;
};

/// Worked out by hand from each file: samples = pieces * STEPS + 1 (Bezier: (N-1)/3 pieces,
/// B-spline: N-3, circle: STEPS + 1); a B-spline whose last 3 points repeat its first 3 is closed.
const std::map<std::string, std::vector<ExpectedSurface>> kExpectedSurfaces{
    // cr3 loop 12 steps, 5 points (closed): 4 * 12 + 1; circ section 12; cr2 profile 12 steps, 7 points
    // (open): 6 * 12 + 1, srev 32. A profile that ends on the axis (every srev here but a closed one)
    // has a pole there: one triangle a copy (a fan), not two.
    // birail: cr3 rails 10 steps, 6 points: 5 * 10 + 1, mirror images, so their 51 samples are at the
    // same fractions: 51 stations; bsp2 section 8 steps, 7 points: 4 * 8 + 1. The leaf's bez3 edges
    // (12 steps: 13 samples) are not mirror images: 24 stations (both ends shared); cr2 vein 2 * 8 + 1.
    // The leaf's edges meet at both tips: a station's ring is one point there, and the triangle
    // of each of the vein's 16 segments that has a side on it is left out.
    {"birail.swp", {{3, {33, false, 51, false, false}}, {7, {17, false, 24, false, false, 0, 0, 0, 0, 32}}}},
    // bez2 profile 24 steps, 10 points: 3 * 24 + 1 (open, from the axis), srev 48.
    {"bezier-vase.swp", {{1, {73, false, 48, true, true, 0, 0, 0, 1}}}},
    {"catmull-rom.swp", {{4, {73, false, 32, true, true, 0, 0, 0, 1}}, {7, {13, true, 49, true, false}}}},
    {"circles.swp", {}},
    {"core.swp", {}},
    // Corners keep one sample per joint (mitre). bez2 square 4 steps, 16 points: 5 * 4 + 1 (closed);
    // bez2 box 2 steps, 16 points: 5 * 2 + 1 (closed); inner as square; circ round 24;
    // bez3 bent 4 steps, 16 points: 5 * 4 + 1 (open); bez2 zigzag as bent, its three 157-degree
    // turns bevelled (the mitre would stretch 5.1 times), the 79-degree one mitred. Left out as
    // having no area: at two of the round tube's corners the inside of the ring is clipped onto the
    // same point by two rings (a triangle on each side of it), and at the zigzag's bevels each
    // strip folds on the bend's axis at the round profile's two points on it (two a bevel and point).
    {"corners.swp",
     {{2, {11, true, 21, true, false}},
      {5, {25, true, 21, true, false, 0, 0, 0, 0, 4}},
      {7, {25, true, 21, false, false}},
      {9, {25, true, 21, false, false, 0, 0, 3, 0, 12}}}},
    // bsp2 sweep 20 steps, 28 points (closed): 25 * 20 + 1; circ profile 50.
    {"flircle.swp", {{2, {51, true, 501, true, false}}}},
    // bsp2 profile 5 steps, 28 points (closed): 25 * 5 + 1; circ sweep 60.
    {"florus.swp", {{2, {126, true, 61, true, false}}}},
    // bsp2 profile 5 steps, 11 points (closed): 8 * 5 + 1; circ sweep 80.
    {"gentorus.swp", {{2, {41, true, 81, true, false}}}},
    // bez2 profile 50 steps, 4 points (open), srev 90.
    {"norm.swp", {{1, {51, false, 90, true, true}}}},
    // helix coil 32 per turn, 6 turns: 192 + 1 (open); circ wire 16.
    {"helix.swp", {{2, {17, true, 193, false, false}}}},
    // knot trefoil 240 and septafoil 600 (closed); circ tube 16, thin 12.
    {"knots.swp", {{4, {17, true, 241, true, false}}, {5, {13, true, 601, true, false}}}},
    // four kb2 curves of 5 points, 16 steps (open): 4 * 16 + 1; circ thin 12.
    {"kochanek-bartels.swp",
     {{5, {13, true, 65, false, false}},
      {6, {13, true, 65, false, false}},
      {7, {13, true, 65, false, false}},
      {8, {13, true, 65, false, false}}}},
    // kb2 star 3 steps, 11 points (closed): 10 * 3 + 1; bez3 bar 12 steps: 13; caps 2 * 30, 2 * 28.
    // bsp2 vase 10 steps, 7 points (open): 4 * 10 + 1, srev 48; both ends are off the axis (a
    // B-spline starts near, not at, its first point): two disks of 48 + 1 vertices, 48 triangles.
    // circ round 24 along bsp3 loop 8 steps, 7 points (closed): 4 * 8 + 1.
    {"solids.swp",
     {{2, {31, true, 13, false, false, 60, 56}},
      {4, {41, false, 48, true, true, 98, 96}},
      {7, {25, true, 33, true, false}}}},
    // cr2 flutes 4 steps, 17 points (closed): 16 * 4 + 1; bez3 shaft 12 steps: 13; caps 2 * 64,
    // 2 * 62. circ mouth 32; bsp3 spine 12 steps, 6 points: 3 * 12 + 1; caps 2 * 32, 2 * 30.
    {"taper.swp", {{3, {65, true, 13, false, false, 128, 124}}, {7, {33, true, 37, false, false, 64, 60}}}},
    // circ profile 30, circ sweep 60.
    {"tor.swp", {{2, {31, true, 61, true, false}}}},
    {"teapot.swp", {}},
    {"bspline-patch.swp", {}},
    // The lathe (srev chunky, 6 copies of 6 samples) under its subd; the cubes are cages.
    {"subdivision.swp", {{9, {6, false, 6, true, true, 0, 0, 0, 2}}}},
    // Imported from vase.svg: bez2 vase_profile 16 steps, 19 points (a line, three cubics and an
    // arc of 106 degrees in two pieces): 6 * 16 + 1 (open, from the axis), srev 48.
    {"vase.swp", {{1, {97, false, 48, true, true, 0, 0, 0, 1}}}},
    // bsp2 profile 8 steps, 11 points (closed): 8 * 8 + 1; bsp3 sweep 16 steps, 11 points (closed): 8 * 16 + 1.
    {"weird.swp", {{2, {65, true, 129, true, false}}}},
    // bsp2 profile 8 steps, 9 points (closed): 6 * 8 + 1; bsp3 sweep 16 steps, 10 points (closed): 7 * 16 + 1.
    {"weirder.swp", {{2, {49, true, 113, true, false}}}},
    // bsp2 profile 8 steps, 26 points (open): 23 * 8 + 1 = 185; srev 90.
    {"wineglass.swp", {{1, {185, false, 90, true, true, 0, 0, 0, 1}}}},
};

TEST(StarterSurfaces, WorkedExamplesOfTheCountFormulas) {
  const Grid wineglass{185, false, 90, true, true, 0, 0, 0, 1};  // its profile starts on the axis
  EXPECT_EQ(wineglass.vertices(), 16650);
  EXPECT_EQ(wineglass.triangles(), 2 * 184 * 90 - 90);
  const Grid tor{31, true, 61, true, false};
  EXPECT_EQ(tor.vertices(), 30 * 60);
  EXPECT_EQ(tor.triangles(), 2 * 30 * 60);
}

TEST(StarterSurfaces, VertexAndTriangleCountsFollowTheFormulas) {
  const auto files = sweep::test::starter_files();
  ASSERT_FALSE(files.empty());
  for (const auto& file : files) {
    const std::string name = file.filename().string();
    const auto expected = kExpectedSurfaces.find(name);
    ASSERT_NE(expected, kExpectedSurfaces.end()) << "no expected counts for the starter file " << name;
    const sweep::Document doc = sweep::io::load_swp_file(file);
    const sweep::Scene scene = sweep::evaluate_document(doc);
    std::size_t surfaces = 0;
    // Swept surfaces only: patches, cages and subdivision surfaces have their own count tests
    // (patch_test.cpp, subdivision_test.cpp).
    for (const auto& object : doc.objects) surfaces += sweep::swept_curves(object).profile >= 0 ? 1 : 0;
    EXPECT_EQ(surfaces, expected->second.size()) << name;
    for (const ExpectedSurface& s : expected->second) {
      ASSERT_LT(static_cast<std::size_t>(s.index), doc.objects.size()) << name;
      const sweep::Object& object = doc.objects[static_cast<std::size_t>(s.index)];
      ASSERT_TRUE(sweep::is_surface(object.kind())) << name;
      // The hand-worked sample counts are the ones the document's curves have.
      const auto& profile_samples =
          scene.objects[static_cast<std::size_t>(object.as<sweep::ProfilePart>().profile)].curve.frames;
      EXPECT_EQ(static_cast<std::int64_t>(profile_samples.size()), s.grid.profile_samples) << name;
      if (object.kind() == sweep::ObjectKind::GeneralizedCylinder) {
        EXPECT_EQ(
            static_cast<std::int64_t>(
                scene.objects[static_cast<std::size_t>(object.as<sweep::CylinderSurface>().sweep)].curve.frames.size()),
            s.grid.around)
            << name;
      } else if (object.kind() == sweep::ObjectKind::Birail) {
        // Stations: every sample of either rail, merged where they fall at the same fraction.
        const auto samples = [&](int index) {
          return static_cast<std::int64_t>(scene.objects[static_cast<std::size_t>(index)].curve.frames.size());
        };
        const sweep::BirailSurface& birail = object.as<sweep::BirailSurface>();
        EXPECT_GE(s.grid.around, std::max(samples(birail.rail1), samples(birail.rail2))) << name;
        EXPECT_LE(s.grid.around, samples(birail.rail1) + samples(birail.rail2) - 2) << name;
      } else {
        EXPECT_EQ(object.as<sweep::CopiesPart>().copies, s.grid.around) << name;
      }
      const sweep::Mesh& mesh = scene.objects[static_cast<std::size_t>(s.index)].mesh;
      EXPECT_EQ(static_cast<std::int64_t>(mesh.vertex_count()), s.grid.vertices()) << name;
      EXPECT_EQ(static_cast<std::int64_t>(mesh.triangle_count()), s.grid.triangles()) << name;
    }
  }
}

/// Sweep samples near which a generalized cylinder can fold: the sweep's radius of curvature
/// (from neighbouring samples) is not clearly larger than the profile's distance from its origin.
std::vector<bool> folding_sweep_samples(const sweep::CurveSamples& profile, const sweep::CurveSamples& sweep_curve) {
  double profile_radius = 0.0;
  for (const auto& f : profile.frames) profile_radius = std::max(profile_radius, glm::length(f.V));
  const auto& s = sweep_curve.frames;
  std::vector<bool> folds(s.size(), false);
  for (std::size_t j = 1; j + 1 < s.size(); ++j) {
    const double curvature = glm::length(s[j + 1].T - s[j - 1].T) / glm::length(s[j + 1].V - s[j - 1].V);
    if (curvature * profile_radius > 0.8) folds[j - 1] = folds[j] = folds[j + 1] = true;
  }
  return folds;
}

TEST(StarterSurfaces, NormalsUnitWindingCounterclockwiseSeamsClosed) {
  for (const auto& file : sweep::test::starter_files()) {
    const sweep::Document doc = sweep::io::load_swp_file(file);
    const sweep::Scene scene = sweep::evaluate_document(doc);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      const sweep::Object& object = doc.objects[i];
      if (!sweep::is_surface(object.kind())) continue;
      const std::string what = file.filename().string() + " " + sweep::display_name(doc, static_cast<int>(i));
      const sweep::Mesh& mesh = scene.objects[i].mesh;
      expect_unit_normals(mesh, what);
      if (sweep::swept_curves(object).profile < 0) {
        // Patches, cages and subdivision surfaces (patch_test.cpp and subdivision_test.cpp check
        // which of them close): counterclockwise, and no edge in more than two triangles.
        EXPECT_GT(expect_counterclockwise(mesh, what), 0) << what;
        for (const auto& [edge, uses] : sweep::test::edge_uses(mesh)) EXPECT_LE(uses, 2) << what;
        continue;
      }
      const sweep::CurveSamples& profile =
          scene.objects[static_cast<std::size_t>(object.as<sweep::ProfilePart>().profile)].curve;
      if (object.kind() == sweep::ObjectKind::GeneralizedCylinder) {
        // Where the sweep bends tighter than the profile is wide, the tube folds over itself
        // (flircle.swp: radius 0.4 along a sweep with radii of curvature down to 0.11) and the
        // folded triangles face inwards whatever the normals; only those are excused.
        const sweep::CurveSamples& sweep_curve =
            scene.objects[static_cast<std::size_t>(object.as<sweep::CylinderSurface>().sweep)].curve;
        const std::vector<bool> folds = folding_sweep_samples(profile, sweep_curve);
        const std::size_t ring = profile.closed ? profile.frames.size() - 1 : profile.frames.size();
        const auto excused = [&](std::uint32_t v) { return folds[v / ring]; };
        const auto folded = static_cast<std::size_t>(std::count(folds.begin(), folds.end(), true));
        EXPECT_LT(folded * 2, folds.size()) << what << ": most of the sweep folds";
        EXPECT_GT(expect_counterclockwise(mesh, what, excused), 0) << what;
      } else {
        EXPECT_GT(expect_counterclockwise(mesh, what), 0) << what;
      }
      for (std::uint32_t index : mesh.indices) ASSERT_LT(index, mesh.vertex_count()) << what;
      const bool profile_closed =
          scene.objects[static_cast<std::size_t>(object.as<sweep::ProfilePart>().profile)].curve.closed;
      const bool sweep_closed = object.kind() == sweep::ObjectKind::SurfaceOfRevolution ||
                                scene.objects[static_cast<std::size_t>(sweep::swept_curves(object).path)].curve.closed;
      // Rings clipped onto one point at a corner leave out the triangles of no area between them
      // (add_quad_without_collapsed): such a tube is closed welded by position, as STL readers weld.
      const sweep::MeshTopology welded = sweep::mesh_topology(mesh);
      if (profile_closed && sweep_closed && welded.welded_vertices < mesh.vertex_count()) {
        EXPECT_TRUE(welded.closed_manifold()) << what;
      } else if (profile_closed && sweep_closed) {
        expect_watertight_and_consistently_oriented(mesh, what);
      } else {
        for (const auto& [edge, uses] : sweep::test::edge_uses(mesh)) EXPECT_LE(uses, 2) << what;
      }
    }
  }
}

}  // namespace
