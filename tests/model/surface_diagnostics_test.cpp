// Pole normals of surfaces of revolution, and the diagnostics of generalized cylinders: seam
// angle, total twist and the folds where the profile reaches beyond the sweep's radius of curvature.
#include "geometry/curves/curve.hpp"
#include "geometry/surfaces/surface.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"

#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>

namespace {

using sweep::test::distance;

std::vector<glm::dvec3> mirrored(std::vector<glm::dvec3> points) {
  for (auto& p : points) p.x = -p.x;
  return points;
}
std::vector<glm::dvec3> reversed(std::vector<glm::dvec3> points) {
  return {points.rbegin(), points.rend()};
}

// A spinning top: from the apex (0, 2) on the axis out to (-1.5, 0) and back to the axis at (0, -1),
// meeting the axis at an angle at both ends.
const std::vector<glm::dvec3> kTop{{0, 2, 0},         {-0.5, 4.0 / 3, 0},  {-1, 2.0 / 3, 0}, {-1.5, 0, 0},
                                   {-1, -1.0 / 3, 0}, {-0.5, -2.0 / 3, 0}, {0, -1, 0}};

// The top meets the axis at an angle at both ends: its tips are cone points, where each copy's
// vertex takes the normal of the faces beside it (out of the solid), not the axis (issue 26).
TEST(RevolutionPoles, ConePointsOnTheAxisTakeTheirFacesNormalsOutOfTheSolid) {
  for (const auto& points : {kTop, mirrored(kTop), reversed(kTop), reversed(mirrored(kTop))}) {
    const sweep::Mesh mesh = sweep::build_surface_of_revolution(sweep::evaluate_bezier(points, 6, true), 16);
    int tips = 0;
    for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
      const glm::dvec3 p(mesh.positions[v]), n(mesh.normals[v]);
      ASSERT_NEAR(glm::length(n), 1.0, 1e-6);
      if (std::hypot(p.x, p.z) < 1e-9) {
        ++tips;
        EXPECT_EQ(n.y > 0.0, p.y > 0.5) << "out of the solid at y = " << p.y;
        EXPECT_LT(std::abs(n.y), 0.99) << "a cone point, not a smooth pole, at y = " << p.y;
      } else {
        EXPECT_GT(glm::dot(n, glm::dvec3(p.x, 0.0, p.z)), 0.0) << v;  // still outward elsewhere
      }
    }
    EXPECT_EQ(tips, 2 * 16);
  }
}

TEST(RevolutionPoles, AProfileCrossingTheAxisAtAnAngleKeepsTheConeNormalWhereItCrosses) {
  // A straight line from (-1, 1) to (1, -1): a double cone; its middle sample is on the axis.
  const std::vector<glm::dvec3> line{{-1, 1, 0}, {-1.0 / 3, 1.0 / 3, 0}, {1.0 / 3, -1.0 / 3, 0}, {1, -1, 0}};
  const sweep::Mesh mesh = sweep::build_surface_of_revolution(sweep::evaluate_bezier(line, 4, true), 12);
  int crossings = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::dvec3 p(mesh.positions[v]), n(mesh.normals[v]);
    ASSERT_TRUE(std::isfinite(n.x) && std::isfinite(n.y) && std::isfinite(n.z));
    EXPECT_NEAR(glm::length(n), 1.0, 1e-6);
    if (glm::length(p) < 1e-9) {
      ++crossings;
      EXPECT_NEAR(std::abs(n.y), std::sqrt(0.5), 1e-6) << "the 45-degree cone's own normal";
    }
  }
  EXPECT_EQ(crossings, 12);
}

