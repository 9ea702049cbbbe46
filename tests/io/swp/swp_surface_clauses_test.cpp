// The surfaces' clauses in SWP: gcyl `scale CURVE`, `twist DEGREES | twist CURVE`, `caps`;
// srev `caps`; birail `height`: round trips and the exact messages for bad input.
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"

#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

namespace {

using sweep::test::expect_error;

const std::string kCurves =
    "circ c 16 1\n"
    "bsp3 path 4 4 [0 0 0] [1 0 0] [2 1 0] [3 1 1]\n"
    "cr2 taper 4 3 [0 1] [0.5 0.7] [1 0.2]\n"
    "cr2 turn 4 2 [0 0] [1 180]\n";
const std::string kList = "(bez2, bsp2, circ, cr2, kb2, poly2, herm2)";

TEST(SwpSurfaceClauses, EveryClauseRoundTrips) {
  for (const std::string surface :
       {"gcyl g c path scale taper", "gcyl g c path twist 45.5", "gcyl g c path twist turn", "gcyl g c path caps",
        "gcyl g c path scale taper twist turn caps", "gcyl g c path twist -720 scale taper", "srev s 12 taper caps",
        "birail b taper path path height", "birail b taper path path"}) {
    const sweep::Document doc = sweep::io::parse_swp(kCurves + surface + "\n");
    const std::string text = sweep::io::write_swp(doc);
    EXPECT_EQ(sweep::io::parse_swp(text), doc) << surface;
    EXPECT_EQ(sweep::io::write_swp(sweep::io::parse_swp(text)), text);
  }
  const sweep::Document doc = sweep::io::parse_swp(kCurves + "gcyl g c path CAPS Twist turn SCALE taper\n");
  const sweep::Object& g = doc.objects.back();
  EXPECT_EQ(g.as<sweep::CylinderSurface>().scale, 2);
  EXPECT_EQ(g.as<sweep::CylinderSurface>().twist_curve, 3);
  EXPECT_TRUE(g.as<sweep::CapsPart>().caps);
  // Written in the table's order, lower case, after the fixed fields.
  EXPECT_NE(sweep::io::write_swp(doc).find("gcyl g c path scale taper twist turn caps\n"), std::string::npos);
}

TEST(SwpSurfaceClauses, ScaleCurveMustBeAKnown2DCurve) {
  expect_error(kCurves + "gcyl g c path scale nope", 5, 21,
               "expected the name of a 2D curve " + kList +
                   " defined above as a scale curve, found 'nope' (no object has that name)");
  expect_error(kCurves + "gcyl g c path scale path", 5, 21,
               "expected the name of a 2D curve " + kList +
                   " defined above as a scale curve, found 'path' (it is a 3D curve (bsp3))");
  expect_error(kCurves + "gcyl g c path scale", 5, 20,
               "expected the name of a 2D curve " + kList + " defined above as a scale curve, found end of file");
}

TEST(SwpSurfaceClauses, ScaleCurveXMustNotDecreaseAndScaleMustBePositive) {
  expect_error(kCurves + "cr2 back 1 3 [0 1] [0.6 1] [0.4 1]\ngcyl g c path scale back", 6, 21,
               "expected a scale curve whose x never decreases, found 'back' (sample 3 of 3 goes back from x = 0.6 "
               "to 0.4)");
  expect_error(kCurves + "cr2 flat 1 2 [0.5 1] [0.5 2]\ngcyl g c path scale flat", 6, 21,
               "expected a scale curve whose x grows from its first to its last sample, found 'flat' (both are at "
               "x = 0.5)");
  expect_error(kCurves + "cr2 neg 1 3 [0 1] [0.5 0] [1 1]\ngcyl g c path scale neg", 6, 21,
               "expected a scale curve with y > 0, found 'neg' (sample 2 of 3 has y = 0)");
  // The twist takes any value, but its x must grow as well.
  expect_error(kCurves + "cr2 back 1 3 [0 1] [0.6 1] [0.4 1]\ngcyl g c path twist back", 6, 21,
               "expected a twist curve whose x never decreases, found 'back' (sample 3 of 3 goes back from x = 0.6 "
               "to 0.4)");
}

TEST(SwpSurfaceClauses, TwistIsANumberOrACurve) {
  expect_error(kCurves + "gcyl g c path twist 1e7", 5, 21, "expected a twist from -1e6 to 1e6 degrees, found '1e7'");
  expect_error(kCurves + "gcyl g c path twist nan", 5, 21,
               "expected the name of a 2D curve " + kList +
                   " defined above as a twist curve, or a number of degrees, found 'nan' (no object has that name)");
  expect_error(kCurves + "gcyl g c path twist -x", 5, 21, "expected a number (twist), found '-x'");
  expect_error(kCurves + "gcyl g c path caps caps", 5, 20,
               "expected each clause at most once, found 'caps' (already given at line 5, column 15)");
  expect_error(kCurves + "gcyl g c path height", 5, 15,
               "expected a clause (scale, twist, caps, material) or a keyword (bez2, bez3, bsp2, bsp3, circ, cr2, cr3, "
               "kb2, kb3, "
               "helix, knot, poly2, poly3, herm2, herm3, srev, gcyl, birail, bezpatch, bsppatch, mesh, subd, material, "
               "rider), found "
               "'height'");
}

TEST(SwpSurfaceClauses, TwistOnAClosedSweepMustCloseIt) {
  const std::string closed = "bsp3 loop 4 7 [4 0 0] [0 4 1] [-4 0 0] [0 -4 -1] [4 0 0] [0 4 1] [-4 0 0]\n";
  // A profile without symmetry must turn whole turns; a circle of 16 samples a 16th of one.
  const std::string blob = "bsp2 blob 4 7 [0 -1] [2 0] [0 1] [-1 0] [0 -1] [2 0] [0 1]\n";
  EXPECT_NO_THROW(sweep::io::parse_swp(kCurves + closed + blob + "gcyl g blob loop twist 720\n"));
  expect_error(kCurves + closed + blob + "gcyl g blob loop twist 45", 7, 24,
               "expected a twist ending at a multiple of 360 degrees, since the sweep 'loop' is closed, found '45'");
  EXPECT_NO_THROW(sweep::io::parse_swp(kCurves + closed + "gcyl g c loop twist 45\n"));
  expect_error(kCurves + closed + "gcyl g c loop twist 10", 6, 21,
               "expected a twist ending at a multiple of 22.5 degrees (360 / 16 for the profile's 16-fold symmetry), "
               "since the sweep 'loop' is closed, found '10'");
  // A square profile (4-fold symmetric) may end on any quarter turn.
  const std::string square = "bsp2 sq 2 7 [1 1] [-1 1] [-1 -1] [1 -1] [1 1] [-1 1] [-1 -1]\n";
  EXPECT_NO_THROW(sweep::io::parse_swp(kCurves + closed + square + "gcyl g sq loop twist -90\n"));
  EXPECT_NO_THROW(sweep::io::parse_swp(kCurves + closed + square + "gcyl g sq loop twist turn\n"));  // 180
  const std::string tilt = "cr2 tilt 4 2 [0 10] [1 55]\n";
  expect_error(kCurves + closed + square + tilt + "gcyl g sq loop twist tilt", 8, 22,
               "expected a twist ending at a multiple of 90 degrees (360 / 4 for the profile's 4-fold symmetry), "
               "since the sweep 'loop' is closed, found 'tilt' (it ends 45 degrees from where it starts)");
}

TEST(SwpSurfaceClauses, BirailRailsAndProfile) {
  expect_error(kCurves + "birail b taper path c", 5, 21,
               "expected an open second rail, like the first rail 'path', found 'c' (it is closed)");
  expect_error(kCurves + "birail b taper c path", 5, 18,
               "expected a closed second rail, like the first rail 'c', found 'path' (it is open)");
  expect_error(kCurves + "birail b c path path", 5, 10,
               "expected a profile whose ends are apart (its first sample rides RAIL1, its last RAIL2), found 'c' "
               "(its first and last samples meet)");
  expect_error(kCurves + "birail b taper path", 5, 20,
               "expected the name of a curve defined above as the second rail, found end of file");
  expect_error(
      kCurves + "birail b path path path", 5, 10,
      "expected the name of a 2D curve " + kList + " defined above as profile, found 'path' (it is a 3D curve (bsp3))");
}

}  // namespace
