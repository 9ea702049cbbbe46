// Randomized property test: thousands of random control polygons (coincident, collinear,
// planar-in-z, along z, tiny down to 1e-300, huge) for every curve type and both frame methods,
// Catmull-Rom and Kochanek-Bartels splines (open and closed, random parameters) among them, and
// helices and torus knots of random size. Every frame must
// be finite, unit, orthonormal and right-handed, and T must be the normalized derivative wherever
// the derivative does not vanish.
#include "geometry/curves/catmull_rom.hpp"
#include "geometry/curves/curve.hpp"
#include "geometry/curves/helix.hpp"
#include "geometry/curves/kochanek_bartels.hpp"
#include "geometry/curves/torus_knot.hpp"

#include "model/evaluation/curve_evaluation.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <numeric>
#include <random>
#include <string>

namespace {

using sweep::ObjectKind;

bool finite(const glm::dvec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

/// Derivative of piece k of a piecewise Bezier curve at t (Bernstein form, independent of bezier.cpp).
glm::dvec3 bezier_derivative(const std::vector<glm::dvec3>& p, std::size_t k, double t) {
  const double s = 1.0 - t;
  return 3.0 * (s * s * (p[3 * k + 1] - p[3 * k]) + 2.0 * s * t * (p[3 * k + 2] - p[3 * k + 1]) +
                t * t * (p[3 * k + 3] - p[3 * k + 2]));
}

enum class Shape { Random, Coincident, Repeated, Collinear, PlanarInZ, AlongZ };
const char* name_of(Shape shape) {
  switch (shape) {
    case Shape::Random:
      return "random";
    case Shape::Coincident:
      return "coincident";
    case Shape::Repeated:
      return "repeated points";
    case Shape::Collinear:
      return "collinear";
    case Shape::PlanarInZ:
      return "planar in z";
    case Shape::AlongZ:
      return "along z";
  }
  return "?";
}

std::vector<glm::dvec3> random_polygon(std::mt19937& rng, Shape shape, std::size_t count, double scale, bool planar) {
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  const auto random_point = [&] { return scale * glm::dvec3(u(rng), u(rng), planar ? 0.0 : u(rng)); };
  std::vector<glm::dvec3> points;
  const glm::dvec3 origin = random_point();
  glm::dvec3 direction = random_point() / scale;
  if (glm::length(direction) < 1e-3) direction = glm::dvec3(1, 0, 0);
  while (points.size() < count) {
    switch (shape) {
      case Shape::Random:
        points.push_back(random_point());
        break;
      case Shape::Coincident:
        points.push_back(origin);
        break;
      case Shape::Repeated: {
        const glm::dvec3 p = random_point();
        const int copies = std::uniform_int_distribution<int>(1, 4)(rng);
        for (int c = 0; c < copies && points.size() < count; ++c) points.push_back(p);
        break;
      }
      case Shape::Collinear:
        points.push_back(origin + scale * u(rng) * direction);
        break;
      case Shape::PlanarInZ:
        points.push_back(glm::dvec3(random_point().x, random_point().y, origin.z));
        break;
      case Shape::AlongZ:
        points.push_back(glm::dvec3(origin.x, origin.y, planar ? 0.0 : scale * u(rng)));
        break;
    }
  }
  return points;
}

/// Derivative of a piece of the curve at t in [0, 1].
using PieceDerivative = std::function<glm::dvec3(std::size_t piece, double t)>;

/// Every frame finite, unit, orthonormal and right-handed; T the normalized derivative of the
/// piece the sample was computed from (the next piece's t = 0 at joints) wherever that derivative
/// is clearly non-zero.
void check_curve(const sweep::CurveSamples& curve, std::size_t pieces, const PieceDerivative& derivative, int steps,
                 double scale, const std::string& what, int& failures) {
  ASSERT_EQ(curve.frames.size(), pieces * static_cast<std::size_t>(steps) + 1) << what;
  for (std::size_t i = 0; i < curve.frames.size(); ++i) {
    const sweep::Frame& f = curve.frames[i];
    const bool ok = finite(f.V) && finite(f.T) && finite(f.N) && finite(f.B) &&
                    std::abs(glm::length(f.T) - 1.0) < 1e-9 && std::abs(glm::length(f.N) - 1.0) < 1e-9 &&
                    std::abs(glm::length(f.B) - 1.0) < 1e-9 && std::abs(glm::dot(f.T, f.N)) < 1e-9 &&
                    std::abs(glm::dot(f.T, f.B)) < 1e-9 && std::abs(glm::dot(f.N, f.B)) < 1e-9 &&
                    glm::length(f.B - glm::cross(f.T, f.N)) < 1e-9;
    if (!ok && ++failures <= 10) ADD_FAILURE() << what << ": sample " << i << " has no orthonormal right-handed frame";
    const std::size_t piece = std::min(i / static_cast<std::size_t>(steps), pieces - 1);
    const double t = static_cast<double>(i - piece * static_cast<std::size_t>(steps)) / steps;
    // Divided by the scale first, so the test's own length does not underflow at scale 1e-300.
    const glm::dvec3 d_scaled = derivative(piece, t) / scale;
    if (glm::length(d_scaled) > 1e-6) {
      const glm::dvec3 expected = glm::normalize(d_scaled);
      if (glm::length(f.T - expected) > 1e-6 && ++failures <= 10) {
        ADD_FAILURE() << what << ": sample " << i << " T is not the normalized derivative";
      }
    }
  }
}

void check_curve(const sweep::CurveSamples& curve, const std::vector<glm::dvec3>& points, ObjectKind kind, int steps,
                 double scale, const std::string& what, int& failures) {
  const bool bezier = kind == ObjectKind::Bezier2 || kind == ObjectKind::Bezier3;
  const auto pieces = static_cast<std::size_t>(sweep::piece_count(kind, static_cast<std::int64_t>(points.size())));
  const PieceDerivative derivative = [&](std::size_t piece, double t) {
    return bezier ? bezier_derivative(points, piece, t) : sweep::test::direct_bspline_derivative(points, piece, t);
  };
  check_curve(curve, pieces, derivative, steps, scale, what, failures);
}

TEST(FramesProperty, RandomControlPolygonsGiveOrthonormalFramesAndDerivativeTangents) {
  std::mt19937 rng(20261122);
  int failures = 0;
  int curves = 0;
  for (const ObjectKind kind : {ObjectKind::Bezier2, ObjectKind::Bezier3, ObjectKind::BSpline2, ObjectKind::BSpline3}) {
    const bool planar = sweep::is_planar_curve(kind);
    const bool bezier = kind == ObjectKind::Bezier2 || kind == ObjectKind::Bezier3;
    for (const Shape shape :
         {Shape::Random, Shape::Coincident, Shape::Repeated, Shape::Collinear, Shape::PlanarInZ, Shape::AlongZ}) {
      // 1e-150 and 1e-300: squared lengths underflow there (the fuzzer found non-unit tangents).
      for (const double scale : {1e-300, 1e-150, 1e-9, 1.0, 1e11}) {
        for (int trial = 0; trial < 25; ++trial) {
          const std::size_t pieces = std::uniform_int_distribution<std::size_t>(1, 4)(rng);
          const std::size_t count = bezier ? 3 * pieces + 1 : pieces + 3;
          const std::vector<glm::dvec3> points = random_polygon(rng, shape, count, scale, planar);
          const int steps = std::uniform_int_distribution<int>(1, 6)(rng);
          for (const auto method : {sweep::FrameMethod::Projection, sweep::FrameMethod::RotationMinimizing}) {
            const sweep::CurveSamples curve = bezier ? sweep::evaluate_bezier(points, steps, planar, {method})
                                                     : sweep::evaluate_bspline(points, steps, planar, {method});
            const std::string what = std::string(sweep::keyword(kind)) + " " + name_of(shape) + " scale " +
                                     std::to_string(scale) + " trial " + std::to_string(trial);
            check_curve(curve, points, kind, steps, scale, what, failures);
            ++curves;
          }
        }
      }
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GE(curves, 5000);
}

TEST(FramesProperty, CirclesOfEveryScaleHaveOrthonormalFrames) {
  for (const double radius : {1e-12, 1e-9, 1.0, 1e11}) {
    for (int steps : {1, 2, 3, 17, 1000}) {
      for (const sweep::Frame& f : sweep::evaluate_circle(radius, steps).frames) {
        ASSERT_TRUE(finite(f.V) && finite(f.T) && finite(f.N) && finite(f.B));
        EXPECT_NEAR(glm::length(f.T), 1.0, 1e-12);
        EXPECT_LT(glm::length(f.B - glm::cross(f.T, f.N)), 1e-12);
        EXPECT_NEAR(glm::dot(f.T, f.N), 0.0, 1e-12);
      }
    }
  }
}

/// Derivative of a cubic Bezier piece given by its 4 control points.
glm::dvec3 piece_derivative(const std::array<glm::dvec3, 4>& p, double t) {
  const double s = 1.0 - t;
  return 3.0 * (s * s * (p[1] - p[0]) + 2.0 * s * t * (p[2] - p[1]) + t * t * (p[3] - p[2]));
}

/// A parameter from its range, its ends and 0 included now and then.
double random_parameter(std::mt19937& rng, double lo, double hi) {
  const int pick = std::uniform_int_distribution<int>(0, 4)(rng);
  if (pick == 0) return lo;
  if (pick == 1) return std::min(hi, std::max(lo, 0.0));
  if (pick == 2) return hi;
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

/// A random cr or kb object: 2 to 8 points of `shape`, now and then closed (last point = first),
/// with random alpha, tension, continuity and bias.
sweep::Object random_interpolating(std::mt19937& rng, ObjectKind kind, Shape shape, double scale) {
  sweep::Object object;
  object.set_kind(kind);
  object.as<sweep::StepsPart>().steps = std::uniform_int_distribution<int>(1, 6)(rng);
  const auto count = std::uniform_int_distribution<std::size_t>(2, 8)(rng);
  object.as<sweep::PointsPart>().points = random_polygon(rng, shape, count, scale, sweep::is_planar_curve(kind));
  if (count >= 4 && std::uniform_int_distribution<int>(0, 2)(rng) == 0)
    object.as<sweep::PointsPart>().points.back() = object.as<sweep::PointsPart>().points.front();
  // Each draw is made for every kind, so both kinds see the same random sequence as before.
  const double alpha = random_parameter(rng, 0.0, 1.0);
  const bool kb = kind == ObjectKind::KochanekBartels2 || kind == ObjectKind::KochanekBartels3;
  object.as<sweep::TensionPart>().tension = kb ? random_parameter(rng, -1.0, 1.0) : random_parameter(rng, 0.0, 0.99);
  const double continuity = random_parameter(rng, -1.0, 1.0);
  const double bias = random_parameter(rng, -1.0, 1.0);
  if (auto* cr = object.find<sweep::AlphaPart>()) cr->alpha = alpha;
  if (auto* kb_shape = object.find<sweep::ContinuityBiasPart>()) *kb_shape = {continuity, bias};
  return object;
}

TEST(FramesProperty, InterpolatingSplinesGiveOrthonormalFramesAndDerivativeTangents) {
  std::mt19937 rng(20260514);
  int failures = 0;
  int curves = 0;
  for (const ObjectKind kind :
       {ObjectKind::CatmullRom2, ObjectKind::CatmullRom3, ObjectKind::KochanekBartels2, ObjectKind::KochanekBartels3}) {
    const bool kb = kind == ObjectKind::KochanekBartels2 || kind == ObjectKind::KochanekBartels3;
    for (const Shape shape :
         {Shape::Random, Shape::Coincident, Shape::Repeated, Shape::Collinear, Shape::PlanarInZ, Shape::AlongZ}) {
      for (const double scale : {1e-300, 1e-150, 1e-9, 1.0, 1e11}) {
        for (int trial = 0; trial < 20; ++trial) {
          const sweep::Object object = random_interpolating(rng, kind, shape, scale);
          const auto& points = object.as<sweep::PointsPart>().points;
          const bool closed = sweep::is_closed_interpolating(points);
          const PieceDerivative derivative = [&](std::size_t piece, double t) {
            return piece_derivative(
                kb ? sweep::kochanek_bartels_piece(
                         points, piece, closed,
                         {object.as<sweep::TensionPart>().tension, object.as<sweep::ContinuityBiasPart>().continuity,
                          object.as<sweep::ContinuityBiasPart>().bias})
                   : sweep::catmull_rom_piece(points, piece, closed, object.as<sweep::AlphaPart>().alpha,
                                              object.as<sweep::TensionPart>().tension),
                t);
          };
          for (const auto method : {sweep::FrameMethod::Projection, sweep::FrameMethod::RotationMinimizing}) {
            const sweep::CurveSamples curve = sweep::evaluate_curve(object, {method});
            const std::string what = std::string(sweep::keyword(kind)) + " " + name_of(shape) + " scale " +
                                     std::to_string(scale) + " trial " + std::to_string(trial) +
                                     (closed ? " closed" : "");
            check_curve(curve, points.size() - 1, derivative, object.as<sweep::StepsPart>().steps, scale, what,
                        failures);
            ++curves;
          }
        }
      }
    }
  }
  EXPECT_EQ(failures, 0);
  EXPECT_GE(curves, 4800);
}

/// 10^u for u uniform in [lo, hi].
double log_uniform(std::mt19937& rng, double lo, double hi) {
  return std::pow(10.0, std::uniform_real_distribution<double>(lo, hi)(rng));
}

TEST(FramesProperty, HelicesAndTorusKnotsOfEverySizeHaveOrthonormalFrames) {
  std::mt19937 rng(20260515);
  int failures = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double radius = log_uniform(rng, -12.0, 12.0);
    const int sign = std::uniform_int_distribution<int>(-1, 1)(rng);
    const double pitch = sign * log_uniform(rng, -12.0, 11.0);
    const double turns = log_uniform(rng, -2.0, 1.0);
    const int steps = std::uniform_int_distribution<int>(1, 64)(rng);
    const double rise = pitch / (2.0 * std::numbers::pi);
    for (const auto method : {sweep::FrameMethod::Projection, sweep::FrameMethod::RotationMinimizing}) {
      const sweep::CurveSamples helix = sweep::evaluate_helix(radius, pitch, turns, steps, {method});
      const double segments = static_cast<double>(helix.frames.size() - 1);
      const PieceDerivative derivative = [&](std::size_t piece, double t) {
        const double angle = 2.0 * std::numbers::pi * turns * (static_cast<double>(piece) + t) / segments;
        return glm::dvec3(-radius * std::sin(angle), radius * std::cos(angle), rise);
      };
      check_curve(helix, helix.frames.size() - 1, derivative, 1, std::max(radius, std::abs(rise)),
                  "helix trial " + std::to_string(trial), failures);
    }
  }
  for (int trial = 0; trial < 300; ++trial) {
    sweep::TorusKnotShape shape;
    do {
      shape.p = std::uniform_int_distribution<int>(1, 9)(rng);
      shape.q = std::uniform_int_distribution<int>(1, 9)(rng);
    } while (std::gcd(shape.p, shape.q) != 1);
    shape.major_radius = log_uniform(rng, -9.0, 12.0);
    shape.minor_radius = shape.major_radius * std::uniform_real_distribution<double>(0.001, 0.999)(rng);
    const int steps = std::uniform_int_distribution<int>(1, 400)(rng);
    for (const auto method : {sweep::FrameMethod::Projection, sweep::FrameMethod::RotationMinimizing}) {
      const sweep::CurveSamples knot = sweep::evaluate_torus_knot(shape, steps, {method});
      const std::string what = "knot trial " + std::to_string(trial);
      // Frames only: the tangent against the formula is checked in torus_knot_test.cpp.
      check_curve(
          knot, static_cast<std::size_t>(steps), [](std::size_t, double) { return glm::dvec3(0.0); }, 1,
          shape.major_radius, what, failures);
    }
  }
  EXPECT_EQ(failures, 0);
}

TEST(TangentRepair, RunsOfCoincidentPointsFaceTheNextDistinctPoint) {
  // A B-spline with its first four points equal: the first piece is a single point; its samples
  // take the direction towards where the curve goes next. The last piece, all equal again, takes
  // the direction it came from.
  const std::vector<glm::dvec3> points{{1, 1, 0}, {1, 1, 0}, {1, 1, 0}, {1, 1, 0}, {4, 5, 0},
                                       {7, 9, 0}, {7, 9, 0}, {7, 9, 0}, {7, 9, 0}};
  const sweep::CurveSamples curve = sweep::evaluate_bspline(points, 5, false);
  for (std::size_t i = 0; i <= 5; ++i) {
    const sweep::Frame& f = curve.frames[i];
    ASSERT_LT(glm::length(f.V - glm::dvec3(1, 1, 0)), 1e-12) << i;
    // The next distinct sample lies on the curve ahead; its direction from (1, 1) is not the
    // chord to (4, 5) but must point into the curve's travel: positive along (3, 4).
    EXPECT_GT(glm::dot(f.T, glm::dvec3(0.6, 0.8, 0.0)), 0.9) << i;
  }
  for (std::size_t i = curve.frames.size() - 6; i < curve.frames.size(); ++i) {
    ASSERT_LT(glm::length(curve.frames[i].V - glm::dvec3(7, 9, 0)), 1e-12) << i;
    EXPECT_GT(glm::dot(curve.frames[i].T, glm::dvec3(0.6, 0.8, 0.0)), 0.9) << i;
  }
}

}  // namespace