TEST(RevolutionPoles, WineglassEndsOnTheAxisPointUpAndDown) {
  const sweep::Document doc = sweep::io::load_swp_file(SWEEP_SWP_DIR "/wineglass.swp");
  const sweep::Scene scene = sweep::evaluate_document(doc);
  const sweep::Mesh& mesh = scene.objects[static_cast<std::size_t>(doc.find("wineglass"))].mesh;
  double lowest = 1e300;
  glm::dvec3 lowest_normal(0.0);
  int poles = 0;
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::dvec3 p(mesh.positions[v]), n(mesh.normals[v]);
    if (std::hypot(p.x, p.z) > 1e-9) continue;
    ++poles;
    EXPECT_EQ(std::abs(n.y), 1.0) << v;
    if (p.y < lowest) {
      lowest = p.y;
      lowest_normal = n;
    }
  }
  EXPECT_GT(poles, 0);
  EXPECT_EQ(lowest_normal, glm::dvec3(0, -1, 0));  // the foot's underside faces down
}

/// |kappa| of a uniform cubic B-spline piece at t, from its derivatives (the second by central
/// differences of the textbook first derivative).
double bspline_curvature(const std::vector<glm::dvec3>& points, std::size_t piece, double t) {
  const double h = 1e-5;
  const glm::dvec3 d1 = sweep::test::direct_bspline_derivative(points, piece, t);
  const glm::dvec3 d2 = (sweep::test::direct_bspline_derivative(points, piece, t + h) -
                         sweep::test::direct_bspline_derivative(points, piece, t - h)) /
                        (2.0 * h);
  return glm::length(glm::cross(d1, d2)) / std::pow(glm::length(d1), 3.0);
}

TEST(SweepDiagnostics, FlircleFoldsExactlyWhereTheProfileReachesBeyondTheRadiusOfCurvature) {
  const sweep::Document doc = sweep::io::load_swp_file(SWEEP_SWP_DIR "/flircle.swp");
  const sweep::Scene scene = sweep::evaluate_document(doc);
  const sweep::Object& surface = doc.objects[static_cast<std::size_t>(doc.find("flircle"))];
  const sweep::Object& sweep_object = doc.objects[static_cast<std::size_t>(surface.as<sweep::CylinderSurface>().sweep)];
  const double r =
      doc.objects[static_cast<std::size_t>(surface.as<sweep::ProfilePart>().profile)].as<sweep::RadiusPart>().radius;
  const sweep::SweepDiagnostics& d = scene.objects[static_cast<std::size_t>(doc.find("flircle"))].diagnostics;
  ASSERT_FALSE(d.folds.empty());
  const auto steps = static_cast<std::size_t>(sweep_object.as<sweep::StepsPart>().steps);
  const std::size_t samples =
      scene.objects[static_cast<std::size_t>(surface.as<sweep::CylinderSurface>().sweep)].curve.frames.size() -
      1;  // closed
  std::vector<bool> in_fold(samples, false);
  for (const sweep::FoldRange& fold : d.folds) {
    ASSERT_LE(fold.first_sample, fold.last_sample);
    EXPECT_DOUBLE_EQ(fold.t_begin, static_cast<double>(fold.first_sample) / static_cast<double>(steps));
    EXPECT_DOUBLE_EQ(fold.t_end, static_cast<double>(fold.last_sample) / static_cast<double>(steps));
    for (int j = fold.first_sample; j <= fold.last_sample; ++j) in_fold[static_cast<std::size_t>(j)] = true;
  }
  for (std::size_t j = 0; j < samples; ++j) {
    const double reach = r * bspline_curvature(sweep_object.as<sweep::PointsPart>().points, j / steps,
                                               static_cast<double>(j % steps) / static_cast<double>(steps));
    if (std::abs(reach - 1.0) < 1e-3) continue;  // too close to call with finite differences
    EXPECT_EQ(in_fold[j], reach >= 1.0) << "sample " << j << ": |kappa| r = " << reach;
  }
}

