// Torus knots: every sample on the torus, STEPS + 1 samples with the last exactly the first and
// closed frames, P turns about the axis and Q through the hole, tangents and curvature of the
// parametric formula, and a tube along each knot that is watertight with a seamless seam.
#include "geometry/curves/torus_knot.hpp"
#include "model/evaluation/scene.hpp"

#include "model/evaluation/curve_evaluation.hpp"
#include "support/core_test_support.hpp"
#include "support/curve_kinds_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

namespace {

using sweep::TorusKnotShape;
using sweep::test::distance;

constexpr double kTwoPi = 2.0 * std::numbers::pi;

const TorusKnotShape kKnots[] = {{2, 3, 2.0, 1.0}, {3, 2, 2.0, 1.0}, {3, 7, 5.0, 0.8},
                                 {2, 5, 1.0, 0.3}, {5, 2, 1e6, 2e5}, {1, 1, 1e-6, 1e-7}};

std::string describe(const TorusKnotShape& k) {
  // Appended piece by piece: "(" + std::to_string(...) trips GCC 12's bogus -Wrestrict.
  std::string text = "knot P ";
  text += std::to_string(k.p);
  text += " Q ";
  text += std::to_string(k.q);
  text += " R ";
  text += std::to_string(k.major_radius);
  return text;
}

/// The knot's formula, for finite differences independent of the evaluation.
glm::dvec3 knot_at(const TorusKnotShape& k, double t) {
  const double rho = k.major_radius + k.minor_radius * std::cos(k.q * t);
  return {rho * std::cos(k.p * t), rho * std::sin(k.p * t), k.minor_radius * std::sin(k.q * t)};
}

TEST(TorusKnot, SamplesLieOnTheTorus) {
  for (const TorusKnotShape& k : kKnots) {
    const sweep::CurveSamples curve = sweep::evaluate_torus_knot(k, 300);
    for (std::size_t i = 0; i < curve.frames.size(); ++i) {
      const glm::dvec3& v = curve.frames[i].V;
      const double from_tube_centre = std::hypot(std::hypot(v.x, v.y) - k.major_radius, v.z);
      EXPECT_NEAR(from_tube_centre, k.minor_radius, 1e-12 * k.major_radius) << describe(k) << " sample " << i;
    }
  }
}

TEST(TorusKnot, IsClosedWithTheLastSampleExactlyTheFirst) {
  for (const TorusKnotShape& k : kKnots) {
    for (const int steps : {3, 17, 240}) {
      const sweep::CurveSamples curve = sweep::evaluate_torus_knot(k, steps);
      ASSERT_EQ(curve.frames.size(), static_cast<std::size_t>(steps) + 1);
      EXPECT_TRUE(curve.closed);
      EXPECT_TRUE(sweep::is_closed(curve.frames));
      EXPECT_EQ(curve.frames.front().V, curve.frames.back().V);
      EXPECT_EQ(curve.frames.front().T, curve.frames.back().T);
      EXPECT_LT(distance(curve.frames.front().N, curve.frames.back().N), 1e-12) << describe(k);
      EXPECT_TRUE(std::isfinite(curve.seam_angle));
    }
  }
  // Without the seam correction the end frame is only propagated (the original tool's seam).
  const sweep::CurveSamples open_seam = sweep::evaluate_torus_knot(kKnots[0], 240, {.close_seam = false});
  EXPECT_EQ(open_seam.seam_angle, 0.0);
  EXPECT_TRUE(open_seam.closed);
}

TEST(TorusKnot, WindsPTimesAboutTheAxisAndQTimesThroughTheHole) {
  for (const TorusKnotShape& k : kKnots) {
    const sweep::CurveSamples curve = sweep::evaluate_torus_knot(k, 720);
    double about_axis = 0.0, through_hole = 0.0;
    for (std::size_t i = 1; i < curve.frames.size(); ++i) {
      const glm::dvec3 &u = curve.frames[i - 1].V, &v = curve.frames[i].V;
      about_axis += std::atan2(u.x * v.y - u.y * v.x, u.x * v.x + u.y * v.y);
      // The angle about the tube's centre circle, in the plane of the axis and the sample.
      const auto tube_angle = [&](const glm::dvec3& w) {
        return std::atan2(w.z, std::hypot(w.x, w.y) - k.major_radius);
      };
      through_hole += std::remainder(tube_angle(v) - tube_angle(u), kTwoPi);
    }
    EXPECT_NEAR(about_axis, kTwoPi * k.p, 1e-9) << describe(k);
    EXPECT_NEAR(through_hole, kTwoPi * k.q, 1e-9) << describe(k);
  }
}

TEST(TorusKnot, TangentAndCurvatureFollowTheFormula) {
  for (const TorusKnotShape& k : kKnots) {
    const int steps = 400;
    const sweep::CurveSamples curve = sweep::evaluate_torus_knot(k, steps);
    for (int i = 0; i < steps; i += 7) {
      const double t = kTwoPi * i / steps, h = 1e-4;
      const glm::dvec3 d1 = (knot_at(k, t + h) - knot_at(k, t - h)) / (2.0 * h);
      const glm::dvec3 d2 = (knot_at(k, t + h) - 2.0 * knot_at(k, t) + knot_at(k, t - h)) / (h * h);
      const double curvature = glm::length(glm::cross(d1, d2)) / std::pow(glm::length(d1), 3.0);
      const auto index = static_cast<std::size_t>(i);
      EXPECT_LT(distance(curve.frames[index].T, glm::normalize(d1)), 1e-7) << describe(k) << " sample " << i;
      EXPECT_NEAR(curve.curvature[index], curvature, 1e-5 * curvature) << describe(k) << " sample " << i;
    }
    EXPECT_EQ(curve.curvature.back(), curve.curvature.front());
  }
}

/// A document with the knot, a small circle and the tube of the circle along the knot.
sweep::Document tube_document(const TorusKnotShape& k, int steps) {
  sweep::Document doc;
  sweep::Object knot;
  knot.set_kind(sweep::ObjectKind::TorusKnot);
  knot.name = "knot";
  knot.as<sweep::StepsPart>().steps = steps;
  knot.as<sweep::TorusKnotCurve>().knot_p = k.p;
  knot.as<sweep::TorusKnotCurve>().knot_q = k.q;
  knot.as<sweep::TorusKnotCurve>().major_radius = k.major_radius;
  knot.as<sweep::RadiusPart>().radius = k.minor_radius;
  sweep::Object circle;
  circle.set_kind(sweep::ObjectKind::Circle);
  circle.name = "section";
  circle.as<sweep::StepsPart>().steps = 12;
  circle.as<sweep::RadiusPart>().radius = 0.05 * k.minor_radius;
  sweep::Object tube;
  tube.set_kind(sweep::ObjectKind::GeneralizedCylinder);
  tube.name = "tube";
  tube.as<sweep::ProfilePart>().profile = 1;
  tube.as<sweep::CylinderSurface>().sweep = 0;
  doc.objects = {knot, circle, tube};
  return doc;
}

TEST(TorusKnot, TubeAlongTheKnotIsWatertightWithASeamlessSeam) {
  for (const TorusKnotShape& k : kKnots) {
    for (const auto method : {sweep::FrameMethod::RotationMinimizing, sweep::FrameMethod::Projection}) {
      for (const auto seam : {sweep::SeamMode::Full, sweep::SeamMode::Symmetric}) {
        const std::string what = describe(k) + (method == sweep::FrameMethod::Projection ? " projection" : " rmf") +
                                 (seam == sweep::SeamMode::Symmetric ? " symmetric" : " full");
        sweep::EvaluationOptions options;
        options.frames.method = method;
        options.seam = seam;
        const sweep::Scene scene = sweep::evaluate_document(tube_document(k, 240), options);
        const sweep::Mesh& mesh = scene.objects[2].mesh;
        const sweep::CurveSamples& knot = scene.objects[0].curve;
        EXPECT_TRUE(scene.objects[2].diagnostics.closed) << what;
        EXPECT_TRUE(scene.objects[2].diagnostics.folds.empty()) << what;
        // The seam ring is shared, so the tube is closed before any welding: every edge in two
        // triangles, traversed once each way.
        int bad = 0;
        for (const auto& [edge, uses] : sweep::test::edge_uses(mesh)) bad += uses != 2 ? 1 : 0;
        for (const auto& [edge, uses] : sweep::test::directed_edge_uses(mesh)) bad += uses != 1 ? 1 : 0;
        EXPECT_EQ(bad, 0) << what;
        EXPECT_EQ(mesh.vertex_count(), 12u * (knot.frames.size() - 1)) << what;
        if (seam != sweep::SeamMode::Full) continue;
        // ... and sharing hides no gap: the ring the end frame would place is the first ring.
        const sweep::CurveSamples& section = scene.objects[1].curve;
        const sweep::Frame& end = knot.frames.back();
        for (std::size_t i = 0; i < 12; ++i) {
          const glm::dvec3 p = end.V + section.frames[i].V.x * end.N + section.frames[i].V.y * end.B;
          EXPECT_LT(distance(p, glm::dvec3(mesh.positions[i])), 1e-5 * k.major_radius) << what << " vertex " << i;
        }
      }
    }
  }
}

TEST(TorusKnot, TrefoilAsInTheFormat) {
  // knot trefoil 240 2 3 2 1
  const sweep::Document doc = tube_document({2, 3, 2.0, 1.0}, 240);
  const sweep::CurveSamples curve = sweep::evaluate_curve(doc.objects[0]);
  EXPECT_EQ(static_cast<std::int64_t>(curve.frames.size()), sweep::curve_sample_count(doc.objects[0]));
  EXPECT_EQ(curve.frames.size(), 241u);
  EXPECT_EQ(curve.frames.front().V, glm::dvec3(3, 0, 0));
  EXPECT_TRUE(curve.closed);
  EXPECT_FALSE(curve.planar);
  for (const auto& f : curve.frames) EXPECT_EQ(sweep::test::frame_problem(f), "");
}

}  // namespace
