// The rider track (rider_track.hpp) by its properties: arc length of exact curves, positions on
// the curve at the distance asked, constant speed however the parameter runs, orthonormal frames
// equal to the sampled ones at the samples and continuous between, closed loops without a jump,
// upright frames, phases and wrapping.
#include "geometry/surfaces/rider_track.hpp"
#include "geometry/curves/circle.hpp"
#include "geometry/curves/curve.hpp"
#include "geometry/curves/helix.hpp"
#include "geometry/curves/polyline.hpp"
#include "geometry/curves/torus_knot.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

#include <cmath>
#include <numbers>
#include <vector>

namespace sweep {
namespace {

constexpr double kPi = std::numbers::pi;

struct Path {
  std::vector<glm::dvec3> points;
  CurveDescriptor curve;
  RiderTrack track;
};

Path make_path(CurveDescriptor curve, std::vector<glm::dvec3> points, std::optional<glm::dvec3> up = {}) {
  Path p;
  p.points = std::move(points);
  p.curve = curve;
  p.curve.points = p.points;
  p.track = make_rider_track(p.curve, evaluate_curve(p.curve), up);
  return p;
}

CurveDescriptor circle(double radius, int steps) {
  CurveDescriptor c;
  c.basis = &kCircleBasis;
  c.planar = true;
  c.radius = radius;
  c.steps = steps;
  return c;
}

CurveDescriptor knot() {
  CurveDescriptor c;
  c.basis = &kTorusKnotBasis;
  c.steps = 300;
  c.knot_p = 2;
  c.knot_q = 3;
  c.major_radius = 2.0;
  c.radius = 0.8;
  return c;
}

CurveDescriptor bezier3(int steps) {
  CurveDescriptor c;
  c.steps = steps;
  return c;
}

/// A 3D Bezier whose parameter runs very unevenly (control points bunched at the start).
const std::vector<glm::dvec3> kUneven = {{0, 0, 0},  {0.01, 0.02, 0}, {0.02, 0.01, 0.03}, {3, 2, 1},
                                         {4, 0, -1}, {5, 1, 0.5},     {6, 3, 0}};

void expect_orthonormal(const Frame& f, const char* where) {
  EXPECT_NEAR(glm::length(f.T), 1.0, 1e-12) << where;
  EXPECT_NEAR(glm::length(f.N), 1.0, 1e-12) << where;
  EXPECT_NEAR(glm::dot(f.T, f.N), 0.0, 1e-12) << where;
  EXPECT_LT(glm::length(glm::cross(f.T, f.N) - f.B), 1e-12) << where;
}

TEST(RiderTrack, ACircleIsTwoPiRLongAndRiddenByItsAngle) {
  const double r = 1.7;
  const Path p = make_path(circle(r, 16), {});
  EXPECT_NEAR(p.track.length(), 2.0 * kPi * r, 1e-12 * r);
  for (const double s : {0.3, 1.0, 4.2, 9.9}) {
    const Frame f = track_frame_at(p.track, s);
    const double angle = s / r;
    EXPECT_NEAR(f.V.x, r * std::cos(angle), 1e-10 * r) << s;
    EXPECT_NEAR(f.V.y, r * std::sin(angle), 1e-10 * r) << s;
    EXPECT_LT(glm::length(f.T - glm::dvec3(-std::sin(angle), std::cos(angle), 0.0)), 1e-10) << s;
    EXPECT_EQ(f.B, glm::dvec3(0.0, 0.0, 1.0)) << "2D: B = +z";
    expect_orthonormal(f, "circle");
  }
}

TEST(RiderTrack, AStraightLineOfUnevenParameterIsRiddenAtItsDistance) {
  // x runs 0..3 along a line whose parameter speed varies by a factor of 100.
  const Path p = make_path(bezier3(4), {{0, 0, 0}, {0.01, 0, 0}, {0.02, 0, 0}, {3, 0, 0}});
  EXPECT_NEAR(p.track.length(), 3.0, 1e-12);
  for (double s = 0.0; s <= 3.0; s += 0.125) EXPECT_NEAR(track_frame_at(p.track, s).V.x, s, 1e-10) << s;
}

TEST(RiderTrack, EqualTimesGiveEqualArcLengthsOnAnyCurve) {
  for (const Path& p : {make_path(bezier3(3), kUneven), make_path(knot(), {})}) {
    const double length = p.track.length();
    const double step = 1e-4 * length;  // a chord this short is its arc to ~1e-9
    for (int k = 0; k < 200; ++k) {
      const double s = (k + 0.37) / 200.0 * (length - step);
      const double chord = glm::length(track_frame_at(p.track, s + step).V - track_frame_at(p.track, s).V);
      EXPECT_NEAR(chord / step, 1.0, 1e-6) << "at " << s;
    }
  }
}

TEST(RiderTrack, PositionsAreOnTheCurveAtTheirArcLength) {
  const Path p = make_path(bezier3(3), kUneven);
  // An independent arc length: 200 000 chords of the exact curve.
  const int n = 200'000;
  const double end = 2.0;  // two pieces
  std::vector<double> u(n + 1), s(n + 1, 0.0);
  glm::dvec3 previous = curve_position(p.curve, 0.0);
  for (int k = 0; k <= n; ++k) {
    u[k] = end * k / n;
    const glm::dvec3 at = curve_position(p.curve, u[k]);
    if (k > 0) s[k] = s[k - 1] + glm::length(at - previous);
    previous = at;
  }
  EXPECT_NEAR(p.track.length(), s[n], 1e-8 * s[n]);
  const double size = glm::length(glm::dvec3(6, 3, 1.5));
  for (const double share : {0.1, 0.33, 0.5, 0.77, 0.95}) {
    const double distance = share * p.track.length();
    const auto k = static_cast<std::size_t>(std::lower_bound(s.begin(), s.end(), distance) - s.begin());
    const double t = (distance - s[k - 1]) / (s[k] - s[k - 1]);
    const glm::dvec3 expected = curve_position(p.curve, u[k - 1] + t * (u[k] - u[k - 1]));
    EXPECT_LT(glm::length(track_frame_at(p.track, distance).V - expected), 1e-9 * size) << share;
  }
}

TEST(RiderTrack, FramesAreTheSampledOnesAtTheSamplesAndContinuousBetween) {
  for (const Path& p : {make_path(knot(), {}), make_path(bezier3(5), kUneven)}) {
    for (std::size_t i = 1; i + 1 < p.track.frames.size(); i += 7) {
      const Frame f = track_frame_at(p.track, p.track.lengths[i]);
      EXPECT_LT(glm::length(f.N - p.track.frames[i].N), 1e-9) << i;
      EXPECT_LT(glm::length(f.V - p.track.frames[i].V), 1e-9) << i;
    }
    const double step = 1e-4 * p.track.length();
    Frame before = track_frame_at(p.track, 0.0);
    for (double s = step; s < p.track.length(); s += step) {
      const Frame f = track_frame_at(p.track, s);
      expect_orthonormal(f, "3D");
      // Rotation-minimizing: N turns no more than T does (plus the seam's spread, tiny a step).
      ASSERT_LT(glm::length(f.N - before.N), 1.5 * glm::length(f.T - before.T) + 1e-3) << "a jump at " << s;
      before = f;
    }
  }
}

TEST(RiderTrack, AClosedLoopHasNoJumpAtItsWrap) {
  const Path p = make_path(knot(), {});
  ASSERT_TRUE(p.track.closed);
  const double eps = 1e-6 * p.track.length();
  const Frame end = track_frame_at(p.track, p.track.length() - eps);
  const Frame start = track_frame_at(p.track, eps);
  EXPECT_LT(glm::length(end.V - start.V), 3.0 * eps);
  EXPECT_LT(glm::length(end.N - start.N), 1e-4);
  EXPECT_LT(glm::length(end.T - start.T), 1e-4);
}

TEST(RiderTrack, UpKeepsBAsCloseToUpAsTheTangentAllows) {
  const glm::dvec3 up{0.0, 0.0, 1.0};
  const Path p = make_path(knot(), {}, up);
  for (int k = 0; k < 97; ++k) {
    const Frame f = track_frame_at(p.track, (k + 0.5) / 97.0 * p.track.length());
    expect_orthonormal(f, "up");
    const glm::dvec3 projected = up - glm::dot(up, f.T) * f.T;  // the best B has this direction
    EXPECT_NEAR(glm::dot(f.B, up), glm::length(projected), 1e-9) << k;
    EXPECT_NEAR(glm::dot(f.N, up), 0.0, 1e-9) << k;
  }
}

TEST(RiderTrack, UpAppliesToPlanarPathsToo) {
  const glm::dvec3 up{0.0, 1.0, 0.0};
  const Path p = make_path(circle(2.0, 24), {}, up);
  for (int k = 1; k < 24; k += 5) {
    if (std::abs(glm::dot(p.track.frames[std::size_t(k)].T, up)) > 0.999) continue;  // carried on there
    const Frame f = track_frame_at(p.track, p.track.lengths[std::size_t(k)] + 1e-3);
    const glm::dvec3 projected = up - glm::dot(up, f.T) * f.T;
    EXPECT_NEAR(glm::dot(f.B, up), glm::length(projected), 1e-9) << k;
  }
}

TEST(RiderTrack, UpCarriesTheFrameOnWhereTheTangentIsUp) {
  CurveDescriptor poly;
  poly.basis = &kPolylineBasis;
  const Path p = make_path(poly, {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 1, 0}}, glm::dvec3(0, 1, 0));
  for (double s = 0.0; s <= p.track.length(); s += 0.1) {
    const Frame f = track_frame_at(p.track, s);
    expect_orthonormal(f, "vertical segment");
    EXPECT_TRUE(std::isfinite(f.N.x) && std::isfinite(f.N.y) && std::isfinite(f.N.z)) << s;
  }
  EXPECT_LT(glm::length(track_frame_at(p.track, 1.5).N - track_frame_at(p.track, 0.5).N), 1e-12)
      << "the frame before the climb, carried on";
}

TEST(RiderTrack, APathOfOnePointStaysThere) {
  const Path p = make_path(bezier3(4), std::vector<glm::dvec3>(4, glm::dvec3(1, 2, 3)));
  EXPECT_EQ(p.track.length(), 0.0);
  const Frame f = track_frame_at(p.track, ride_distance(p.track, 3.3, 2.0, 0.5));
  EXPECT_EQ(f.V, glm::dvec3(1, 2, 3));
  expect_orthonormal(f, "a point");
}

TEST(RiderTrack, RideDistanceLoopsWithPhases) {
  const Path p = make_path(circle(1.0, 8), {});
  const double length = p.track.length();
  EXPECT_NEAR(ride_distance(p.track, 2.5, 10.0, 0.0), 0.25 * length, 1e-12);
  EXPECT_NEAR(ride_distance(p.track, 2.5, 10.0, 0.5), 0.75 * length, 1e-12);
  EXPECT_NEAR(ride_distance(p.track, 12.5, 10.0, 0.0), 0.25 * length, 1e-12);
  EXPECT_NEAR(ride_distance(p.track, -2.5, 10.0, 0.0), 0.75 * length, 1e-12);
  EXPECT_LT(ride_distance(p.track, 10.0, 10.0, 0.0), 1e-12);
  EXPECT_LT(ride_distance(p.track, 5.0, 10.0, 0.5), length);
}

TEST(RiderTrack, FrameMatrixIsTheAirplanesPlacement) {
  const Path p = make_path(knot(), {});
  const Frame f = track_frame_at(p.track, 1.234);
  const glm::dmat4 m = frame_matrix(f);
  EXPECT_EQ(glm::dvec3(m * glm::dvec4(0, 0, 1, 0)), f.T);
  EXPECT_EQ(glm::dvec3(m * glm::dvec4(1, 0, 0, 0)), f.N);
  EXPECT_EQ(glm::dvec3(m * glm::dvec4(0, 1, 0, 0)), f.B);
  EXPECT_EQ(glm::dvec3(m * glm::dvec4(0, 0, 0, 1)), f.V);
}

}  // namespace
}  // namespace sweep