TEST(SweepDiagnostics, TheToriAndWeirdTubesDoNotFold) {
  for (const char* file : {"tor.swp", "gentorus.swp", "florus.swp", "weird.swp", "weirder.swp", "corners.swp"}) {
    const sweep::Document doc = sweep::io::load_swp_file(std::string(SWEEP_SWP_DIR) + "/" + file);
    const sweep::Scene scene = sweep::evaluate_document(doc);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      if (doc.objects[i].kind() == sweep::ObjectKind::GeneralizedCylinder) {
        EXPECT_TRUE(scene.objects[i].diagnostics.folds.empty()) << file << " " << doc.objects[i].name;
      }
    }
  }
}

TEST(SweepDiagnostics, SeamAngleAndTwist) {
  // Planar closed sweeps need no correction and do not twist.
  for (const char* file : {"tor.swp", "gentorus.swp", "florus.swp"}) {
    const sweep::Document doc = sweep::io::load_swp_file(std::string(SWEEP_SWP_DIR) + "/" + file);
    const sweep::Scene scene = sweep::evaluate_document(doc);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      if (doc.objects[i].kind() != sweep::ObjectKind::GeneralizedCylinder) continue;
      const sweep::SweepDiagnostics& d = scene.objects[i].diagnostics;
      EXPECT_TRUE(d.closed) << file;
      EXPECT_EQ(d.seam_angle, 0.0) << file;
      EXPECT_LT(d.total_twist, 1e-9) << file;
    }
  }
  // weirder: rotation-minimizing frames twist only by the spread seam angle, all one way.
  const sweep::Document doc = sweep::io::load_swp_file(SWEEP_SWP_DIR "/weirder.swp");
  const auto surface = static_cast<std::size_t>(doc.find("weirder"));
  const auto sweep_index = static_cast<std::size_t>(doc.objects[surface].as<sweep::CylinderSurface>().sweep);
  const sweep::Scene scene = sweep::evaluate_document(doc);
  const sweep::SweepDiagnostics& d = scene.objects[surface].diagnostics;
  EXPECT_EQ(d.seam_angle, scene.objects[sweep_index].curve.seam_angle);
  EXPECT_GT(std::abs(d.seam_angle), 0.1);
  EXPECT_NEAR(d.total_twist, std::abs(d.seam_angle), 1e-9);
  // Without the correction the rotation-minimizing tube does not twist at all (and has a seam).
  sweep::EvaluationOptions raw;
  raw.frames.close_seam = false;
  const sweep::Scene uncorrected = sweep::evaluate_document(doc, raw);
  EXPECT_EQ(uncorrected.objects[surface].diagnostics.seam_angle, 0.0);
  EXPECT_LT(uncorrected.objects[surface].diagnostics.total_twist, 1e-12);
  // Projection frames twist on their own: more in total than the correction alone.
  sweep::EvaluationOptions projection;
  projection.frames.method = sweep::FrameMethod::Projection;
  const sweep::Scene projected = sweep::evaluate_document(doc, projection);
  EXPECT_GT(projected.objects[surface].diagnostics.total_twist,
            std::abs(projected.objects[surface].diagnostics.seam_angle));
}

TEST(SweepDiagnostics, OpenSweepsAndOtherObjects) {
  const sweep::Document doc = sweep::io::load_swp_file(SWEEP_SWP_DIR "/corners.swp");
  const sweep::Scene scene = sweep::evaluate_document(doc);
  const sweep::SweepDiagnostics& bent = scene.objects[static_cast<std::size_t>(doc.find("benttube"))].diagnostics;
  EXPECT_FALSE(bent.closed);
  EXPECT_EQ(bent.seam_angle, 0.0);
  EXPECT_LT(bent.total_twist, 1e-9);  // rotation-minimizing, open: no twist at all
  const sweep::SweepDiagnostics& curve = scene.objects[static_cast<std::size_t>(doc.find("bent"))].diagnostics;
  EXPECT_FALSE(curve.closed);
  EXPECT_TRUE(curve.folds.empty());
}

}  // namespace
