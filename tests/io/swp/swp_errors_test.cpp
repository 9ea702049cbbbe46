// Bad SWP input: one test per class of mistake, each checking the full message
// ("FILE:LINE:COLUMN: expected ..., found ...") and the location; plus the forgiving parts of
// the format (empty files, keyword case, free layout).
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"

#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <new>
#include <string>

// The largest single allocation made while `g_tracking` is on: shows that a file announcing a
// huge surface is refused before anything of that size is allocated. Replacing the global
// operator new is the only portable way to see allocations made inside the library.
namespace {
std::atomic<bool> g_tracking{false};
std::atomic<std::size_t> g_largest_allocation{0};
}  // namespace

[[gnu::noinline]] void* operator new(std::size_t size) {
  if (g_tracking.load(std::memory_order_relaxed)) {
    std::size_t seen = g_largest_allocation.load(std::memory_order_relaxed);
    while (size > seen && !g_largest_allocation.compare_exchange_weak(seen, size, std::memory_order_relaxed)) {
    }
  }
  if (void* p = std::malloc(size == 0 ? 1 : size)) return p;
  throw std::bad_alloc();
}
// Not inlined: GCC would otherwise see free() on the result of a new-expression and warn
// (-Wmismatched-new-delete), although these replacements pair malloc with free.
[[gnu::noinline]] void operator delete(void* p) noexcept {
  std::free(p);
}
[[gnu::noinline]] void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

