// Sharp corners of piecewise Bezier sweeps: the joint sample keeps its place (sample counts as
// before) and the profile lies in the mitre plane, stretched across the bend, so a square path
// makes a clean square tube: every vertex at the profile's distance from both segments, no pinch,
// no folded triangle.
#include "geometry/curves/curve.hpp"
#include "geometry/surfaces/surface.hpp"
#include "io/swp/read.hpp"

#include "model/evaluation/curve_evaluation.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace {

using sweep::test::distance;

double distance_to_line(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& direction) {
  const glm::dvec3 d = glm::normalize(direction);
  const glm::dvec3 v = p - a;
  return glm::length(v - glm::dot(v, d) * d);
}

double distance_to_segment(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double t = std::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return distance(p, a + t * ab);
}

struct Path {
  sweep::Object curve;
  std::vector<glm::dvec3> corners;  // the polyline the Bezier path follows (control points 0, 3, 6, ...)
};

Path path_named(const sweep::Document& doc, const std::string& name) {
  Path path{doc.objects[static_cast<std::size_t>(doc.find(name))], {}};
  for (std::size_t k = 0; k < path.curve.as<sweep::PointsPart>().points.size(); k += 3)
    path.corners.push_back(path.curve.as<sweep::PointsPart>().points[k]);
  return path;
}

/// Every vertex of a round tube of radius r along a polyline path lies at distance >= r from the
/// path (no pinch), at exactly r from its own segment away from the corners, and at a corner ring
/// at exactly r from the lines of both segments that meet there (a clean mitre). No triangle faces
/// against its vertex normals (no fold).
void expect_clean_tube(const sweep::Mesh& mesh, const sweep::CurveSamples& sweep_curve, const Path& path, double r,
                       std::size_t ring, const std::string& what) {
  const auto& corners = path.corners;
  const std::size_t steps = static_cast<std::size_t>(path.curve.as<sweep::StepsPart>().steps);
  for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::dvec3 p(mesh.positions[v]);
    double nearest = 1e300;
    for (std::size_t k = 0; k + 1 < corners.size(); ++k)
      nearest = std::min(nearest, distance_to_segment(p, corners[k], corners[k + 1]));
    EXPECT_GT(nearest, r * (1.0 - 1e-5)) << what << " vertex " << v << " pinches in";
    const std::size_t sample = v / ring;
    const std::size_t piece = sample / steps;
    if (sample % steps != 0 || sample == 0 || piece + 1 >= corners.size()) {
      if (sample % steps != 0) {
        EXPECT_NEAR(distance_to_line(p, corners[piece], corners[piece + 1] - corners[piece]), r, 1e-5 * r)
            << what << " " << v;
      }
      continue;
    }
    // A joint: corners[piece] is where segment piece - 1 meets segment piece.
    const glm::dvec3& c = corners[piece];
    EXPECT_NEAR(distance_to_line(p, c, c - corners[piece - 1]), r, 1e-5 * r) << what << " corner vertex " << v;
    EXPECT_NEAR(distance_to_line(p, c, corners[piece + 1] - c), r, 1e-5 * r) << what << " corner vertex " << v;
  }
  int folded = 0;
  int slivers = 0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a(mesh.positions[mesh.indices[t]]), b(mesh.positions[mesh.indices[t + 1]]),
        c(mesh.positions[mesh.indices[t + 2]]);
    const glm::dvec3 n = glm::dvec3(mesh.normals[mesh.indices[t]]) + glm::dvec3(mesh.normals[mesh.indices[t + 1]]) +
                         glm::dvec3(mesh.normals[mesh.indices[t + 2]]);
    const glm::dvec3 geometric = glm::cross(b - a, c - a);
    // Rings that reach the mitre plane are clipped onto it, onto the points the rings nearer the
    // corner have there: the triangles between them would have no area and are left out.
    if (glm::length(geometric) <= 1e-6 * r * r) {
      ++slivers;
      continue;
    }
    if (glm::dot(geometric, n) <= 0.0) ++folded;
  }
  EXPECT_EQ(folded, 0) << what;
  EXPECT_EQ(slivers, 0) << what;
  (void)sweep_curve;
}

TEST(Corners, JointsWithATangentJumpAreCornersWithTheirArrivingTangent) {
  const sweep::Document doc = sweep::io::load_swp_file(SWEEP_SWP_DIR "/corners.swp");
  for (const char* name : {"square", "inner", "bent"}) {
    const Path path = path_named(doc, name);
    const sweep::CurveSamples curve = sweep::evaluate_curve(path.curve);
    ASSERT_EQ(static_cast<std::int64_t>(curve.frames.size()), sweep::curve_sample_count(path.curve)) << name;
    const std::size_t steps = static_cast<std::size_t>(path.curve.as<sweep::StepsPart>().steps);
    ASSERT_EQ(curve.corners.size(), path.corners.size() - 2) << name;  // every interior joint
    for (std::size_t k = 0; k < curve.corners.size(); ++k) {
      const sweep::Corner& corner = curve.corners[k];
      EXPECT_EQ(corner.sample, (k + 1) * steps) << name;
      const glm::dvec3 arriving = glm::normalize(path.corners[k + 1] - path.corners[k]);
      const glm::dvec3 leaving = glm::normalize(path.corners[k + 2] - path.corners[k + 1]);
      EXPECT_LT(distance(corner.incoming, arriving), 1e-12) << name;
      EXPECT_LT(distance(curve.frames[corner.sample].T, leaving), 1e-12) << name;
    }
  }
}

