// Converting a curve to another kind (issue 61, item 3): exact conversions sample the same curve
// within 1e-12 at the same STEPS; fits stay within their tolerance; corners refuse Hermite; the
// surfaces that use a converted curve keep their references.
#include "io/swp/read.hpp"
#include "model/edit/edit.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

namespace sweep {
namespace {

const char* const kCurves =
    "bsp2 open 8 6\n[0 1]\n[0.5 1]\n[1 0.5]\n[1 -0.5]\n[0.5 -1]\n[0 -1]\n"
    "bsp3 loop 6 7\n[1 0 0]\n[0 1 0.5]\n[-1 0 0]\n[0 -1 -0.5]\n[1 0 0]\n[0 1 0.5]\n[-1 0 0]\n"
    "cr2 cr 8 4\n[0 0]\n[1 2]\n[3 1]\n[4 3]\n"
    "kb3 kb 8 4 tension 0.3 bias -0.2\n[0 0 0]\n[1 2 1]\n[3 1 0]\n[4 3 2]\n"
    "poly3 zig 3\n[0 0 0]\n[1 1 0]\n[2 0 1]\n"
    "herm2 h 8 4\n[0 0]\n[1 0]\n[2 1]\n[0 1]\n"
    "bez2 smooth 8 7\n[0 0]\n[1 1]\n[2 1]\n[3 0]\n[4 -1]\n[5 -1]\n[6 0]\n";

double sample_distance(const Object& a, const Object& b) {
  const CurveSamples x = evaluate_curve(a);
  const CurveSamples y = evaluate_curve(b);
  EXPECT_EQ(x.frames.size(), y.frames.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(x.frames.size(), y.frames.size()); ++i) {
    worst = std::max(worst, glm::length(x.frames[i].V - y.frames[i].V));
  }
  return worst;
}

TEST(EditConvert, EveryCurveWithPointsBecomesTheSameBezierExactly) {
  const Document doc = io::parse_swp(kCurves);
  for (const Object& curve : doc.objects) {
    const ObjectKind to = is_planar_curve(curve.kind()) ? ObjectKind::Bezier2 : ObjectKind::Bezier3;
    if (to == curve.kind()) continue;  // refused: nothing to convert
    const Conversion result = convert_curve(curve, to, 1e-3);
    EXPECT_TRUE(result.exact);
    EXPECT_EQ(result.curve.kind(), to);
    EXPECT_EQ(result.curve.name, curve.name);
    EXPECT_LT(sample_distance(curve, result.curve), 1e-12) << curve.name;
    EXPECT_EQ(is_closed(describe_curve(result.curve)), is_closed(describe_curve(curve))) << curve.name;
  }
}

TEST(EditConvert, ASmoothCurveBecomesTheSameHermiteExactlyAndACornerRefuses) {
  const Document doc = io::parse_swp(kCurves);
  for (const char* name : {"open", "loop", "cr", "smooth"}) {
    const Object& curve = doc.objects[std::size_t(doc.find(name))];
    const ObjectKind to = is_planar_curve(curve.kind()) ? ObjectKind::Hermite2 : ObjectKind::Hermite3;
    const Conversion result = convert_curve(curve, to, 1e-3);
    EXPECT_LT(sample_distance(curve, result.curve), 1e-12) << name;
  }
  try {
    convert_curve(doc.objects[std::size_t(doc.find("zig"))], ObjectKind::Hermite3, 1e-3);
    FAIL() << "a polyline's corner became a Hermite point";
  } catch (const EditError& e) {
    EXPECT_STREQ(e.what(),
                 "'zig' has a corner at its joint 1: a Hermite curve has one tangent at each point (make the joint "
                 "smooth and symmetric first)");
  }
}

TEST(EditConvert, FitsStayWithinTheirToleranceAndSayTheirDeviation) {
  const Document doc = io::parse_swp(kCurves);
  for (const char* name : {"open", "loop", "cr", "smooth", "zig"}) {
    const Object& curve = doc.objects[std::size_t(doc.find(name))];
    const bool planar = is_planar_curve(curve.kind());
    for (const ObjectKind to : {planar ? ObjectKind::BSpline2 : ObjectKind::BSpline3,
                                planar ? ObjectKind::CatmullRom2 : ObjectKind::CatmullRom3}) {
      if (to == curve.kind()) continue;  // nothing to convert
      const double tolerance = 1e-3 * curve_extent(curve);
      const Conversion fit = convert_curve(curve, to, tolerance);
      EXPECT_FALSE(fit.exact);
      EXPECT_EQ(fit.curve.kind(), to);
      EXPECT_LE(fit.deviation, tolerance) << name << " to " << keyword(to);
      EXPECT_NEAR(fit.deviation, curve_deviation_between(curve, fit.curve), 1e-15);
      EXPECT_EQ(is_closed(describe_curve(fit.curve)), is_closed(describe_curve(curve))) << name;
    }
  }
}

TEST(EditConvert, TheSurfaceUsingTheCurveKeepsItsReferenceAndOneUndoStepIsAChange) {
  Document doc =
      io::parse_swp("bsp2 profile 8 6\n[0 1]\n[0.5 1]\n[1 0.5]\n[1 -0.5]\n[0.5 -1]\n[0 -1]\nsrev vase 12 profile\n");
  const Change change = convert_curve(doc, 0, ObjectKind::Bezier2, 1e-3);
  EXPECT_EQ(doc.objects[0].kind(), ObjectKind::Bezier2);
  EXPECT_EQ(doc.objects[0].name, "profile");
  EXPECT_EQ(doc.objects[1].as<RevolutionSurface>().profile, 0);
  EXPECT_FALSE(change.objects.empty());
  try {
    convert_curve(doc, 0, ObjectKind::Bezier3, 1e-3);
    FAIL();
  } catch (const EditError& e) {
    EXPECT_STREQ(e.what(), "expected a 2D kind for 'profile' (bez2), found bez3");
  }
  try {
    convert_curve(doc, 0, ObjectKind::Bezier2, 1e-3);
    FAIL();
  } catch (const EditError& e) {
    EXPECT_STREQ(e.what(), "'profile' is a bez2 already");
  }
}

}  // namespace
}  // namespace sweep