namespace {

using sweep::test::expect_error;

const std::string kKeywords =
    "expected a keyword (bez2, bez3, bsp2, bsp3, circ, cr2, cr3, kb2, kb3, helix, knot, poly2, poly3, herm2, herm3, "
    "srev, gcyl, "
    "birail, bezpatch, "
    "bsppatch, mesh, subd, material, rider)";
const std::string kSteps = "expected STEPS, a whole number from 1 to 100000";
const std::string kProfile =
    "expected the name of a 2D curve (bez2, bsp2, circ, cr2, kb2, poly2, herm2) defined above as profile";
const std::string kSweep = "expected the name of a curve defined above as sweep";

TEST(SwpErrors, UnknownKeyword) {
  // After a curve without points, a word may also be a clause.
  expect_error(
      "circ c 10 1\n  bez4 a 10 4\n", 2, 3,
      "expected a clause (tolerance) or a" + kKeywords.substr(std::string("expected a").size()) + ", found 'bez4'");
  expect_error("[0 0]", 1, 1, kKeywords + ", found '['");
}

TEST(SwpErrors, MissingOpeningBracket) {
  expect_error("bez2 a 10 4\n[0 0]\n1 1]\n[2 2]\n[3 3]\n", 3, 1, "expected '[' to start point 2 of 4, found '1'");
}

TEST(SwpErrors, MissingClosingBracket) {
  expect_error("bez2 a 10 4\n[0 0\n[1 1]\n[2 2]\n[3 3]\n", 3, 1,
               "expected ']' to end point 1 of 4 (2D points have 2 coordinates), found '['");
  // A 3D point in a 2D curve is the same mistake, seen at the third coordinate.
  expect_error("bsp2 a 10 4\n[0 0 0]", 2, 6,
               "expected ']' to end point 1 of 4 (2D points have 2 coordinates), found '0'");
  expect_error("bez3 a 10 4\n[0 0 0 0]", 2, 8,
               "expected ']' to end point 1 of 4 (3D points have 3 coordinates), found '0'");
}

TEST(SwpErrors, MissingCoordinate) {
  expect_error("bez3 a 10 4\n[0 0]", 2, 5, "expected a number (z of point 1 of 4), found ']'");
}

TEST(SwpErrors, NonNumericValue) {
  expect_error("bez2 a 10 4\n[0 zero]", 2, 4, "expected a number (y of point 1 of 4), found 'zero'");
  expect_error("bez2 a 10 4\n[0 0] [1.5.2 0]", 2, 8, "expected a number (x of point 2 of 4), found '1.5.2'");
  expect_error("bez2 a 10 4\n[0 0] [1,5 0]", 2, 8, "expected a number (x of point 2 of 4), found '1,5'");
  expect_error("circ c 10 one", 1, 11, "expected a number (radius), found 'one'");
}

TEST(SwpErrors, NaNAndInfinity) {
  expect_error("bez2 a 10 4\n[nan 0]", 2, 2, "expected a finite number (x of point 1 of 4), found 'nan'");
  expect_error("bez2 a 10 4\n[0 -inf]", 2, 4, "expected a finite number (y of point 1 of 4), found '-inf'");
  expect_error("bez3 a 10 4\n[0 0 +infinity]", 2, 6, "expected a finite number (z of point 1 of 4), found '+infinity'");
  expect_error("circ c 10 inf", 1, 11, "expected a finite number (radius), found 'inf'");
  expect_error("circ c 10 NaN", 1, 11, "expected a finite number (radius), found 'NaN'");
}

TEST(SwpErrors, NumbersOutOfRange) {
  expect_error("bez2 a 10 4\n[1e999 0]", 2, 2, "expected a number (x of point 1 of 4), found '1e999' (out of range)");
  expect_error("bez2 a 10 4\n[0 -2e12]", 2, 4,
               "expected a number from -1e12 to 1e12 (y of point 1 of 4), found '-2e12'");
  expect_error("circ c 10 -1", 1, 11, "expected a radius of 0 or more, found '-1'");
}

TEST(SwpErrors, BezierCountNotThreeNPlusOne) {
  const std::string expected = "expected a Bezier control point count of the form 3n+1 (4, 7, 10, ...)";
  expect_error("bez2 a 10 5\n[0 0] [1 1] [2 2] [3 3] [4 4]", 1, 11, expected + ", found '5'");
  expect_error("bez3 a 10 1\n[0 0 0]", 1, 11, expected + ", found '1'");
  expect_error("bez3 a 10 3", 1, 11, expected + ", found '3'");
}

TEST(SwpErrors, FewerThanFourBSplinePoints) {
  expect_error("bsp2 a 10 3\n[0 0] [1 1] [2 2]", 1, 11, "expected at least 4 B-spline control points, found '3'");
  expect_error("bsp3 a 10 1\n[0 0 0]", 1, 11, "expected at least 4 B-spline control points, found '1'");
}

TEST(SwpErrors, CountZeroOrNegative) {
  expect_error("bsp2 a 10 0", 1, 11, "expected at least 4 B-spline control points, found '0'");
  expect_error("bez2 a 10 0", 1, 11,
               "expected a Bezier control point count of the form 3n+1 (4, 7, 10, ...), found '0'");
  expect_error("bez2 a 10 -4", 1, 11, "expected a control point count, a whole number from 0 to 10000000, found '-4'");
  expect_error("bez2 a 10 four", 1, 11,
               "expected a control point count, a whole number from 0 to 10000000, found 'four'");
}

TEST(SwpErrors, StepsZeroNegativeOrAbsurd) {
  expect_error("circ c 0 1", 1, 8, kSteps + ", found '0'");
  expect_error("bez2 a -3 4", 1, 8, kSteps + ", found '-3'");
  expect_error("bsp2 a 2.5 4", 1, 8, kSteps + ", found '2.5'");
  expect_error("bez2 p 10 4 [0 0] [1 1] [2 2] [3 3]\nsrev s 99999999999999999999999 p", 2, 8,
               kSteps + ", found '99999999999999999999999'");
  expect_error("circ c 100001 1", 1, 8, kSteps + ", found '100001'");
}

/// Parses with allocation tracking on; returns the error message and the largest allocation.
std::pair<std::string, std::size_t> parse_tracking_allocations(const std::string& text) {
  std::string message;
  g_largest_allocation = 0;
  g_tracking = true;
  try {
    (void)sweep::io::parse_swp(text, "bad.swp");
  } catch (const sweep::io::ParseError& e) {
    g_tracking = false;
    message = e.what();
  }
  g_tracking = false;
  return {message, g_largest_allocation.load()};
}

TEST(SwpErrors, AllocationProbeSeesTheParsersAllocations) {
  // Without this, a probe that saw nothing would make the two tests below pass vacuously.
  std::string text = "bsp2 a 1 4000\n";
  for (int i = 0; i < 4000; ++i)
    text.append("[")
        .append(std::to_string(i))
        .append(" 0]\n");  // not "[" + string: GCC 12 -O2 -Wrestrict false positive
  const auto [message, largest] = parse_tracking_allocations(text);
  EXPECT_EQ(message, "");
  EXPECT_GE(largest, 4000 * sizeof(glm::dvec3));
}

TEST(SwpErrors, SurfaceOverTheVertexCapFailsBeforeAllocating) {
  // 1001 profile samples x 100000 copies = 100100000 vertices (about 2.4 GB as float3 x 2).
  const std::string revolution = "bez2 p 1000 4 [-1 1] [-2 0] [-2 -1] [-1 -2]\nsrev big 100000 p\n";
  const auto [message, largest] = parse_tracking_allocations(revolution);
  EXPECT_EQ(message,
            "bad.swp:2:10: expected a surface of at most 50000000 vertices, found '100000' "
            "(this one would have 100100000)");
  EXPECT_LT(largest, std::size_t{1} << 20) << "the parser allocated " << largest << " bytes at once";

  // 10001 x 10001 samples; reported at the keyword since a gcyl has no STEPS.
  const std::string cylinder = "bez2 p 10000 4 [-1 1] [-2 0] [-2 -1] [-1 -2]\ncirc s 10000 1\ngcyl big p s\n";
  const auto [cylinder_message, cylinder_largest] = parse_tracking_allocations(cylinder);
  EXPECT_EQ(cylinder_message,
            "bad.swp:3:1: expected a surface of at most 50000000 vertices, found 'gcyl' "
            "(this one would have 100020001)");
  EXPECT_LT(cylinder_largest, std::size_t{1} << 20);

  // Two surfaces under the cap each but over it together.
  expect_error("bez2 p 1000 4 [-1 1] [-2 0] [-2 -1] [-1 -2]\nsrev a 30000 p\nsrev b 30000 p\n", 3, 8,
               "expected at most 50000000 surface vertices in the whole document, found '30000' "
               "(this surface brings the total to 60060000)");
}

TEST(SwpErrors, HugeControlPointCountInAShortFileFailsWithoutReserving) {
  const auto [message, largest] = parse_tracking_allocations("bsp2 a 1 10000000\n[0 0]");
  EXPECT_EQ(message, "bad.swp:2:6: expected '[' to start point 2 of 10000000, found end of file");
  EXPECT_LT(largest, std::size_t{1} << 20);
}

TEST(SwpErrors, UndefinedReference) {
  expect_error("circ c 10 1\nsrev s 10 nope", 2, 11, kProfile + ", found 'nope' (no object has that name)");
  expect_error("circ c 10 1\ngcyl g c nope", 2, 10, kSweep + ", found 'nope' (no object has that name)");
  // '.' names no object, even when anonymous objects come before or after it.
  expect_error("circ . 10 1\nsrev s 10 .", 2, 11,
               kProfile + ", found '.' ('.' means no name; only named objects can be referenced)");
  expect_error("circ c 10 1\ngcyl g c .\ncirc . 10 1", 2, 10,
               kSweep + ", found '.' ('.' means no name; only named objects can be referenced)");
  expect_error("circ c 10 1\nsrev s 10", 2, 10, kProfile + ", found end of file");
}

TEST(SwpErrors, ForwardReference) {
  expect_error("srev s 10 p\nbez2 p 10 4 [0 0] [1 1] [2 2] [3 3]", 1, 11,
               kProfile + ", found 'p' (it is defined further down; references point backwards only)");
  expect_error("circ p 10 1\ngcyl g p s\ncirc s 10 2", 2, 10,
               kSweep + ", found 's' (it is defined further down; references point backwards only)");
}

TEST(SwpErrors, ThreeDimensionalProfile) {
  const std::string curve = "bez3 p 10 4 [0 0 0] [1 1 1] [2 2 2] [3 3 3]\n";
  expect_error(curve + "srev s 10 p", 2, 11, kProfile + ", found 'p' (it is a 3D curve (bez3))");
  expect_error(curve + "circ s 10 1\ngcyl g p s", 3, 8, kProfile + ", found 'p' (it is a 3D curve (bez3))");
}

TEST(SwpErrors, SurfaceUsedAsACurve) {
  expect_error("circ c 10 1\nsrev s 10 c\ngcyl g c s", 3, 10, kSweep + ", found 's' (it is a surface (srev))");
  expect_error("circ c 10 1\ncirc d 10 3\ngcyl g c d\nsrev s 10 g", 4, 11,
               kProfile + ", found 'g' (it is a surface (gcyl))");
}

TEST(SwpErrors, DuplicateName) {
  expect_error("circ a 10 1\n\ncirc a 10 2", 3, 6,
               "expected a new name, found 'a' (already used by the object at line 1)");
  // A surface cannot take a curve's name either.
  expect_error("circ a 10 1\nsrev a 10 a", 2, 6,
               "expected a new name, found 'a' (already used by the object at line 1)");
  // Anonymous objects never clash.
  EXPECT_EQ(sweep::io::parse_swp("circ . 10 1\ncirc . 10 2").objects.size(), 2u);
}

TEST(SwpErrors, InvalidName) {
  const std::string expected =
      "expected a name (a letter or '_', then letters, digits, '_', '-' or '.') or '.' for none";
  expect_error("circ 9c 10 1", 1, 6, expected + ", found '9c'");
  expect_error("circ a/b 10 1", 1, 6, expected + ", found 'a/b'");
  expect_error("circ " + std::string(201, 'n') + " 10 1", 1, 6, expected + ", found '" + std::string(32, 'n') + "...'");
}

TEST(SwpErrors, TruncatedFile) {
  expect_error("bez2 a 10 4\n[0 0]\n[1", 3, 3, "expected a number (y of point 2 of 4), found end of file");
  expect_error("bez2 a 10 4\n[0 0]\n[1 1\n", 4, 1,
               "expected ']' to end point 2 of 4 (2D points have 2 coordinates), found end of file");
  expect_error("circ", 1, 5,
               "expected a name (a letter or '_', then letters, digits, '_', '-' or '.') or '.' for none, "
               "found end of file");
  expect_error("circ c 10", 1, 10, "expected a number (radius), found end of file");
}

TEST(SwpErrors, BinaryJunk) {
  std::string junk;
  for (int c = 0x00; c <= 0x1f; ++c) junk += static_cast<char>(c);
  junk += '\xff';
  // 0x09..0x0d are white space, so the first word is bytes 0x00..0x08.
  expect_error(junk, 1, 1, kKeywords + ", found '\\x00\\x01\\x02\\x03\\x04\\x05\\x06\\x07\\x08'");
  // Junk after a newline is placed on its line; bytes above 0x7e are shown in hex too.
  expect_error("bsp2 c 10 4 [0 0] [1 0] [1 1] [0 1]\n\x0e\x1f\xff", 2, 1, kKeywords + ", found '\\x0E\\x1F\\xFF'");
  expect_error("circ c 10 \xfe\xff", 1, 11, "expected a number (radius), found '\\xFE\\xFF'");
  // Long junk is cut at 32 bytes.
  expect_error(
      std::string(40, '\x01'), 1, 1, kKeywords + ", found '" + [] {
        std::string shown;
        for (int i = 0; i < 32; ++i) shown += "\\x01";
        return shown;
      }() + "...'");
}

TEST(SwpErrors, WindowsLineEndingsCountLinesOnce) {
  expect_error("circ a 10 1\r\ncirc a 10 2\r\n", 2, 6,
               "expected a new name, found 'a' (already used by the object at line 1)");
}

TEST(SwpErrors, UnreadableFileIsReportedWithoutLine) {
  const std::filesystem::path missing = std::filesystem::path(SWEEP_TEST_DATA_DIR) / "no-such-file.swp";
  try {
    (void)sweep::io::load_swp_file(missing);
    FAIL() << "no error";
  } catch (const sweep::io::ParseError& e) {
    EXPECT_EQ(std::string(e.what()), missing.string() + ": cannot open: No such file or directory");
    EXPECT_EQ(e.line(), 0);
  }
}

TEST(SwpLayout, EmptyFileIsAnEmptyDocument) {
  EXPECT_TRUE(sweep::io::parse_swp("", "empty.swp").objects.empty());
  EXPECT_TRUE(sweep::io::parse_swp(" \n\t\r\n\n", "blank.swp").objects.empty());
  EXPECT_EQ(sweep::io::write_swp(sweep::io::parse_swp("")), "");
}

TEST(SwpLayout, KeywordsAreCaseInsensitive) {
  const sweep::Document doc = sweep::io::parse_swp(
      "Bez2 p 10 4 [-1 1] [-2 0] [-2 -1] [-1 -2]\nCIRC s 10 2\nsReV r 10 p\nGcyl g p s\nBSP3 b 2 4 [0 0 0] [1 0 0] [1 "
      "1 0] [1 1 1]");
  ASSERT_EQ(doc.objects.size(), 5u);
  EXPECT_EQ(doc.objects[0].kind(), sweep::ObjectKind::Bezier2);
  EXPECT_EQ(doc.objects[1].kind(), sweep::ObjectKind::Circle);
  EXPECT_EQ(doc.objects[2].kind(), sweep::ObjectKind::SurfaceOfRevolution);
  EXPECT_EQ(doc.objects[3].kind(), sweep::ObjectKind::GeneralizedCylinder);
  EXPECT_EQ(doc.objects[4].kind(), sweep::ObjectKind::BSpline3);
  // Names keep their case: 'P' is not 'p'.
  expect_error("circ p 10 1\nsrev s 10 P", 2, 11, kProfile + ", found 'P' (no object has that name)");
  // Written back in lower case.
  EXPECT_EQ(sweep::io::write_swp(sweep::io::parse_swp("CIRC c 10 2")), "circ c 10 2\n\n");
}

TEST(SwpLayout, FreeLayout) {
  // Points sharing lines, brackets touching numbers and keywords, tabs, no trailing newline.
  const sweep::Document loose =
      sweep::io::parse_swp("bez2 a\t2\n4 [0 0][1 1]\n[ 2\n2 ]   [3 -3]circ c 3 0.5\nsrev\ns 4 a");
  const sweep::Document tidy =
      sweep::io::parse_swp("bez2 a 2 4\n[0 0]\n[1 1]\n[2 2]\n[3 -3]\n\ncirc c 3 0.5\n\nsrev s 4 a\n");
  EXPECT_EQ(loose, tidy);
  ASSERT_EQ(loose.objects.size(), 3u);
  EXPECT_EQ(loose.objects[0].as<sweep::PointsPart>().points[3], glm::dvec3(3, -3, 0));
  EXPECT_EQ(loose.objects[1].location, (sweep::SourceLocation{4, 13}));
  EXPECT_EQ(loose.objects[2].location, (sweep::SourceLocation{5, 1}));
  // Signs and exponents are numbers.
  const sweep::Document numbers = sweep::io::parse_swp("bez2 a +2 +4 [+1 -0] [.5 5.] [1e-3 -2E+2] [3 3]");
  EXPECT_EQ(numbers.objects[0].as<sweep::StepsPart>().steps, 2);
  EXPECT_EQ(numbers.objects[0].as<sweep::PointsPart>().points[1], glm::dvec3(0.5, 5.0, 0.0));
  EXPECT_EQ(numbers.objects[0].as<sweep::PointsPart>().points[2], glm::dvec3(1e-3, -200.0, 0.0));
}

}  // namespace
