// Ends that extend (issue 61, item 2): I at an open curve's end adds at that end for every kind
// with control points; a Bezier gains a whole piece whose joint stays smooth (G1: the tangent's
// direction is the same on both sides), the others a point one step on; the shape already there
// does not move; a closed curve says it has no end.
#include "io/swp/read.hpp"
#include "model/edit/edit.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace sweep {
namespace {

const char* const kCurves =
    "bez3 b 8 4\n[0 0 0]\n[1 0 0]\n[2 1 0]\n[3 1 1]\n"
    "bsp2 s 8 4\n[0 0]\n[1 1]\n[2 0]\n[3 1]\n"
    "cr2 c 8 3\n[0 0]\n[1 1]\n[2 0]\n"
    "kb3 k 8 3\n[0 0 0]\n[1 1 0]\n[2 0 1]\n"
    "poly2 p 3\n[0 0]\n[1 1]\n[2 0]\n"
    "herm2 h 8 4\n[0 0]\n[1 0]\n[2 1]\n[0 1]\n";

/// The unit tangent at the curve parameter `u` (the piece that starts there).
glm::dvec3 tangent(const Object& curve, double u) {
  return glm::normalize(curve_derivatives(curve, u).d1);
}

TEST(EditExtend, ABezierGainsAPieceAtEitherEndAndStaysSmooth) {
  Document doc = io::parse_swp(kCurves);
  const std::vector<glm::dvec3> before = doc.objects[0].as<PointsPart>().points;
  const Object original = doc.objects[0];
  extend_curve(doc, 0, CurveEnd::End);
  const std::vector<glm::dvec3>& after = doc.objects[0].as<PointsPart>().points;
  ASSERT_EQ(after.size(), 7u) << "one whole piece: two handles and a joint";
  for (std::size_t i = 0; i < before.size(); ++i) EXPECT_EQ(after[i], before[i]) << i;
  // G1 at the old end (parameter 1): the tangent leaving equals the one arriving.
  const double eps = 1e-9;
  EXPECT_NEAR(glm::length(tangent(doc.objects[0], 1.0) - tangent(original, 1.0 - eps)), 0.0, 1e-6);
  EXPECT_EQ(after[4] - after[3], after[3] - after[2]) << "C1: the handles equally long";

  extend_curve(doc, 0, CurveEnd::Start);
  const std::vector<glm::dvec3>& both = doc.objects[0].as<PointsPart>().points;
  ASSERT_EQ(both.size(), 10u);
  EXPECT_EQ(both[3], before[0]) << "the old start is now the second joint";
  EXPECT_EQ(both[3] - both[2], both[4] - both[3]);
}

TEST(EditExtend, ABezierPieceEndsWhereThePenPutsIt) {
  Document doc = io::parse_swp(kCurves);
  extend_curve(doc, 0, CurveEnd::End, glm::dvec3(5.0, 2.0, 1.0));
  const std::vector<glm::dvec3>& points = doc.objects[0].as<PointsPart>().points;
  EXPECT_EQ(points.back(), glm::dvec3(5.0, 2.0, 1.0));
  EXPECT_EQ(points[4] - points[3], points[3] - points[2]);
}

TEST(EditExtend, EveryOtherKindGainsAPointOneStepOnAndKeepsItsPoints) {
  Document doc = io::parse_swp(kCurves);
  for (int index = 1; index < int(doc.objects.size()); ++index) {
    const std::vector<glm::dvec3> before = doc.objects[std::size_t(index)].as<PointsPart>().points;
    const std::size_t stride = point_layout(doc.objects[std::size_t(index)].kind()).stride;
    extend_curve(doc, index, CurveEnd::End);
    extend_curve(doc, index, CurveEnd::Start);
    const std::vector<glm::dvec3>& after = doc.objects[std::size_t(index)].as<PointsPart>().points;
    const std::string kind(keyword(doc.objects[std::size_t(index)].kind()));
    ASSERT_EQ(after.size(), before.size() + 2 * stride) << kind;
    for (std::size_t i = 0; i < before.size(); ++i) EXPECT_EQ(after[i + stride], before[i]) << kind << " " << i;
    const std::size_t n = before.size();
    EXPECT_EQ(after[after.size() - stride], 2.0 * before[n - stride] - before[n - 2 * stride]) << kind;
    EXPECT_EQ(after[0], 2.0 * before[0] - before[stride]) << kind;
  }
}

TEST(EditExtend, EndsAreTheFirstPointAndTheLastGroupsPoint) {
  const Document doc = io::parse_swp(kCurves);
  EXPECT_EQ(end_at(doc.objects[0], 0), CurveEnd::Start);
  EXPECT_EQ(end_at(doc.objects[0], 3), CurveEnd::End);
  EXPECT_EQ(end_at(doc.objects[0], 2), std::nullopt) << "a handle";
  EXPECT_EQ(end_at(doc.objects[5], 2), CurveEnd::End) << "the Hermite's last point, not its tangent";
  EXPECT_EQ(end_at(doc.objects[5], 3), std::nullopt);
}

TEST(EditExtend, AClosedCurveHasNoEnd) {
  Document doc = io::parse_swp("poly2 ring 4\n[0 0]\n[1 0]\n[0 1]\n[0 0]\n");
  EXPECT_EQ(end_at(doc.objects[0], 0), std::nullopt);
  try {
    extend_curve(doc, 0, CurveEnd::End);
    FAIL() << "extended a closed curve";
  } catch (const EditError& e) {
    EXPECT_STREQ(e.what(), "curve 'ring' is closed: it has no end to extend");
  }
}

}  // namespace
}  // namespace sweep