TEST(Corners, SmoothStarterCurvesHaveNone) {
  for (const char* file :
       {"weird.swp", "weirder.swp", "flircle.swp", "florus.swp", "gentorus.swp", "tor.swp", "core.swp"}) {
    const sweep::Document doc = sweep::io::load_swp_file(std::string(SWEEP_SWP_DIR) + "/" + file);
    for (const sweep::Object& object : doc.objects) {
      if (sweep::is_curve(object.kind())) {
        EXPECT_TRUE(sweep::evaluate_curve(object).corners.empty()) << file;
      }
    }
  }
}

TEST(Corners, SquareAndBentPathsMakeCleanMitredTubes) {
  const sweep::Document doc = sweep::io::load_swp_file(SWEEP_SWP_DIR "/corners.swp");
  const sweep::Object& round = doc.objects[static_cast<std::size_t>(doc.find("round"))];
  const sweep::CurveSamples profile = sweep::evaluate_curve(round);
  for (const char* name : {"inner", "bent"}) {
    for (const auto method : {sweep::FrameMethod::RotationMinimizing, sweep::FrameMethod::Projection}) {
      const Path path = path_named(doc, name);
      const sweep::CurveSamples sweep_curve = sweep::evaluate_curve(path.curve, {method});
      const sweep::Mesh mesh = sweep::build_generalized_cylinder(profile, sweep_curve);
      expect_clean_tube(mesh, sweep_curve, path, round.as<sweep::RadiusPart>().radius, profile.frames.size() - 1, name);
    }
  }
}

TEST(Corners, DenseSamplesNearACornerAreClippedAtTheMitreInsteadOfFolding) {
  // With 40 samples per unit side, several rings lie within r of each corner and would reach
  // through the mitre plane on the inside of the bend.
  sweep::Document doc = sweep::io::load_swp_file(SWEEP_SWP_DIR "/corners.swp");
  for (const char* name : {"inner", "bent"}) {
    Path path = path_named(doc, name);
    path.curve.as<sweep::StepsPart>().steps = 40;
    const sweep::CurveSamples profile = sweep::evaluate_circle(0.25, 16);
    const sweep::CurveSamples sweep_curve = sweep::evaluate_curve(path.curve);
    const sweep::Mesh mesh = sweep::build_generalized_cylinder(profile, sweep_curve);
    expect_clean_tube(mesh, sweep_curve, path, 0.25, 16, name);
  }
}

TEST(Corners, WithoutTheMitreTheCornerPinches) {
  // The check above can fail: dropping the corner information (the original tool's placement,
  // the profile square to the leaving tangent) brings corner vertices closer than r to the path.
  const sweep::Document doc = sweep::io::load_swp_file(SWEEP_SWP_DIR "/corners.swp");
  const sweep::CurveSamples profile = sweep::evaluate_curve(doc.objects[static_cast<std::size_t>(doc.find("round"))]);
  const Path path = path_named(doc, "inner");
  sweep::CurveSamples sweep_curve = sweep::evaluate_curve(path.curve);
  sweep_curve.corners.clear();
  const sweep::Mesh mesh = sweep::build_generalized_cylinder(profile, sweep_curve);
  double nearest = 1e300;
  for (const auto& v : mesh.positions) {
    for (std::size_t k = 0; k + 1 < path.corners.size(); ++k) {
      nearest = std::min(nearest, distance_to_segment(glm::dvec3(v), path.corners[k], path.corners[k + 1]));
    }
  }
  EXPECT_LT(nearest, 0.25 * 0.9);
}

TEST(Corners, HairpinsStayFiniteAndTheMitreIsLimited) {
  // Turns of 170, 179.9 and exactly 180 degrees: no NaN, no spike longer than the mitre limit.
  for (const double end_y : {0.17, 1e-3, 0.0}) {
    const std::vector<glm::dvec3> points{
        {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {2, end_y / 3, 0.0}, {1, 2 * end_y / 3, 0}, {0, end_y, 0}};
    for (const bool planar : {true, false}) {
      const sweep::CurveSamples sweep_curve = sweep::evaluate_bezier(points, 3, planar);
      const sweep::Mesh mesh = sweep::build_generalized_cylinder(sweep::evaluate_circle(0.1, 12), sweep_curve);
      for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::dvec3 p(mesh.positions[v]), n(mesh.normals[v]);
        ASSERT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) << end_y;
        ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z)) << end_y;
        EXPECT_NEAR(glm::length(n), 1.0, 1e-6);
        if (v / 12 == 3) {
          EXPECT_LE(distance(p, glm::dvec3(3, 0, 0)), 0.1 * sweep::kMitreLimit * (1 + 1e-6)) << end_y;
        }
      }
    }
  }
}

}  // namespace
