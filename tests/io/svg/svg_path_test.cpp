// SVG path data (svg/detail/path.hpp): every command absolute and relative gives the same curve, implicit
// repeats, the number grammar without blanks, exact lines and quadratics, closed subpaths, every
// message; rapidcheck: path data built from the grammar reads in any spacing, garbage never crashes.
#include "io/svg/detail/path.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <charconv>
#include <cmath>
#include <string>
#include <vector>

namespace sweep::io::svg_detail {
namespace {

constexpr std::size_t kNoCap = 1u << 30;

std::vector<BezierSubpath> read(std::string_view data) {
  const PathParse parsed = parse_path_data(data, kNoCap);
  EXPECT_EQ(parsed.error, "") << data;
  return parsed.subpaths;
}

std::string error_of(std::string_view data) {
  const PathParse parsed = parse_path_data(data, kNoCap);
  EXPECT_TRUE(parsed.subpaths.empty()) << data;
  return parsed.error;
}

void expect_same(std::string_view a, std::string_view b, double tolerance = 1e-12) {
  const std::vector<BezierSubpath> pa = read(a);
  const std::vector<BezierSubpath> pb = read(b);
  ASSERT_EQ(pa.size(), pb.size()) << a << " | " << b;
  for (std::size_t i = 0; i < pa.size(); ++i) {
    EXPECT_EQ(pa[i].closed, pb[i].closed) << a << " | " << b;
    ASSERT_EQ(pa[i].points.size(), pb[i].points.size()) << a << " | " << b;
    for (std::size_t k = 0; k < pa[i].points.size(); ++k) {
      EXPECT_NEAR(pa[i].points[k].x, pb[i].points[k].x, tolerance) << a << " | " << b << " point " << k;
      EXPECT_NEAR(pa[i].points[k].y, pb[i].points[k].y, tolerance) << a << " | " << b << " point " << k;
    }
  }
}

TEST(SvgPath, RelativeCommandsGiveTheSameCurveAsAbsoluteOnes) {
  expect_same("M10 20 L30 45", "m10 20 l20 25");
  expect_same("M10 20 H30 V45", "m10 20 h20 v25");
  expect_same("M10 20 H30 V45", "M10 20 L30 20 L30 45");
  expect_same("M1 2 C3 4 5 6 7 8 S11 12 13 14", "m1 2 c2 2 4 4 6 6 s4 4 6 6");
  expect_same("M1 2 Q3 4 5 6 T9 10", "m1 2 q2 2 4 4 t4 4");
  expect_same("M1 2 A5 3 30 1 0 9 4", "m1 2 a5 3 30 1 0 8 2");
  expect_same("M1 2 L5 2 L5 7 Z M20 20 L25 20", "m1 2 l4 0 l0 5 z m19 18 l5 0");
}

TEST(SvgPath, ImplicitRepeatsAndMovetoPairsAreLinetos) {
  expect_same("M0 0 10 0 10 10", "M0 0 L10 0 L10 10");
  expect_same("m1 1 2 0 0 2", "M1 1 L3 1 L3 3");
  expect_same("M0 0 C1 1 2 2 3 3 4 4 5 5 6 6", "M0 0 C1 1 2 2 3 3 C4 4 5 5 6 6");
  expect_same("M0 0 h1 2 3", "M0 0 H1 H3 H6");
  expect_same("M0 0 a1 1 0 0 1 2 0 1 1 0 0 1 2 0", "M0 0 a1 1 0 0 1 2 0 a1 1 0 0 1 2 0");
}

TEST(SvgPath, NumbersFollowTheGrammarNotTheBlanks) {
  expect_same("M1.5.5L-1-2", "M 1.5 0.5 L -1 -2");
  expect_same("M1e-3,0L1E2,+0", "M 0.001 0 L 100 0");
  expect_same("M0,0a1 1 0 001 1", "M 0 0 a 1 1 0 0 0 1 1");
  expect_same("M0 0a1,1,0,1,1,1,1", "M 0 0 a 1 1 0 1 1 1 1");
  expect_same("\n\tM 0 , 0\r\nL 1 , 1 ", "M0 0L1 1");
}

TEST(SvgPath, LinesHaveHandlesAtThirdsAndCubicsAreCopied) {
  const std::vector<BezierSubpath> line = read("M0 0 L3 6");
  ASSERT_EQ(line.size(), 1u);
  EXPECT_EQ(line[0].points, (std::vector<glm::dvec2>{{0, 0}, {1, 2}, {2, 4}, {3, 6}}));
  EXPECT_FALSE(line[0].closed);
  const std::vector<BezierSubpath> cubic = read("M0.1 0.2 C0.3 0.4 1e-7 -2.5 1234.5678 9");
  ASSERT_EQ(cubic.size(), 1u);
  EXPECT_EQ(cubic[0].points, (std::vector<glm::dvec2>{{0.1, 0.2}, {0.3, 0.4}, {1e-7, -2.5}, {1234.5678, 9}}));
}

glm::dvec2 cubic_at(const std::vector<glm::dvec2>& p, std::size_t first, double t) {
  const double s = 1.0 - t;
  return s * s * s * p[first] + 3.0 * s * s * t * p[first + 1] + 3.0 * s * t * t * p[first + 2] +
         t * t * t * p[first + 3];
}

TEST(SvgPath, QuadraticsAreTheSameCurveAsCubics) {
  // Q from (1, 2) by (7, -3) to (4, 9), then T reflecting (7, -3) about (4, 9) to (1, 21).
  const std::vector<BezierSubpath> quad = read("M1 2 Q7 -3 4 9 T 10 10");
  ASSERT_EQ(quad.size(), 1u);
  ASSERT_EQ(quad[0].points.size(), 7u);
  const glm::dvec2 q[2][3] = {{{1, 2}, {7, -3}, {4, 9}}, {{4, 9}, {1, 21}, {10, 10}}};
  for (int piece = 0; piece < 2; ++piece) {
    for (int k = 0; k <= 50; ++k) {
      const double t = k / 50.0;
      const double s = 1.0 - t;
      const glm::dvec2 expected = s * s * q[piece][0] + 2.0 * s * t * q[piece][1] + t * t * q[piece][2];
      const glm::dvec2 got = cubic_at(quad[0].points, static_cast<std::size_t>(3 * piece), t);
      EXPECT_NEAR(got.x, expected.x, 1e-12);
      EXPECT_NEAR(got.y, expected.y, 1e-12);
    }
  }
  // S reflects the previous cubic's second handle; after a line it starts at the current point.
  expect_same("M0 0 C1 2 3 4 5 5 S9 9 10 10", "M0 0 C1 2 3 4 5 5 C7 6 9 9 10 10");
  expect_same("M0 0 L5 5 S9 9 10 10", "M0 0 L5 5 C5 5 9 9 10 10");
  expect_same("M0 0 L5 5 T10 10", "M0 0 L5 5 Q5 5 10 10");
}

TEST(SvgPath, ClosedSubpathsEndOnTheirFirstPoint) {
  const std::vector<BezierSubpath> square = read("M0 0 L1 0 L1 1 Z");
  ASSERT_EQ(square.size(), 1u);
  EXPECT_TRUE(square[0].closed);
  EXPECT_EQ(square[0].points.size(), 10u);  // the closing line is drawn
  EXPECT_EQ(square[0].points.back(), square[0].points.front());
  const std::vector<BezierSubpath> already = read("M0 0 L1 0 L0 0 Z");
  ASSERT_EQ(already.size(), 1u);
  EXPECT_EQ(already[0].points.size(), 7u);  // no zero-length closing line
  EXPECT_TRUE(already[0].closed);
  // After Z a drawing command starts a new subpath at the closed one's first point.
  const std::vector<BezierSubpath> after = read("M2 3 L1 0 Z L5 5");
  ASSERT_EQ(after.size(), 2u);
  EXPECT_EQ(after[1].points.front(), glm::dvec2(2, 3));
  EXPECT_FALSE(after[1].closed);
  for (const char* next : {"L5 5", "H5", "V5", "C1 1 2 2 5 5", "S2 2 5 5", "Q1 1 5 5", "T5 5", "A1 1 0 0 1 5 5"}) {
    const std::vector<BezierSubpath> drawn = read(std::string("M2 3 L1 0 Z ") + next);
    ASSERT_EQ(drawn.size(), 2u) << next;
    EXPECT_EQ(drawn[1].points.front(), glm::dvec2(2, 3)) << next;
    EXPECT_EQ(drawn[1].points.size() % 3, 1u) << next;
  }
}

TEST(SvgPath, MovetosAloneDrawNothing) {
  EXPECT_TRUE(read("").empty());
  EXPECT_TRUE(read("  ").empty());
  EXPECT_TRUE(read("M1 1").empty());
  EXPECT_TRUE(read("M1 1 M2 2 Z").empty());
  EXPECT_EQ(read("M1 1 M2 2 L3 3").size(), 1u);
}

TEST(SvgPath, EveryProblemHasItsMessage) {
  EXPECT_EQ(error_of("M 0 0 C 1 2 x"), "expected a number after 'C' in path data, found 'x'");
  EXPECT_EQ(error_of("L 0 0"), "expected 'M' or 'm' at the start of path data, found 'L'");
  EXPECT_EQ(error_of("M0 0 L1"), "expected a number after 'L' in path data, found the end of the path data");
  EXPECT_EQ(error_of("M0 0 A 1 1 0 2 0 1 1"), "expected the large-arc flag (0 or 1) after 'A' in path data, found '2'");
  EXPECT_EQ(error_of("M0 0 a 1 1 0 0 x 1 1"), "expected the sweep flag (0 or 1) after 'a' in path data, found 'x'");
  EXPECT_EQ(error_of("M0 0 L1 1 X2"), "expected a path command (one of M L H V C S Q T A Z) in path data, found 'X2'");
  EXPECT_EQ(error_of("M0 0 L1 1 Z 5"), "expected a path command after 'Z' in path data, found '5'");
  EXPECT_EQ(error_of("M 1e999 0"), "expected a number after 'M' in path data, found '1e999'");
  EXPECT_EQ(error_of("M0 0 L1 1 e"), "expected a path command (one of M L H V C S Q T A Z) in path data, found 'e'");
  const PathParse capped = parse_path_data("M0 0 h1 h1 h1", 6);
  EXPECT_EQ(capped.error, "expected at most 6 control points, found more in this path data");
  EXPECT_TRUE(capped.subpaths.empty());
  EXPECT_EQ(parse_path_data("M0 0 h1 h1", 7).error, "");
}

TEST(SvgPath, NumberListsReadTheSameGrammar) {
  EXPECT_EQ(parse_number_list("1,2 3-4.5.5", "in points", 10).numbers, (std::vector<double>{1, 2, 3, -4.5, 0.5}));
  EXPECT_EQ(parse_number_list("1 x", "in points", 10).error, "expected a number in points, found 'x'");
  EXPECT_EQ(parse_number_list("1 2 3", "in viewBox", 2).error, "expected at most 2 numbers in viewBox");
}

// --- Properties -------------------------------------------------------------------------------

std::string number_text(int value, int decimals) {
  std::string text = std::to_string(value);
  if (decimals > 0) {
    text += '.';
    text += std::to_string(decimals);
  }
  return text;
}

/// A path built from the grammar: each command with its arguments (arc flags as 0/1), `separator`
/// between the numbers, `lead` (blanks or nothing) after each command letter.
std::string path_text(const std::vector<std::pair<char, std::vector<int>>>& commands, const std::string& separator,
                      const std::string& lead) {
  std::string text;
  for (const auto& [command, args] : commands) {
    text += command;
    for (std::size_t i = 0; i < args.size(); ++i) {
      text += i == 0 ? lead : separator;
      const bool flag = (command == 'A' || command == 'a') && (i == 3 || i == 4);
      text += flag ? std::to_string(args[i] & 1) : number_text(args[i], (args[i] & 3) == 0 ? 0 : args[i] & 7);
    }
    text += lead;
  }
  return text;
}

int arguments(char command) {
  switch (command & ~0x20) {
    case 'Z':
      return 0;
    case 'H':
    case 'V':
      return 1;
    case 'M':
    case 'L':
    case 'T':
      return 2;
    case 'S':
    case 'Q':
      return 4;
    case 'C':
      return 6;
    default:
      return 7;
  }
}

RC_GTEST_PROP(SvgPathProperties, GrammarPathsReadAlikeInAnySpacing, ()) {
  const auto length = *rc::gen::inRange(1, 12);
  std::vector<std::pair<char, std::vector<int>>> commands;
  commands.push_back({'M', *rc::gen::container<std::vector<int>>(2, rc::gen::inRange(-1000, 1000))});
  for (int i = 0; i < length; ++i) {
    const char command = *rc::gen::elementOf(std::string("MmLlHhVvCcSsQqTtAaZz"));
    commands.push_back({command, *rc::gen::container<std::vector<int>>(static_cast<std::size_t>(arguments(command)),
                                                                       rc::gen::inRange(-1000, 1000))});
  }
  const PathParse spaced = parse_path_data(path_text(commands, " ", " "), kNoCap);
  RC_ASSERT(spaced.error.empty());
  for (const BezierSubpath& subpath : spaced.subpaths) {
    RC_ASSERT(subpath.points.size() >= 4u);
    RC_ASSERT((subpath.points.size() - 1) % 3 == 0u);
    if (subpath.closed) RC_ASSERT(subpath.points.back() == subpath.points.front());
  }
  const std::string separator = *rc::gen::element<std::string>(",", " , ", "\n", "\t,");
  const std::string lead = *rc::gen::element<std::string>("", "\n ", "\t");
  const PathParse other = parse_path_data(path_text(commands, separator, lead), kNoCap);
  RC_ASSERT(other.error.empty());
  RC_ASSERT(other.subpaths.size() == spaced.subpaths.size());
  for (std::size_t i = 0; i < other.subpaths.size(); ++i) {
    RC_ASSERT(other.subpaths[i].points == spaced.subpaths[i].points);
    RC_ASSERT(other.subpaths[i].closed == spaced.subpaths[i].closed);
  }
}

RC_GTEST_PROP(SvgPathProperties, GarbageNeverCrashesAndErrorsLeaveNothing, ()) {
  const std::string text =
      *rc::gen::container<std::string>(rc::gen::elementOf(std::string("MmLlHhVvCcSsQqTtAaZz0123456789.-+eE ,\tx\n")));
  const PathParse parsed = parse_path_data(text, 1000);
  if (!parsed.error.empty()) {
    RC_ASSERT(parsed.subpaths.empty());
    RC_ASSERT(parsed.error.starts_with("expected "));
  }
  for (const BezierSubpath& subpath : parsed.subpaths) {
    RC_ASSERT((subpath.points.size() - 1) % 3 == 0u);
    RC_ASSERT(subpath.points.size() >= 4u);
  }
}

}  // namespace
}  // namespace sweep::io::svg_detail
