// The curve kinds cr2/cr3/kb2/kb3/helix/knot and the optional `key value` clauses in SWP files:
// bad input by its exact message and position, and write -> parse as the identity with the
// writer's exact text (a clause is written only when it differs from its default).
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/clauses.hpp"
#include "model/curve_parameters.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

namespace {

using sweep::ObjectKind;

using sweep::test::error_of;
using sweep::test::expect_error;

const std::string kKeywords =
    "expected a keyword (bez2, bez3, bsp2, bsp3, circ, cr2, cr3, kb2, kb3, helix, knot, poly2, poly3, herm2, herm3, "
    "srev, gcyl, "
    "birail, bezpatch, "
    "bsppatch, mesh, subd, material, rider)";
const std::string kProfile =
    "expected the name of a 2D curve (bez2, bsp2, circ, cr2, kb2, poly2, herm2) defined above as profile";
const std::string kAlpha = "expected alpha from 0 to 1 (0 uniform, 0.5 centripetal, 1 chordal)";
const std::string kCatmullRomTension = "expected tension from 0 up to (not including) 1";
const std::string kCatmullRomClauses = "expected a clause (alpha, tension, tolerance) or '[' to start point 1 of ";
const std::string kKochanekBartelsClauses =
    "expected a clause (tension, continuity, bias, tolerance) or '[' to start point 1 of ";
const std::string kCurveClause = "expected a clause (tolerance) or a keyword";
const std::string kPlacedClause = "expected a clause (at, tolerance) or a keyword";

TEST(SwpClauseErrors, KeywordListNamesEveryKind) {
  expect_error("cr4 c 8 2", 1, 1, kKeywords + ", found 'cr4'");
  // The list is every keyword once: ", "-separated between the parentheses.
  const std::size_t open = kKeywords.find('(');
  std::string list = kKeywords.substr(open + 1, kKeywords.size() - open - 2) + ", ";
  for (int k = 0; k <= static_cast<int>(ObjectKind::Rider); ++k) {
    const std::string entry = std::string(sweep::keyword(static_cast<ObjectKind>(k))) + ", ";
    const std::size_t at = list.find(entry);
    ASSERT_NE(at, std::string::npos) << entry;
    EXPECT_TRUE(at == 0 || list[at - 1] == ' ') << entry;
    list.erase(at, entry.size());
  }
  EXPECT_EQ(list, "");
}

TEST(SwpClauseErrors, FewerThanTwoInterpolatedPoints) {
  expect_error("cr2 c 8 1\n[0 0]", 1, 9, "expected at least 2 Catmull-Rom control points, found '1'");
  expect_error("cr3 c 8 0", 1, 9, "expected at least 2 Catmull-Rom control points, found '0'");
  expect_error("kb3 k 8 0", 1, 9, "expected at least 2 Kochanek-Bartels control points, found '0'");
  expect_error("kb2 k 8 1 [0 0]", 1, 9, "expected at least 2 Kochanek-Bartels control points, found '1'");
  expect_error("kb2 k 8 -2", 1, 9, "expected a control point count, a whole number from 0 to 10000000, found '-2'");
  EXPECT_EQ(error_of("cr2 c 8 2 [0 0] [1 1]\nkb3 k 8 2 [0 0 0] [1 1 1]"), "no error");
}

TEST(SwpClauseErrors, AlphaOutsideZeroToOne) {
  expect_error("cr2 c 8 2 alpha 1.5 [0 0] [1 1]", 1, 17, kAlpha + ", found '1.5'");
  expect_error("cr3 c 8 2 alpha -0.1", 1, 17, kAlpha + ", found '-0.1'");
  expect_error("cr3 c 8 2 alpha 1e13", 1, 17, kAlpha + ", found '1e13'");
  EXPECT_EQ(error_of("cr2 a 8 2 alpha 0 [0 0] [1 1]\ncr2 b 8 2 alpha 1 [0 0] [1 1]"), "no error");
}

TEST(SwpClauseErrors, TensionOutsideItsRange) {
  // Catmull-Rom: [0, 1), the tangents are scaled by 1 - T.
  expect_error("cr2 c 8 2 tension 1", 1, 19, kCatmullRomTension + ", found '1'");
  expect_error("cr3 c 8 2 tension -0.5", 1, 19, kCatmullRomTension + ", found '-0.5'");
  EXPECT_EQ(error_of("cr2 c 8 2 tension 0.999 [0 0] [1 1]"), "no error");
  // Kochanek-Bartels: [-1, 1].
  expect_error("kb2 c 8 2 tension 1.5", 1, 19, "expected tension from -1 to 1, found '1.5'");
  expect_error("kb3 c 8 2 tension -1.000001", 1, 19, "expected tension from -1 to 1, found '-1.000001'");
  EXPECT_EQ(error_of("kb2 a 8 2 tension -1 [0 0] [1 1]\nkb2 b 8 2 tension 1 [0 0] [1 1]"), "no error");
}

TEST(SwpClauseErrors, ContinuityAndBiasOutsideMinusOneToOne) {
  expect_error("kb3 c 8 2 continuity 2", 1, 22, "expected continuity from -1 to 1, found '2'");
  expect_error("kb2 c 8 2 bias -1.01", 1, 16, "expected bias from -1 to 1, found '-1.01'");
  EXPECT_EQ(error_of("kb2 c 8 2 continuity -1 bias 1 [0 0] [1 1]"), "no error");
}

TEST(SwpClauseErrors, UnknownClauseKey) {
  expect_error("cr2 c 8 2 beta 1 [0 0] [1 1]", 1, 11, kCatmullRomClauses + "2, found 'beta'");
  // Each kind has its own keys: bias is Kochanek-Bartels only, alpha Catmull-Rom only.
  expect_error("cr2 c 8 2 bias 0", 1, 11, kCatmullRomClauses + "2, found 'bias'");
  expect_error("kb2 c 8 3 alpha 0.5", 1, 11, kKochanekBartelsClauses + "3, found 'alpha'");
  // A keyword or a number where a clause or the first point must be.
  expect_error("cr2 c 8 2 circ d 8 1", 1, 11, kCatmullRomClauses + "2, found 'circ'");
  expect_error("cr3 c 8 2 0.5 [0 0 0] [1 1 1]", 1, 11, kCatmullRomClauses + "2, found '0.5'");
  expect_error("kb3 c 8 2 tension 0.5\n  tension2 0.5", 2, 3, kKochanekBartelsClauses + "2, found 'tension2'");
  // Helix and knot have only their place and the tolerance: another word after their fixed
  // fields must start the next object.
  EXPECT_EQ(error_of("helix h 16 1 1 2 tolerance 0.1"), "no error");
  expect_error("knot k 16 2 3 2 1 alpha 0.5", 1, 19,
               kPlacedClause + kKeywords.substr(std::string("expected a keyword").size()) + ", found 'alpha'");
}

// A helix or torus knot stands where its `at X Y Z` clause puts it (the Create panel places new
// ones beside the scene): every number checked, written back only when not at the origin.
TEST(SwpClauseErrors, AHelixOrKnotsPlace) {
  EXPECT_EQ(error_of("helix h 16 1 1 2 at 3 -4 5.5 tolerance 0.1\nknot k 240 2 3 1 0.4 at 0 0 0"), "no error");
  expect_error("knot k 16 2 3 2 1 at 1 2", 1, 25, "expected a number (at z), found end of file");
  expect_error("knot k 16 2 3 2 1 at 1 two 3", 1, 24, "expected a number (at y), found 'two'");
  expect_error("helix h 16 1 1 2 at 2e12 0 0", 1, 21,
               "expected a place with coordinates from -1e12 to 1e12, found '2e12'");
  expect_error("helix h 16 1 1 2 at 1 1 1 at 2 2 2", 1, 27,
               "expected each clause at most once, found 'at' (already given at line 1, column 18)");
  expect_error("circ c 16 1 at 1 1 1", 1, 13,
               kCurveClause + kKeywords.substr(std::string("expected a keyword").size()) + ", found 'at'");
}

TEST(SwpClauses, APlaceIsWrittenBackWhereItIsNotTheOrigin) {
  const sweep::Document doc = sweep::io::parse_swp("knot k 240 2 3 1 0.4 at 3 0 -1.5\nhelix h 16 1 1 2 at 0 0 0\n");
  EXPECT_EQ(doc.objects[0].as<sweep::PlacePart>().at, glm::dvec3(3.0, 0.0, -1.5));
  EXPECT_EQ(sweep::io::write_swp(doc), "knot k 240 2 3 1 0.4 at 3 0 -1.5\n\nhelix h 16 1 1 2\n\n");
  EXPECT_EQ(sweep::io::write_swp(sweep::io::parse_swp(sweep::io::write_swp(doc))), sweep::io::write_swp(doc));
}

TEST(SwpClauseErrors, ClauseValueMissingOrNotANumber) {
  expect_error("cr2 c 8 2 alpha [0 0] [1 1]", 1, 17, "expected a number (alpha), found '['");
  expect_error("cr2 c 8 2 tension", 1, 18, "expected a number (tension), found end of file");
  expect_error("cr2 c 8 2 alpha half", 1, 17, "expected a number (alpha), found 'half'");
  expect_error("kb2 c 8 2 continuity bias 0", 1, 22, "expected a number (continuity), found 'bias'");
  expect_error("kb2 c 8 2 bias nan", 1, 16, "expected a finite number (bias), found 'nan'");
  expect_error("kb2 c 8 2 bias 1e999", 1, 16, "expected a number (bias), found '1e999' (out of range)");
}

TEST(SwpClauseErrors, ClauseGivenTwice) {
  expect_error("cr2 c 8 2 alpha 0 alpha 1", 1, 19,
               "expected each clause at most once, found 'alpha' (already given at line 1, column 11)");
  // Keys are case-insensitive like keywords, so a different spelling is the same clause.
  expect_error("kb2 c 8 2 bias 0.5 tension 0.5\n  Tension 0.5 [0 0] [1 1]", 2, 3,
               "expected each clause at most once, found 'Tension' (already given at line 1, column 20)");
}

TEST(SwpClauseErrors, PointsOfTheWrongDimension) {
  expect_error("cr2 c 8 2\n[0 0 0]", 2, 6,
               "expected ']' to end point 1 of 2 (2D points have 2 coordinates), found '0'");
  expect_error("kb2 c 8 2 tension 0.5\n[0 0] [1 1 1]", 2, 12,
               "expected ']' to end point 2 of 2 (2D points have 2 coordinates), found '1'");
  expect_error("cr3 c 8 2 [0 0] [1 1 1]", 1, 15, "expected a number (z of point 1 of 2), found ']'");
  // The clauses come before the points, and the count still says how many.
  expect_error("cr2 c 8 2 alpha 1", 1, 18, "expected '[' to start point 1 of 2, found end of file");
  expect_error("cr2 c 8 2 [0 0] [1 1] [2 2]", 1, 23,
               kKeywords + ", found '[' (the cr2 above already has its 2 points)");
}

TEST(SwpClauseErrors, KnotPAndQ) {
  expect_error("knot k 100 2 4 2 1", 1, 14,
               "expected P and Q without a common factor (P = 2 and Q = 4 share 2: that is a link of 2 loops, not "
               "a knot), found '4'");
  expect_error("knot k 100 6 9 2 1", 1, 14,
               "expected P and Q without a common factor (P = 6 and Q = 9 share 3: that is a link of 3 loops, not "
               "a knot), found '9'");
  expect_error("knot k 100 2.5 3 2 1", 1, 12, "expected P, a whole number from 1 to 1000, found '2.5'");
  expect_error("knot k 100 1001 3 2 1", 1, 12, "expected P, a whole number from 1 to 1000, found '1001'");
  expect_error("knot k 100 2 0 2 1", 1, 14, "expected Q, a whole number from 1 to 1000, found '0'");
  expect_error("knot k 100 2 three 2 1", 1, 14, "expected Q, a whole number from 1 to 1000, found 'three'");
  EXPECT_EQ(sweep::kMaxKnotWinding, 1000);
  EXPECT_EQ(error_of("knot a 100 1 1 2 1\nknot b 100 1000 999 2 1\nknot c 100 +3 +2 2 1"), "no error");
}

TEST(SwpClauseErrors, KnotRadii) {
  const std::string crossing = "expected r less than R (the torus would cross its own axis)";
  expect_error("knot k 100 2 3 1 1", 1, 18, crossing + ", found '1'");
  expect_error("knot k 100 2 3 1 2", 1, 18, crossing + ", found '2'");
  expect_error("knot k 100 2 3 -2 1", 1, 19, crossing + ", found '1'");
  expect_error("knot k 100 2 3 2 0", 1, 18, "expected a positive tube radius r, found '0'");
  expect_error("knot k 100 2 3 2 -1", 1, 18, "expected a positive tube radius r, found '-1'");
  expect_error("knot k 100 2 3 2 1e-13", 1, 18, "expected a tube radius r of at least 1e-12, found '1e-13'");
  expect_error("knot k 100 2 3 big 1", 1, 16, "expected a number (torus radius R), found 'big'");
  expect_error("knot k 100 2 3 2", 1, 17, "expected a number (tube radius r), found end of file");
  expect_error("knot k 100 2 3 2e12 1", 1, 16, "expected a number from -1e12 to 1e12 (torus radius R), found '2e12'");
}

TEST(SwpClauseErrors, HelixRadiusPitchAndTurns) {
  expect_error("helix h 16 0 1 2", 1, 12, "expected a positive radius, found '0'");
  expect_error("helix h 16 -1 1 2", 1, 12, "expected a positive radius, found '-1'");
  expect_error("helix h 16 1e-13 1 2", 1, 12, "expected a radius of at least 1e-12, found '1e-13'");
  expect_error("helix h 16 1 1 0", 1, 16, "expected a positive number of turns, found '0'");
  expect_error("helix h 16 1 1 -2", 1, 16, "expected a positive number of turns, found '-2'");
  expect_error("helix h 16 1 2e12 3", 1, 14, "expected a number from -1e12 to 1e12 (pitch), found '2e12'");
  expect_error("helix h 16 1 inf 3", 1, 14, "expected a finite number (pitch), found 'inf'");
  expect_error("helix h 16 1 1", 1, 15, "expected a number (turns), found end of file");
  EXPECT_EQ(error_of("helix a 16 1 -0.5 0.25\nhelix b 3 1e-12 0 1e-300"), "no error");
}

TEST(SwpClauseErrors, SampleCapsOfTheNewKinds) {
  // A helix has ceil(STEPS * TURNS) + 1 samples; the error is at TURNS.
  EXPECT_EQ(error_of("helix h 1 1 1 9999999"), "no error");  // 10000000 samples
  expect_error("helix h 1 1 1 9999999.5", 1, 15,
               "expected at most 10000000 samples per curve, found '9999999.5' (STEPS 1 and TURNS 9999999.5 give "
               "10000001)");
  expect_error("helix h 100000 1 1 100", 1, 20,
               "expected at most 10000000 samples per curve, found '100' (STEPS 100000 and TURNS 100 give 10000001)");
  expect_error("helix h 100000 1 1 1e12", 1, 20,
               "expected at most 10000000 samples per curve, found '1e12' (STEPS 100000 and TURNS 1e12 give "
               "100000000000000001)");
  expect_error("helix a 100000 1 1 90\nhelix b 100000 1 1 90\nhelix c 100000 1 1 90", 3, 20,
               "expected at most 20000000 curve samples in the whole document, found '90' (this curve brings the "
               "total to 27000003)");
  // Catmull-Rom and Kochanek-Bartels: (N - 1) * STEPS + 1, checked before the points are read.
  expect_error("cr2 c 100000 101", 1, 7,
               "expected at most 10000000 samples per curve, found '100000' (STEPS 100000 gives 10000001)");
  expect_error("kb3 c 100000 102", 1, 7,
               "expected at most 10000000 samples per curve, found '100000' (STEPS 100000 gives 10100001)");
}

TEST(SwpClauseErrors, NewKindsAsProfilesAndSweeps) {
  expect_error("cr3 p 8 2 [0 0 0] [1 1 1]\nsrev s 8 p", 2, 10, kProfile + ", found 'p' (it is a 3D curve (cr3))");
  expect_error("helix p 8 1 1 1\nsrev s 8 p", 2, 10, kProfile + ", found 'p' (it is a 3D curve (helix))");
  expect_error("knot p 8 2 3 2 1\ncirc c 8 1\ngcyl g p c", 3, 8, kProfile + ", found 'p' (it is a 3D curve (knot))");
  EXPECT_EQ(error_of("cr2 p 8 2 [-1 1] [-1 -1]\nkb2 q 8 2 [-1 1] [-1 -1]\nhelix h 8 1 1 1\nknot k 8 2 3 2 1\n"
                     "srev a 8 p\nsrev b 8 q\ngcyl c p h\ngcyl d q k\nkb3 s 4 2 [0 0 0] [0 0 1]\ngcyl e p s"),
            "no error");
}

TEST(SwpClauseErrors, ValidateDocumentChecksTheNewFields) {
  sweep::Document doc = sweep::io::parse_swp(
      "cr2 c 8 2 [0 0] [1 1]\nknot k 100 2 3 2 1\nhelix h 32 1 1 2\nkb2 b 8 2 [0 0] [1 1]\n", "edit.swp");
  const auto message = [](const sweep::Document& d) -> std::string {
    try {
      sweep::io::validate_document(d, "edit.swp");
    } catch (const sweep::io::ParseError& e) {
      return e.what();
    }
    return "no error";
  };
  EXPECT_EQ(message(doc), "no error");
  sweep::Document bad = doc;
  bad.objects[0].as<sweep::AlphaPart>().alpha = 2.0;
  EXPECT_EQ(message(bad), "edit.swp:1:1: " + kAlpha + ", found '2' (in c)");
  bad = doc;
  bad.objects[0].as<sweep::TensionPart>().tension = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(message(bad), "edit.swp:1:1: expected a finite number (tension), found 'nan' (in c)");
  bad = doc;
  bad.objects[1].as<sweep::TorusKnotCurve>().knot_q = 4;
  EXPECT_EQ(message(bad),
            "edit.swp:2:1: expected P and Q without a common factor (P = 2 and Q = 4 share 2: that is a link of 2 "
            "loops, not a knot), found '4' (in k)");
  bad = doc;
  bad.objects[2].as<sweep::HelixCurve>().turns = 312500.5;
  EXPECT_EQ(message(bad),
            "edit.swp:3:1: expected at most 10000000 samples per curve, found '312500.5' (STEPS 32 and TURNS "
            "312500.5 give 10000017) (in h)");
  bad = doc;
  bad.objects[3].as<sweep::ContinuityBiasPart>().bias = -3.0;
  EXPECT_EQ(message(bad), "edit.swp:4:1: expected bias from -1 to 1, found '-3' (in b)");
}

// ---- Writing ----

TEST(SwpClauseWriter, ExactTextOfEveryNewKind) {
  const std::string text =
      "cr2 c 8 3 alpha 1 tension 0.25\n[0 0]\n[1 2]\n[3 -1]\n\n"
      "cr3 d 4 2 alpha 0\n[0 0 0]\n[1 1 1]\n\n"
      "kb2 e 6 2 tension -1 continuity 0.5 bias 1\n[0 0]\n[1 0]\n\n"
      "kb3 f 6 2\n[0 0 0]\n[0 0 1]\n\n"
      "helix h 32 1 0.6 6\n\n"
      "knot k 240 2 3 2 1\n\n";
  const sweep::Document doc = sweep::io::parse_swp(text);
  ASSERT_EQ(doc.objects.size(), 6u);
  EXPECT_EQ(sweep::io::write_swp(doc), text);
  EXPECT_EQ(doc.objects[0].as<sweep::AlphaPart>().alpha, 1.0);
  EXPECT_EQ(doc.objects[0].as<sweep::TensionPart>().tension, 0.25);
  EXPECT_EQ(doc.objects[0].as<sweep::PointsPart>().points[2], glm::dvec3(3, -1, 0));
  EXPECT_EQ(doc.objects[1].as<sweep::AlphaPart>().alpha, 0.0);
  EXPECT_EQ(doc.objects[1].as<sweep::TensionPart>().tension, 0.0);
  EXPECT_EQ(doc.objects[2].as<sweep::TensionPart>().tension, -1.0);
  EXPECT_EQ(doc.objects[2].as<sweep::ContinuityBiasPart>().continuity, 0.5);
  EXPECT_EQ(doc.objects[2].as<sweep::ContinuityBiasPart>().bias, 1.0);
  EXPECT_EQ(doc.objects[3].as<sweep::TensionPart>().tension, 0.0);  // kb3 f: every clause at its default
  EXPECT_EQ(doc.objects[3].as<sweep::ContinuityBiasPart>().continuity, 0.0);
  EXPECT_EQ(doc.objects[3].as<sweep::ContinuityBiasPart>().bias, 0.0);
  EXPECT_EQ(doc.objects[4].as<sweep::RadiusPart>().radius, 1.0);
  EXPECT_EQ(doc.objects[4].as<sweep::HelixCurve>().pitch, 0.6);
  EXPECT_EQ(doc.objects[4].as<sweep::HelixCurve>().turns, 6.0);
  EXPECT_EQ(doc.objects[5].as<sweep::TorusKnotCurve>().knot_p, 2);
  EXPECT_EQ(doc.objects[5].as<sweep::TorusKnotCurve>().knot_q, 3);
  EXPECT_EQ(doc.objects[5].as<sweep::TorusKnotCurve>().major_radius, 2.0);
  EXPECT_EQ(doc.objects[5].as<sweep::RadiusPart>().radius, 1.0);
}

TEST(SwpClauseWriter, ClausesInAnyOrderAndCaseAreWrittenInTableOrder) {
  const sweep::Document doc = sweep::io::parse_swp("CR2 c 8 3 TENSION 0.25\n  Alpha 1 [0 0] [1 2] [3 -1]");
  EXPECT_EQ(sweep::io::write_swp(doc), "cr2 c 8 3 alpha 1 tension 0.25\n[0 0]\n[1 2]\n[3 -1]\n\n");
  EXPECT_EQ(
      sweep::io::write_swp(sweep::io::parse_swp("kb3 k 4 2 bias 0.5 continuity -0.5 tension 0.1 [0 0 0] [1 1 1]")),
      "kb3 k 4 2 tension 0.1 continuity -0.5 bias 0.5\n[0 0 0]\n[1 1 1]\n\n");
}

TEST(SwpClauseWriter, ClausesEqualToTheirDefaultsAreNotWritten) {
  const sweep::Document given = sweep::io::parse_swp("cr2 c 8 2 alpha 0.5 tension 0 [0 0] [1 1]");
  EXPECT_EQ(given, sweep::io::parse_swp("cr2 c 8 2 [0 0] [1 1]"));
  EXPECT_EQ(sweep::io::write_swp(given), "cr2 c 8 2\n[0 0]\n[1 1]\n\n");
  EXPECT_EQ(sweep::io::write_swp(sweep::io::parse_swp("kb2 k 8 2 tension 0 continuity -0 bias 0.0 [0 0] [1 1]")),
            "kb2 k 8 2\n[0 0]\n[1 1]\n\n");
}

TEST(SwpClauseWriter, EveryClauseOfEveryKindRoundTrips) {
  // Driven by the clause table, so a clause added later is covered: each one alone at a value
  // other than its default (0.75 is within every range so far), then all together.
  for (int k = 0; k <= static_cast<int>(ObjectKind::Rider); ++k) {
    const auto kind = static_cast<ObjectKind>(k);
    for (const sweep::SwpClause& clause : sweep::swp_clauses(kind)) {
      // A key that were a keyword would end the clauses of a kind without points; `material` is
      // the one exception, told apart by the name after it (swp/read.cpp, material_clause_follows).
      if (clause.key != "material") {
        EXPECT_FALSE(sweep::kind_from_keyword(clause.key)) << clause.key << " is a keyword";
      }
      if (!clause.check) continue;  // a flag or a reference (surface clauses: swp_surface_clauses_test.cpp)
      // A default that means "off" (tolerance 0: by STEPS) is never written, and refused if typed.
      if (clause.default_means_off) {
        EXPECT_NE(clause.check(kind, clause.default_value), "") << clause.key;
      } else {
        EXPECT_EQ(clause.check(kind, clause.default_value), "") << clause.key;
      }
    }
    if (!sweep::has_control_points(kind) || sweep::swp_clauses(kind).empty()) continue;
    sweep::Object curve;
    curve.set_kind(kind);
    curve.name = "c";
    if (auto* steps = curve.find<sweep::StepsPart>()) steps->steps = 5;  // polylines: no STEPS
    curve.as<sweep::PointsPart>().points.assign(4, glm::dvec3(0.0));
    for (std::size_t i = 0; i < curve.as<sweep::PointsPart>().points.size(); ++i)
      curve.as<sweep::PointsPart>().points[i].x = static_cast<double>(i);
    sweep::Document all;
    all.objects.push_back(curve);
    for (const sweep::SwpClause& clause : sweep::swp_clauses(kind)) {
      sweep::Document one;
      one.objects.push_back(curve);
      *clause.field(one.objects[0]) = 0.75;
      *clause.field(all.objects[0]) = 0.75;
      const std::string text = sweep::io::write_swp(one);
      const std::string fields = sweep::kind_info(kind).steps ? " 5 4 " : " 4 ";
      EXPECT_NE(text.find(fields + std::string(clause.key) + " 0.75\n"), std::string::npos) << text;
      EXPECT_EQ(sweep::io::parse_swp(text), one) << text;
    }
    const std::string text = sweep::io::write_swp(all);
    EXPECT_EQ(sweep::io::parse_swp(text), all) << text;
    EXPECT_EQ(sweep::io::write_swp(sweep::io::parse_swp(text)), text);
  }
}

TEST(SwpClauseWriter, AwkwardValuesSurviveBitForBit) {
  sweep::Document doc;
  sweep::Object cr;
  cr.set_kind(ObjectKind::CatmullRom3);
  cr.name = "cr";
  cr.as<sweep::StepsPart>().steps = 3;
  cr.as<sweep::PointsPart>().points = {{0.1, 1.0 / 3.0, -2.0 / 7.0}, {1e-300, 0, 1e12}, {-0.1, 1.0 / 3.0, -2.0 / 7.0}};
  cr.as<sweep::AlphaPart>().alpha = 1.0 / 3.0;
  cr.as<sweep::TensionPart>().tension = std::nextafter(1.0, 0.0);
  doc.objects.push_back(cr);
  sweep::Object kb;
  kb.set_kind(ObjectKind::KochanekBartels2);
  kb.name = "kb";
  kb.as<sweep::StepsPart>().steps = 7;
  kb.as<sweep::PointsPart>().points = {{0, 0, 0}, {1, 1, 0}};
  kb.as<sweep::TensionPart>().tension = -1.0;
  kb.as<sweep::ContinuityBiasPart>().continuity = std::numeric_limits<double>::denorm_min();
  kb.as<sweep::ContinuityBiasPart>().bias = -2.0 / 3.0;
  doc.objects.push_back(kb);
  sweep::Object helix;
  helix.set_kind(ObjectKind::Helix);
  helix.as<sweep::StepsPart>().steps = 17;
  helix.as<sweep::RadiusPart>().radius = std::sqrt(2.0);
  helix.as<sweep::HelixCurve>().pitch = -1e12;
  helix.as<sweep::HelixCurve>().turns = 0.1;
  doc.objects.push_back(helix);
  sweep::Object knot;
  knot.set_kind(ObjectKind::TorusKnot);
  knot.name = "k";
  knot.as<sweep::StepsPart>().steps = 1000;
  knot.as<sweep::TorusKnotCurve>().knot_p = 1000;
  knot.as<sweep::TorusKnotCurve>().knot_q = 999;
  knot.as<sweep::TorusKnotCurve>().major_radius = 1e12;
  knot.as<sweep::RadiusPart>().radius = std::nextafter(1e12, 0.0);
  doc.objects.push_back(knot);
  const std::string text = sweep::io::write_swp(doc);
  EXPECT_EQ(sweep::io::parse_swp(text), doc) << text;
  EXPECT_EQ(sweep::io::write_swp(sweep::io::parse_swp(text)), text);
  EXPECT_NO_THROW(sweep::io::validate_document(doc));
}

}  // namespace
