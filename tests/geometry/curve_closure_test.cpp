// The one definition of a closed curve (is_closed of a descriptor, by its basis's rule) and how
// evaluation follows it: a curve evaluates closed only if its basis says its ends meet.
#include "geometry/curves/bezier.hpp"
#include "geometry/curves/catmull_rom.hpp"
#include "geometry/curves/circle.hpp"
#include "geometry/curves/curve.hpp"
#include "geometry/curves/helix.hpp"
#include "geometry/curves/polyline.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

using sweep::CurveDescriptor;

CurveDescriptor points_curve(const sweep::CurveBasis& basis, const std::vector<glm::dvec3>& points) {
  CurveDescriptor c;
  c.basis = &basis;
  c.points = points;
  c.steps = 8;
  return c;
}

// A smooth closed Bezier: two pieces, the seam's handles collinear with the seam point.
const std::vector<glm::dvec3> kLoop{{1, 0, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}, {1, -1, 0}, {1, 0, 0}};

TEST(CurveClosure, ABezierIsClosedWhenItsLastPointIsItsFirstAndEvaluatesClosedWhenSmoothThere) {
  const CurveDescriptor loop = points_curve(sweep::kBezierBasis, kLoop);
  EXPECT_TRUE(sweep::is_closed(loop));
  EXPECT_TRUE(sweep::evaluate_curve(loop).closed);
  std::vector<glm::dvec3> teardrop = kLoop;
  teardrop[1] = {2, 1, 0};  // a corner at the seam: closed, but its samples do not meet smoothly
  EXPECT_TRUE(sweep::is_closed(points_curve(sweep::kBezierBasis, teardrop)));
  EXPECT_FALSE(sweep::evaluate_curve(points_curve(sweep::kBezierBasis, teardrop)).closed);
}

TEST(CurveClosure, AGapBeyondTheSeamToleranceIsOpenForTheEditorAndForEvaluation) {
  std::vector<glm::dvec3> gap = kLoop;
  gap.back().y = 1e-7;  // 1e-9 of the seam points' size is 2e-9
  const CurveDescriptor open = points_curve(sweep::kBezierBasis, gap);
  EXPECT_FALSE(sweep::is_closed(open));
  EXPECT_FALSE(sweep::evaluate_curve(open).closed) << "the samples alone are within 1e-6 of the size";
  gap.back().y = 1e-10;
  EXPECT_TRUE(sweep::is_closed(points_curve(sweep::kBezierBasis, gap)));
}

TEST(CurveClosure, ABSplineIsClosedWhenItsLastThreePointsRepeatItsFirstThree) {
  const std::vector<glm::dvec3> ring{{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {1, 0, 0}, {0, 1, 0}, {-1, 0, 0}};
  EXPECT_TRUE(sweep::is_closed(points_curve(sweep::kBSplineBasis, ring)));
  EXPECT_TRUE(sweep::evaluate_curve(points_curve(sweep::kBSplineBasis, ring)).closed);
  std::vector<glm::dvec3> two_repeated(ring.begin(), ring.end() - 1);
  EXPECT_FALSE(sweep::is_closed(points_curve(sweep::kBSplineBasis, two_repeated)));
  EXPECT_FALSE(sweep::is_closed(points_curve(sweep::kBSplineBasis, {ring.begin(), ring.begin() + 5})))
      << "fewer than 6 points cannot repeat 3 of their own";
}

TEST(CurveClosure, InterpolatingCurvesAndPolylinesCloseByTheirLastPointAndKeepASeamCorner) {
  const std::vector<glm::dvec3> square{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 0}};
  for (const sweep::CurveBasis* basis : {&sweep::kCatmullRomBasis, &sweep::kPolylineBasis}) {
    CurveDescriptor c = points_curve(*basis, square);
    c.planar = true;
    EXPECT_TRUE(sweep::is_closed(c)) << basis->name;
    EXPECT_TRUE(sweep::evaluate_curve(c).closed) << basis->name;
    EXPECT_EQ(sweep::is_closed_interpolating(square), sweep::is_closed(c)) << basis->name;
  }
  EXPECT_FALSE(sweep::is_closed(points_curve(sweep::kPolylineBasis, {square.begin(), square.begin() + 3})));
}

TEST(CurveClosure, AnalyticCurvesCloseByTheirShape) {
  CurveDescriptor circle;
  circle.basis = &sweep::kCircleBasis;
  circle.radius = 1.0;
  circle.steps = 12;
  EXPECT_TRUE(sweep::is_closed(circle));
  CurveDescriptor helix;
  helix.basis = &sweep::kHelixBasis;
  helix.radius = 1.0;
  helix.steps = 12;
  helix.turns = 2.0;
  EXPECT_TRUE(sweep::is_closed(helix)) << "flat and of whole turns";
  EXPECT_TRUE(sweep::evaluate_curve(helix).closed);
  helix.pitch = 0.5;
  EXPECT_FALSE(sweep::is_closed(helix));
  EXPECT_FALSE(sweep::evaluate_curve(helix).closed);
  helix.pitch = 0.0;
  helix.turns = 1.5;
  EXPECT_FALSE(sweep::is_closed(helix));
}

}  // namespace
