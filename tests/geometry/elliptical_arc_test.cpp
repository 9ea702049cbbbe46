// SVG elliptical arcs as cubics (elliptical_arc.hpp): the centre form of SVG 1.1 F.6.5 checked
// against arcs whose centre is known, and the cubic pieces sampled against the ellipse: every
// sample within the stated tolerance, at most 90 degrees a piece, the end point exact.
#include "geometry/curves/elliptical_arc.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

namespace sweep {
namespace {

constexpr double kPi = std::numbers::pi;

glm::dvec2 cubic_at(glm::dvec2 p0, glm::dvec2 p1, glm::dvec2 p2, glm::dvec2 p3, double t) {
  const double s = 1.0 - t;
  return s * s * s * p0 + 3.0 * s * s * t * p1 + 3.0 * s * t * t * p2 + t * t * t * p3;
}

/// A point in the coordinates of the unit circle the ellipse of `arc` is the image of.
glm::dvec2 to_unit_circle(const CentreArc& arc, glm::dvec2 p) {
  const glm::dvec2 d = p - arc.centre;
  const double c = std::cos(arc.phi);
  const double s = std::sin(arc.phi);
  return {(c * d.x + s * d.y) / arc.rx, (-s * d.x + c * d.y) / arc.ry};
}

/// The largest distance from the unit circle of any of 200 samples per piece of the cubics of
/// `arc`; also checks the pieces' count and angle and the exact end point.
double largest_error(const EndpointArc& arc) {
  const std::optional<CentreArc> centre = centre_arc(arc);
  EXPECT_TRUE(centre.has_value());
  const std::vector<glm::dvec2> points = arc_to_cubics(arc);
  EXPECT_EQ(points.size() % 3, 0u);
  const auto pieces = static_cast<double>(points.size() / 3);
  EXPECT_LE(std::abs(centre->delta_angle) / pieces, kArcMaxPieceAngle * (1.0 + 1e-12));
  EXPECT_EQ(points.back(), arc.to);
  double worst = 0.0;
  glm::dvec2 start = arc.from;
  for (std::size_t i = 0; i + 2 < points.size(); i += 3) {
    for (int k = 0; k <= 200; ++k) {
      const glm::dvec2 p = cubic_at(start, points[i], points[i + 1], points[i + 2], k / 200.0);
      worst = std::max(worst, std::abs(glm::length(to_unit_circle(*centre, p)) - 1.0));
    }
    start = points[i + 2];
  }
  return worst;
}

TEST(EllipticalArc, AQuarterCircleIsOnePieceWithinTheStatedTolerance) {
  const EndpointArc quarter{{1.0, 0.0}, {0.0, 1.0}, 1.0, 1.0, 0.0, false, true};
  EXPECT_EQ(arc_to_cubics(quarter).size(), 3u);
  const double error = largest_error(quarter);
  // The 4/3 tan(θ/4) handles: the cubic leaves the circle by at most 2.725e-4 of the radius.
  EXPECT_GT(error, 2.7e-4);
  EXPECT_LE(error, kArcRelativeError);
}

TEST(EllipticalArc, TheFourFlagCombinationsPickTheirCentreAndDirection) {
  // From (1, 0) to (0, 1) on circles of radius 1: centre (0, 0) or (1, 1).
  for (const bool large : {false, true}) {
    for (const bool sweep : {false, true}) {
      const std::optional<CentreArc> arc = centre_arc({{1.0, 0.0}, {0.0, 1.0}, 1.0, 1.0, 0.0, large, sweep});
      ASSERT_TRUE(arc.has_value());
      const glm::dvec2 expected = large == sweep ? glm::dvec2(1.0, 1.0) : glm::dvec2(0.0, 0.0);
      EXPECT_NEAR(glm::length(arc->centre - expected), 0.0, 1e-12) << large << sweep;
      EXPECT_EQ(arc->delta_angle > 0.0, sweep);
      EXPECT_NEAR(std::abs(arc->delta_angle), large ? 1.5 * kPi : 0.5 * kPi, 1e-12);
      EXPECT_NEAR(glm::length(point_on(*arc, arc->start_angle) - glm::dvec2(1.0, 0.0)), 0.0, 1e-12);
      EXPECT_NEAR(glm::length(point_on(*arc, arc->start_angle + arc->delta_angle) - glm::dvec2(0.0, 1.0)), 0.0, 1e-12);
    }
  }
}

TEST(EllipticalArc, RadiiTooSmallGrowUntilTheyReach) {
  // F.6.6: radius 1 cannot span 10, so it becomes 5 and the arc is a half circle about the middle.
  const std::optional<CentreArc> arc = centre_arc({{0.0, 0.0}, {10.0, 0.0}, 1.0, -1.0, 0.0, false, true});
  ASSERT_TRUE(arc.has_value());
  EXPECT_NEAR(arc->rx, 5.0, 1e-12);
  EXPECT_NEAR(arc->ry, 5.0, 1e-12);
  EXPECT_NEAR(glm::length(arc->centre - glm::dvec2(5.0, 0.0)), 0.0, 1e-12);
  EXPECT_NEAR(std::abs(arc->delta_angle), kPi, 1e-9);
  EXPECT_EQ(arc_to_cubics({{0.0, 0.0}, {10.0, 0.0}, 1.0, 1.0, 0.0, false, true}).size(), 6u);
}

TEST(EllipticalArc, ZeroRadiusIsALineAndNoMoveIsNoArc) {
  const std::vector<glm::dvec2> line = arc_to_cubics({{0.0, 0.0}, {3.0, 6.0}, 0.0, 2.0, 30.0, true, true});
  ASSERT_EQ(line.size(), 3u);
  EXPECT_EQ(line[0], glm::dvec2(1.0, 2.0));
  EXPECT_EQ(line[1], glm::dvec2(2.0, 4.0));
  EXPECT_EQ(line[2], glm::dvec2(3.0, 6.0));
  EXPECT_FALSE(centre_arc({{0.0, 0.0}, {3.0, 6.0}, 0.0, 2.0, 30.0, true, true}).has_value());
  EXPECT_TRUE(arc_to_cubics({{2.0, 2.0}, {2.0, 2.0}, 1.0, 1.0, 0.0, true, true}).empty());
}

// Found by the SVG fuzzer: ry = 1e-308 against a chord of length 5 overflowed the scaled radii to
// infinity and the piece count to NaN. An ellipse that thin is its chord within rounding.
TEST(EllipticalArc, RadiiTooUnequalToComputeAreTheStraightLineTheyAlmostAre) {
  for (const double ry : {1e-308, -1e-308, 1e-200, 1e-160}) {
    const EndpointArc arc{{1.0, 1.0}, {5.0, 5.0}, 1.0, ry, 1.0, false, true};
    const std::vector<glm::dvec2> points = arc_to_cubics(arc);
    ASSERT_FALSE(points.empty()) << ry;
    EXPECT_EQ(points.back(), glm::dvec2(5.0, 5.0)) << ry;
    for (const glm::dvec2& p : points) {
      EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y)) << ry;
      EXPECT_NEAR(p.x, p.y, 1e-9) << "off the chord from (1, 1) to (5, 5), ry " << ry;
    }
  }
}

TEST(EllipticalArc, RandomArcsStayOnTheirEllipseWithinTheTolerance) {
  std::mt19937 random(20261204);
  std::uniform_real_distribution<double> coordinate(-50.0, 50.0);
  std::uniform_real_distribution<double> radius(0.01, 60.0);
  std::uniform_real_distribution<double> angle(-720.0, 720.0);
  double worst = 0.0;
  for (int i = 0; i < 2000; ++i) {
    const EndpointArc arc{{coordinate(random), coordinate(random)},
                          {coordinate(random), coordinate(random)},
                          radius(random),
                          radius(random),
                          angle(random),
                          (i & 1) != 0,
                          (i & 2) != 0};
    worst = std::max(worst, largest_error(arc));
  }
  EXPECT_LE(worst, kArcRelativeError);
}

}  // namespace
}  // namespace sweep
