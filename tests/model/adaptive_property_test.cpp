// Property-based tests (rapidcheck) of adaptive sampling's promises (core/adaptive.hpp): on random
// control polygons of every control-point kind, with cusps, straight runs (also turning back on
// themselves), runs of coincident points and curves that are a single point, and tolerances from
// 1e-5 to 1e-1 of the curve's size,
//  - every chord stays within D of the exact curve (measured by curve_deviation, 64 times denser),
//  - every part between consecutive samples turns at most kMaxTurn,
//  - every joint between cubic pieces is a sample, the parameters increase, the frames are unit
//    and orthonormal, and nothing is capped.
// Circles and helices get exactly the count of the formula ceil(pi / acos(1 - D / R)) per turn,
// at least 2 pi / kMaxTurn = 8, and one segment fewer would break the bound; torus knots keep D.
#include "geometry/curves/adaptive.hpp"
#include "geometry/curves/bezier.hpp"
#include "geometry/curves/catmull_rom.hpp"
#include "geometry/curves/curve.hpp"
#include "geometry/curves/kochanek_bartels.hpp"
#include "io/swp/write.hpp"
#include "model/evaluation/deviation.hpp"

#include "geometry/curves/helix.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "support/curve_kinds_test_support.hpp"

#include <gtest/gtest.h>
#include <rapidcheck.h>
#include <rapidcheck/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace {

using sweep::ObjectKind;
using Piece = std::array<glm::dvec3, 4>;

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

/// The cubic Bezier pieces of a control-point curve, built as evaluate_curve builds them.
std::vector<Piece> pieces_of(const sweep::Object& o) {
  const std::vector<glm::dvec3>& p = o.as<sweep::PointsPart>().points;
  std::vector<Piece> pieces;
  const ObjectKind kind = o.kind();
  if (kind == ObjectKind::Bezier2 || kind == ObjectKind::Bezier3) {
    for (std::size_t k = 0; 3 * k + 3 < p.size(); ++k)
      pieces.push_back({p[3 * k], p[3 * k + 1], p[3 * k + 2], p[3 * k + 3]});
  } else if (kind == ObjectKind::BSpline2 || kind == ObjectKind::BSpline3) {
    for (std::size_t k = 0; k + 3 < p.size(); ++k) {
      pieces.push_back(sweep::bspline_piece_to_bezier({p[k], p[k + 1], p[k + 2], p[k + 3]}));
    }
  } else if (const auto* alpha = o.find<sweep::AlphaPart>()) {  // Catmull-Rom
    for (std::size_t k = 0; k + 1 < p.size(); ++k) {
      pieces.push_back(sweep::catmull_rom_piece(p, k, sweep::is_closed_interpolating(p), alpha->alpha,
                                                o.as<sweep::TensionPart>().tension));
    }
  } else if (const auto* shape = o.find<sweep::ContinuityBiasPart>()) {  // Kochanek-Bartels
    for (std::size_t k = 0; k + 1 < p.size(); ++k) {
      pieces.push_back(
          sweep::kochanek_bartels_piece(p, k, sweep::is_closed_interpolating(p),
                                        {o.as<sweep::TensionPart>().tension, shape->continuity, shape->bias}));
    }
  }
  return pieces;
}

double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

double largest_coordinate(const std::vector<glm::dvec3>& points) {
  double largest = 0.0;
  for (const glm::dvec3& p : points) largest = std::max({largest, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return largest;
}

/// "" if the adaptive sampling of a control-point curve for tolerance D keeps every promise of
/// adaptive.hpp, else the first one broken.
std::string adaptive_problem(const sweep::Object& curve, double tolerance) {
  const sweep::CurveSamples s = sweep::evaluate_curve(curve, {}, {tolerance, 0.0});
  const std::vector<Piece> pieces = pieces_of(curve);
  if (s.capped) return "capped";
  if (s.steps != 0) return "steps " + std::to_string(s.steps) + " instead of 0 (adaptive)";
  if (s.frames.size() < 2 || s.parameters.size() != s.frames.size()) {
    return std::to_string(s.frames.size()) + " frames, " + std::to_string(s.parameters.size()) + " parameters";
  }
  // Parameters rise strictly from 0 to the piece count, and every joint k is among them.
  if (s.parameters.front() != 0.0 || s.parameters.back() != static_cast<double>(pieces.size())) {
    return "parameters from " + std::to_string(s.parameters.front()) + " to " + std::to_string(s.parameters.back());
  }
  for (std::size_t i = 0; i + 1 < s.parameters.size(); ++i) {
    if (!(s.parameters[i] < s.parameters[i + 1])) return "parameters not increasing at " + std::to_string(i);
  }
  for (std::size_t k = 0; k <= pieces.size(); ++k) {
    if (!std::binary_search(s.parameters.begin(), s.parameters.end(), static_cast<double>(k))) {
      return "joint " + std::to_string(k) + " is not a sample";
    }
  }
  for (std::size_t i = 0; i < s.frames.size(); ++i) {
    const std::string problem = sweep::test::frame_problem(s.frames[i]);
    if (!problem.empty()) return "frame " + std::to_string(i) + ": " + problem;
  }
  // The bound, with a relative slack of 1e-9 for rounding: the samples and the reference points
  // are computed in double precision at coordinates up to the curve's size, and D >= 1e-5 of it,
  // so rounding moves a measured distance by far less than 1e-9 D.
  const double deviation = sweep::curve_deviation(curve, s, 64);
  if (!(deviation <= tolerance * (1.0 + 1e-9))) {
    return "deviation " + std::to_string(deviation) + " > tolerance " + std::to_string(tolerance);
  }
  // The turn limit. Checkable per part, on the piece's own derivative inside the part: no two
  // tangents there are more than kMaxTurn apart (what is_flat demands of the hodograph). Not
  // checkable on the sample tangents T alone: a joint's T is the next piece's leaving tangent
  // (at a corner it differs from the arriving one by the corner's turn, which no sampling can
  // reduce), and where the speed vanishes (cusps, coincident control points) T is a limit from
  // one side only. Left out: parts at the depth limit (1e-7 of a piece, accepted as they are so
  // that degenerate input ends) and tangents where the speed vanishes (no direction, see below);
  // a part whose chord is zero must be a point. The angle gets a slack for the rounding of a
  // short part's tangents at large coordinates.
  const double scale = largest_coordinate(curve.as<sweep::PointsPart>().points) +
                       sweep::test::extent_of(curve.as<sweep::PointsPart>().points);
  for (std::size_t i = 0; i + 1 < s.parameters.size(); ++i) {
    const double k = std::min(std::floor(s.parameters[i]), static_cast<double>(pieces.size() - 1));
    const double a = s.parameters[i] - k, b = s.parameters[i + 1] - k;
    if (b - a <= 1.5e-7) continue;
    const glm::dvec3 chord = s.frames[i + 1].V - s.frames[i].V;
    const double chord_length = glm::length(chord);
    const Piece& piece = pieces[static_cast<std::size_t>(k)];
    // The part's hodograph vector at a tangent, (b - a) d1 / 3, has no direction if it is below
    // the rounding of the coordinates (next to a cusp the part's control points can coincide
    // exactly while the true tangent still points back) or tiny beside the chord.
    const double noise = 64.0 * kEpsilon * scale;
    if (chord_length == 0.0) {
      // A part without a chord turns by more than pi unless it is a point: a loop. Exempt are
      // parts across the tip of a spike (a cusp, where the tangent reverses whatever the
      // sampling), whose ends are the same point when the walk meets the tip symmetrically: a
      // part of length L ~ 1e-7 there reaches only about |c''| L^2 / 2, some 1e-13 of the size.
      const double loop = std::max(noise, 1e-9 * sweep::test::extent_of(curve.as<sweep::PointsPart>().points));
      for (int j = 1; j < 16; ++j) {
        const glm::dvec3 p = sweep::evaluate_bezier_piece(piece, a + (b - a) * j / 16.0).position;
        if (glm::length(p - s.frames[i].V) > loop) {
          return "part " + std::to_string(i) + " (piece " + std::to_string(k) + ", t " + std::to_string(a) + " to " +
                 std::to_string(b) + ") is a loop without a chord";
        }
      }
      continue;
    }
    const double slack = 1e-9 + 1e-12 * scale / chord_length;
    std::vector<glm::dvec3> tangents;
    for (int j = 0; j <= 16; ++j) {
      const glm::dvec3 d1 = sweep::evaluate_bezier_piece(piece, a + (b - a) * j / 16.0).d1;
      if (glm::length(d1) * (b - a) / 3.0 > std::max(1e-9 * chord_length, noise)) tangents.push_back(d1);
    }
    for (std::size_t m = 0; m < tangents.size(); ++m) {
      for (std::size_t n = m + 1; n < tangents.size(); ++n) {
        const double angle = angle_between(tangents[m], tangents[n]);
        if (angle > sweep::kMaxTurn + slack) {
          return "part " + std::to_string(i) + " (piece " + std::to_string(k) + ", t " + std::to_string(a) + " to " +
                 std::to_string(b) + "): tangents " + std::to_string(angle) + " rad apart";
        }
      }
    }
  }
  return "";
}

/// How the random control polygon is made degenerate.
enum class Shape {
  Generic,     // random points on a small integer grid (collinear and equal points happen too)
  Cusp,        // Bezier: P3 = P0 + P1 - P2, a cusp at t = 1/2 (with P1 = P2 a spike); others: a triple point or a spike
  Straight,    // every point on one line, at random places along it (so the curve turns back)
  Coincident,  // a run of equal points
  OnePoint,    // every point the same
};

/// A random control-point curve of `kind`: a few pieces on an integer grid scaled by a power of
/// two, made degenerate as `shape` says; cr/kb get random clauses and are sometimes closed.
sweep::Object random_curve(ObjectKind kind) {
  const bool planar = sweep::is_planar_curve(kind);
  std::size_t count = 0;
  if (kind == ObjectKind::Bezier2 || kind == ObjectKind::Bezier3) {
    count = 3 * static_cast<std::size_t>(*rc::gen::inRange(1, 5)) + 1;
  } else if (kind == ObjectKind::BSpline2 || kind == ObjectKind::BSpline3) {
    count = static_cast<std::size_t>(*rc::gen::inRange(4, 9));
  } else {
    count = static_cast<std::size_t>(*rc::gen::inRange(2, 8));
  }
  const double unit = std::ldexp(1.0, *rc::gen::inRange(-12, 13));
  const auto coordinate = [&] { return unit * *rc::gen::inRange(-8, 9); };
  const auto point = [&] { return glm::dvec3(coordinate(), coordinate(), planar ? 0.0 : coordinate()); };
  std::vector<glm::dvec3> points(count);
  for (glm::dvec3& p : points) p = point();
  const Shape shape =
      *rc::gen::element(Shape::Generic, Shape::Cusp, Shape::Straight, Shape::Coincident, Shape::OnePoint);
  const auto index = [&](std::size_t below) {
    return static_cast<std::size_t>(*rc::gen::inRange<int>(0, static_cast<int>(below)));
  };
  switch (shape) {
    case Shape::Generic:
      break;
    case Shape::Cusp:
      if (kind == ObjectKind::Bezier2 || kind == ObjectKind::Bezier3) {
        const std::size_t k = index(count / 3);
        if (*rc::gen::arbitrary<bool>()) points[3 * k + 2] = points[3 * k + 1];
        points[3 * k + 3] = points[3 * k] + points[3 * k + 1] - points[3 * k + 2];
      } else if (count >= 3) {
        // A triple point (a B-spline passes through it with zero speed), or a spike: out to
        // points[i + 1] and straight back.
        const std::size_t i = index(count - 2);
        if (*rc::gen::arbitrary<bool>()) {
          points[i + 1] = points[i + 2] = points[i];
        } else {
          points[i + 2] = points[i];
        }
      }
      break;
    case Shape::Straight: {
      const glm::dvec3 origin = point();
      glm::dvec3 direction = point();
      if (direction == glm::dvec3(0.0)) direction.x = unit;
      for (glm::dvec3& p : points) p = origin + static_cast<double>(*rc::gen::inRange(-6, 7)) * direction;
      break;
    }
    case Shape::Coincident: {
      const std::size_t first = index(count - 1);
      const std::size_t last = first + 1 + index(count - first - 1);
      for (std::size_t i = first + 1; i <= last; ++i) points[i] = points[first];
      break;
    }
    case Shape::OnePoint:
      std::fill(points.begin(), points.end(), points.front());
      break;
  }
  sweep::Object curve;
  curve.set_kind(kind);
  curve.as<sweep::StepsPart>().steps = 4;
  if (sweep::is_interpolating(kind) && count >= 3 && *rc::gen::arbitrary<bool>()) points.back() = points.front();
  if ((kind == ObjectKind::BSpline2 || kind == ObjectKind::BSpline3) && *rc::gen::arbitrary<bool>()) {
    points.insert(points.end(), points.begin(), points.begin() + 3);  // closed: the first three again
  }
  curve.as<sweep::PointsPart>().points = std::move(points);
  if (kind == ObjectKind::CatmullRom2 || kind == ObjectKind::CatmullRom3) {
    curve.as<sweep::AlphaPart>().alpha = *rc::gen::inRange(0, 5) / 4.0;
    curve.as<sweep::TensionPart>().tension = *rc::gen::inRange(0, 4) / 4.0;
  } else if (kind == ObjectKind::KochanekBartels2 || kind == ObjectKind::KochanekBartels3) {
    curve.as<sweep::TensionPart>().tension = *rc::gen::inRange(-4, 5) / 4.0;
    curve.as<sweep::ContinuityBiasPart>().continuity = *rc::gen::inRange(-4, 5) / 4.0;
    curve.as<sweep::ContinuityBiasPart>().bias = *rc::gen::inRange(-4, 5) / 4.0;
  }
  return curve;
}

/// A tolerance from 1e-5 to 1e-1 of the curve's size (log-uniform); for a curve that is a single
/// point, any positive value.
double random_tolerance(const sweep::Object& curve) {
  const double extent = sweep::curve_extent(curve);
  const double share = std::pow(10.0, -5.0 + 4.0 * *rc::gen::inRange(0, 1001) / 1000.0);
  return extent > 0.0 ? share * extent : share;
}

void check_random_curve(ObjectKind kind) {
  const sweep::Object curve = random_curve(kind);
  const double tolerance = random_tolerance(curve);
  const std::string problem = adaptive_problem(curve, tolerance);
  if (!problem.empty()) {
    sweep::Document doc;
    doc.objects.push_back(curve);
    RC_LOG() << sweep::io::write_swp(doc) << "tolerance " << tolerance << "\n";
  }
  RC_ASSERT(problem == "");
}

RC_GTEST_PROP(AdaptiveCurves, BezierKeepsTheBoundTheTurnAndItsJoints, ()) {
  check_random_curve(*rc::gen::element(ObjectKind::Bezier2, ObjectKind::Bezier3));
}

RC_GTEST_PROP(AdaptiveCurves, BSplineKeepsTheBoundTheTurnAndItsJoints, ()) {
  check_random_curve(*rc::gen::element(ObjectKind::BSpline2, ObjectKind::BSpline3));
}

RC_GTEST_PROP(AdaptiveCurves, CatmullRomKeepsTheBoundTheTurnAndItsJoints, ()) {
  check_random_curve(*rc::gen::element(ObjectKind::CatmullRom2, ObjectKind::CatmullRom3));
}

RC_GTEST_PROP(AdaptiveCurves, KochanekBartelsKeepsTheBoundTheTurnAndItsJoints, ()) {
  check_random_curve(*rc::gen::element(ObjectKind::KochanekBartels2, ObjectKind::KochanekBartels3));
}

// ---- Analytic curves ----

/// ceil(pi / acos(1 - D / R)): the fewest chords over a circle of radius R whose sagitta
/// R (1 - cos(pi / n)) stays within D, written out independently of circle_segments.
int formula_segments(double radius, double tolerance) {
  return static_cast<int>(std::ceil(std::numbers::pi / std::acos(1.0 - tolerance / radius)));
}

/// Slack for a measured distance on a curve of size `size`: positions are rounded to a few units
/// in the last place of the coordinates, so the measurement carries that absolute error besides
/// the relative 1e-9 of the bound.
double measured_bound(double tolerance, double size) {
  return tolerance * (1.0 + 1e-9) + 64.0 * kEpsilon * size;
}

/// A radius 10^[-3, 6) and a tolerance 10^[-6, log10 0.07] of it.
std::pair<double, double> random_radius_and_tolerance() {
  const double radius = std::pow(10.0, -3.0 + 9.0 * *rc::gen::inRange(0, 1000) / 1000.0);
  const double low = -6.0, high = std::log10(0.07);
  const double ratio = std::pow(10.0, low + (high - low) * *rc::gen::inRange(0, 1001) / 1000.0);
  return {radius, ratio * radius};
}

RC_GTEST_PROP(AdaptiveCircle, SegmentsAreTheFormulasAndTheFewestWithinTheTolerance, ()) {
  const auto [radius, tolerance] = random_radius_and_tolerance();
  sweep::Object circle;
  circle.set_kind(ObjectKind::Circle);
  circle.as<sweep::StepsPart>().steps = 16;
  circle.as<sweep::RadiusPart>().radius = radius;
  const sweep::CurveSamples s = sweep::evaluate_curve(circle, {}, {tolerance, 0.0});
  const int n = formula_segments(radius, tolerance);
  RC_ASSERT(!s.capped);
  RC_ASSERT(n >= 9);  // D / R <= 0.07 needs more than the angle limit's 8
  RC_ASSERT(s.frames.size() == static_cast<std::size_t>(n) + 1);
  RC_ASSERT(s.closed);
  RC_ASSERT(s.frames.front().V == s.frames.back().V);
  // Within D as measured (8 points per chord: the middle, where the sagitta is, among them) ...
  RC_ASSERT(sweep::curve_deviation(circle, s, 8) <= measured_bound(tolerance, radius));
  // ... and one segment fewer would not be: exactly, and as measured.
  RC_ASSERT(radius * (1.0 - std::cos(std::numbers::pi / (n - 1))) > tolerance);
  const sweep::CurveSamples fewer = sweep::evaluate_circle(radius, n - 1);
  RC_ASSERT(sweep::curve_deviation(circle, fewer, 8) > tolerance);
}

TEST(AdaptiveCircle, NeverFewerThanEightSegments) {
  // D / R from just above 1 - cos(pi / 8) = 0.0761 (where the formula gives 8) to far more than
  // the diameter: the angle limit keeps 2 pi / kMaxTurn = 8 segments.
  EXPECT_EQ(2.0 * std::numbers::pi / sweep::kMaxTurn, 8.0);
  for (const double ratio : {0.077, 0.1, 0.5, 1.0, 2.0, 1e3, 1e300}) {
    sweep::Object circle;
    circle.set_kind(ObjectKind::Circle);
    circle.as<sweep::StepsPart>().steps = 3;
    circle.as<sweep::RadiusPart>().radius = 2.5;
    const sweep::CurveSamples s =
        sweep::evaluate_curve(circle, {}, {ratio * circle.as<sweep::RadiusPart>().radius, 0.0});
    EXPECT_EQ(s.frames.size(), 9u) << ratio;
    EXPECT_EQ(
        sweep::circle_segments(circle.as<sweep::RadiusPart>().radius, ratio * circle.as<sweep::RadiusPart>().radius), 8)
        << ratio;
    for (std::size_t i = 0; i + 1 < s.frames.size(); ++i) {
      EXPECT_LE(angle_between(s.frames[i].T, s.frames[i + 1].T), sweep::kMaxTurn + 1e-12) << ratio;
    }
  }
  // Just below 0.0761 the formula asks for 9.
  EXPECT_EQ(sweep::circle_segments(1.0, 0.0761), 9);
}

RC_GTEST_PROP(AdaptiveHelix, EachTurnHasTheCountOfItsCircle, ()) {
  const auto [radius, tolerance] = random_radius_and_tolerance();
  sweep::Object helix;
  helix.set_kind(ObjectKind::Helix);
  helix.as<sweep::StepsPart>().steps = 16;
  helix.as<sweep::RadiusPart>().radius = radius;
  helix.as<sweep::HelixCurve>().pitch = radius * *rc::gen::inRange(-40, 41) / 8.0;
  helix.as<sweep::HelixCurve>().turns = *rc::gen::inRange(1, 25) / 4.0;
  const sweep::CurveSamples s = sweep::evaluate_curve(helix, {}, {tolerance, 0.0});
  const int per_turn = formula_segments(radius, tolerance);
  RC_ASSERT(!s.capped);
  RC_ASSERT(s.frames.size() == static_cast<std::size_t>(std::ceil(per_turn * helix.as<sweep::HelixCurve>().turns)) + 1);
  RC_ASSERT(s.frames.size() ==
            static_cast<std::size_t>(sweep::helix_sample_count(per_turn, helix.as<sweep::HelixCurve>().turns)));
  // Its chords stray only sideways, as the circle's seen from +z.
  const double size = radius + std::abs(helix.as<sweep::HelixCurve>().pitch * helix.as<sweep::HelixCurve>().turns);
  RC_ASSERT(sweep::curve_deviation(helix, s, 8) <= measured_bound(tolerance, size));
}

RC_GTEST_PROP(AdaptiveTorusKnot, ChordsStayWithinTheTolerance, ()) {
  sweep::Object knot;
  knot.set_kind(ObjectKind::TorusKnot);
  knot.as<sweep::StepsPart>().steps = 16;
  do {
    knot.as<sweep::TorusKnotCurve>().knot_p = *rc::gen::inRange(1, 8);
    knot.as<sweep::TorusKnotCurve>().knot_q = *rc::gen::inRange(1, 8);
  } while (std::gcd(knot.as<sweep::TorusKnotCurve>().knot_p, knot.as<sweep::TorusKnotCurve>().knot_q) != 1);
  knot.as<sweep::TorusKnotCurve>().major_radius = *rc::gen::inRange(2, 9) / 2.0;
  knot.as<sweep::RadiusPart>().radius = knot.as<sweep::TorusKnotCurve>().major_radius * *rc::gen::inRange(1, 10) / 10.0;
  const double extent = sweep::curve_extent(knot);
  const double tolerance = extent * std::pow(10.0, -4.0 + 3.0 * *rc::gen::inRange(0, 1001) / 1000.0);
  const sweep::CurveSamples s = sweep::evaluate_curve(knot, {}, {tolerance, 0.0});
  RC_ASSERT(!s.capped);
  RC_ASSERT(s.closed);
  RC_ASSERT(sweep::curve_deviation(knot, s, 32) <= measured_bound(tolerance, extent));
  for (std::size_t i = 0; i + 1 < s.frames.size(); ++i) {
    RC_ASSERT(angle_between(s.frames[i].T, s.frames[i + 1].T) <= sweep::kMaxTurn + 1e-9);
  }
}

}  // namespace
