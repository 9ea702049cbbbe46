// Catmull-Rom splines: they pass through every point at its knot, equal the Barry-Goldman pyramid
// of Yuksel, Schaefer and Keyser written here from the paper, have continuous tangents, a C1 seam
// when closed, end tangents along the reflected end chords, tangents scaled by 1 - tension, and no
// NaN for repeated points.
#include "geometry/curves/catmull_rom.hpp"
#include "geometry/curves/bezier.hpp"
#include "geometry/curves/curve.hpp"

#include "model/evaluation/curve_evaluation.hpp"
#include "support/core_test_support.hpp"
#include "support/curve_kinds_test_support.hpp"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>

namespace {

using sweep::test::distance;

const std::vector<glm::dvec3> kOpen3D{{0, 0, 0}, {1, 2, -1}, {3, 2.5, 0.5}, {4, 0, 2}, {6, 1, 1}, {6.5, 3, -1}};
// Uneven spacing (swp/catmull-rom.swp): uniform knots overshoot here, the others do not.
const std::vector<glm::dvec3> kOpen2D =
    sweep::test::planar_points({{-5, 2.5}, {-4.2, 4}, {-3.9, 4.1}, {-3.6, 4}, {-3, 2.5}, {-2.4, 3.2}});
const std::vector<glm::dvec3> kClosed3D{{3, 0, -1}, {0, 1.5, 1}, {-3, 0, -1}, {0, -1.5, 1}, {3, 0, -1}};
const std::vector<glm::dvec3> kClosed2D = sweep::test::planar_points({{2, 0}, {0, 1}, {-1.5, 0.2}, {-1, -1}, {2, 0}});

constexpr double kAlphas[] = {0.0, 0.5, 1.0};

struct Case {
  std::string name;
  const std::vector<glm::dvec3>* points;
  bool planar;
  bool closed;
};
const Case kCases[] = {{"open 3D", &kOpen3D, false, false},
                       {"open 2D", &kOpen2D, true, false},
                       {"closed 3D", &kClosed3D, false, true},
                       {"closed 2D", &kClosed2D, true, true}};

/// The Catmull-Rom segment P1 -> P2 at s in [0, 1] by the Barry-Goldman pyramid (Yuksel,
/// Schaefer, Keyser 2011, eq. 1 and 2), knots t_{i+1} = t_i + |P_{i+1} - P_i|^alpha.
glm::dvec3 barry_goldman(const std::array<glm::dvec3, 4>& p, double alpha, double s) {
  std::array<double, 4> t{0.0, 0.0, 0.0, 0.0};
  for (std::size_t i = 0; i < 3; ++i) t[i + 1] = t[i] + std::pow(glm::length(p[i + 1] - p[i]), alpha);
  const double u = t[1] + s * (t[2] - t[1]);
  const auto blend = [u](const glm::dvec3& a, const glm::dvec3& b, double ta, double tb) {
    return ((tb - u) * a + (u - ta) * b) / (tb - ta);
  };
  const glm::dvec3 a1 = blend(p[0], p[1], t[0], t[1]), a2 = blend(p[1], p[2], t[1], t[2]),
                   a3 = blend(p[2], p[3], t[2], t[3]);
  return blend(blend(a1, a2, t[0], t[2]), blend(a2, a3, t[1], t[3]), t[1], t[2]);
}

/// The polygon with the neighbours every segment needs written out: reflected ends for an open
/// polygon, the wrapped points for a closed one (last = first).
std::vector<glm::dvec3> with_neighbours(const std::vector<glm::dvec3>& p) {
  const std::size_t n = p.size();
  if (p.front() == p.back()) {
    std::vector<glm::dvec3> out{p[n - 2]};
    out.insert(out.end(), p.begin(), p.end());
    out.push_back(p[1]);
    return out;
  }
  std::vector<glm::dvec3> out{2.0 * p[0] - p[1]};
  out.insert(out.end(), p.begin(), p.end());
  out.push_back(2.0 * p[n - 1] - p[n - 2]);
  return out;
}

glm::dvec3 direction(const glm::dvec3& v) {
  return glm::normalize(v);
}

TEST(CatmullRom, PassesThroughEveryPointAtItsKnot) {
  const int steps = 9;
  for (const Case& c : kCases) {
    const auto& p = *c.points;
    for (const double alpha : kAlphas) {
      for (const double tension : {0.0, 0.5, 0.9}) {
        const sweep::CurveSamples curve = sweep::evaluate_catmull_rom(p, steps, alpha, tension, c.planar);
        ASSERT_EQ(curve.frames.size(), (p.size() - 1) * steps + 1) << c.name;
        for (std::size_t k = 0; k < p.size(); ++k) {
          EXPECT_LE(distance(curve.frames[k * steps].V, p[k]), 1e-12 * sweep::test::extent_of(p))
              << c.name << " alpha " << alpha << " tension " << tension << " point " << k;
        }
      }
    }
  }
}

TEST(CatmullRom, SamplesEqualTheBarryGoldmanPyramid) {
  const int steps = 16;
  for (const Case& c : kCases) {
    const std::vector<glm::dvec3> q = with_neighbours(*c.points);
    for (const double alpha : kAlphas) {
      const sweep::CurveSamples curve = sweep::evaluate_catmull_rom(*c.points, steps, alpha, 0.0, c.planar);
      for (std::size_t k = 0; k + 1 < c.points->size(); ++k) {
        for (int s = 0; s <= steps; ++s) {
          const glm::dvec3 expected = barry_goldman({q[k], q[k + 1], q[k + 2], q[k + 3]}, alpha, double(s) / steps);
          EXPECT_LT(distance(curve.frames[k * steps + std::size_t(s)].V, expected),
                    1e-12 * sweep::test::extent_of(*c.points))
              << c.name << " alpha " << alpha << " segment " << k << " step " << s;
        }
      }
    }
  }
}

TEST(CatmullRom, TangentIsContinuousAtInteriorPoints) {
  for (const Case& c : kCases) {
    const auto& p = *c.points;
    const bool closed = c.closed;
    for (const double alpha : kAlphas) {
      for (const double tension : {0.0, 0.5}) {
        const sweep::CurveSamples curve = sweep::evaluate_catmull_rom(p, 8, alpha, tension, c.planar);
        EXPECT_TRUE(curve.corners.empty()) << c.name << " alpha " << alpha;
        for (std::size_t k = 1; k + 1 < p.size(); ++k) {
          const auto arriving = sweep::catmull_rom_piece(p, k - 1, closed, alpha, tension);
          const auto leaving = sweep::catmull_rom_piece(p, k, closed, alpha, tension);
          const glm::dvec3 in = direction(arriving[3] - arriving[2]), out = direction(leaving[1] - leaving[0]);
          EXPECT_LT(distance(in, out), 1e-12) << c.name << " alpha " << alpha << " point " << k;
          EXPECT_LT(distance(curve.frames[k * 8].T, out), 1e-12) << c.name << " alpha " << alpha << " point " << k;
        }
      }
    }
  }
}

TEST(CatmullRom, TensionScalesTheTangents) {
  for (const double alpha : kAlphas) {
    for (std::size_t k = 0; k + 1 < kOpen3D.size(); ++k) {
      const auto loose = sweep::catmull_rom_piece(kOpen3D, k, false, alpha, 0.0);
      for (const double tension : {0.25, 0.75, 0.999}) {
        const auto tense = sweep::catmull_rom_piece(kOpen3D, k, false, alpha, tension);
        EXPECT_LT(distance(tense[1] - tense[0], (1.0 - tension) * (loose[1] - loose[0])), 1e-12);
        EXPECT_LT(distance(tense[3] - tense[2], (1.0 - tension) * (loose[3] - loose[2])), 1e-12);
      }
    }
  }
}

TEST(CatmullRom, OpenEndsFollowTheEndChords) {
  // Reflected neighbours make the end tangent the end chord's direction for every alpha.
  for (const Case& c : kCases) {
    if (c.closed) continue;
    const auto& p = *c.points;
    for (const double alpha : kAlphas) {
      const sweep::CurveSamples curve = sweep::evaluate_catmull_rom(p, 5, alpha, 0.3, c.planar);
      EXPECT_FALSE(curve.closed);
      EXPECT_LT(distance(curve.frames.front().T, direction(p[1] - p[0])), 1e-12) << c.name;
      EXPECT_LT(distance(curve.frames.back().T, direction(p[p.size() - 1] - p[p.size() - 2])), 1e-12) << c.name;
    }
  }
  const auto neighbours = sweep::segment_neighbourhood(kOpen3D, 0, false);
  EXPECT_EQ(neighbours[0], 2.0 * kOpen3D[0] - kOpen3D[1]);
}

TEST(CatmullRom, ClosedCurveHasAC1Seam) {
  for (const Case& c : kCases) {
    const auto& p = *c.points;
    if (!c.closed) continue;
    for (const double alpha : kAlphas) {
      const sweep::CurveSamples curve = sweep::evaluate_catmull_rom(p, 12, alpha, 0.0, c.planar);
      EXPECT_TRUE(curve.closed) << c.name << " alpha " << alpha;
      EXPECT_EQ(curve.frames.front().V, curve.frames.back().V) << c.name;
      EXPECT_GT(glm::dot(curve.frames.front().T, curve.frames.back().T), 1.0 - 1e-12) << c.name;
      // The frames close too (the seam is spread), so a tube along it has no crack or kink.
      EXPECT_LT(distance(curve.frames.front().N, curve.frames.back().N), 1e-9) << c.name;
    }
  }
}

TEST(CatmullRom, ClosedWhenTheLastOfAtLeastFourPointsRepeatsTheFirst) {
  for (const Case& c : kCases) EXPECT_EQ(sweep::is_closed_interpolating(*c.points), c.closed) << c.name;
  const glm::dvec3 a(0, 0, 0), b(1, 0, 0), c(0, 1, 0);
  EXPECT_FALSE(sweep::is_closed_interpolating(std::vector<glm::dvec3>{a, b, a}));  // two distinct points make no loop
  EXPECT_FALSE(sweep::is_closed_interpolating(std::vector<glm::dvec3>{a, a}));
  EXPECT_TRUE(sweep::is_closed_interpolating(std::vector<glm::dvec3>{a, b, c, a}));
  // Within 1e-9 of the seam's size, as the editor keeps it closed (is_closed_polygon, edit.hpp).
  const std::vector<glm::dvec3> near{a, b, c, a + glm::dvec3(1e-10, 0, 0)};
  EXPECT_TRUE(sweep::is_closed_interpolating(near));
  EXPECT_TRUE(sweep::evaluate_catmull_rom(near, 8, 0.5, 0.0, true).closed);
  EXPECT_FALSE(sweep::is_closed_interpolating(std::vector<glm::dvec3>{a, b, c, a + glm::dvec3(1e-8, 0, 0)}));
}

TEST(CatmullRom, TwoPointsAreAStraightSegment) {
  const std::vector<glm::dvec3> p{{1, 2, 3}, {4, -2, 3}};
  for (const double alpha : kAlphas) {
    const sweep::CurveSamples curve = sweep::evaluate_catmull_rom(p, 10, alpha, 0.0, false);
    ASSERT_EQ(curve.frames.size(), 11u);
    for (const auto& f : curve.frames) {
      EXPECT_LT(sweep::test::distance_to_segment(f.V, p[0], p[1]), 1e-12);
      EXPECT_LT(distance(f.T, direction(p[1] - p[0])), 1e-12);
    }
  }
}

/// Repeated consecutive points for Catmull-Rom (every alpha) and Kochanek-Bartels.
std::vector<sweep::CurveSamples> curves_through(const std::vector<glm::dvec3>& p, int steps, bool planar) {
  std::vector<sweep::CurveSamples> curves;
  for (const double alpha : kAlphas) curves.push_back(sweep::evaluate_catmull_rom(p, steps, alpha, 0.0, planar));
  curves.push_back(sweep::evaluate_kochanek_bartels(p, steps, {}, planar));
  curves.push_back(sweep::evaluate_kochanek_bartels(p, steps, {0.3, -0.5, 0.4}, planar));
  return curves;
}

TEST(CatmullRom, RepeatedPointsGiveNoNaNAndPointSegments) {
  const glm::dvec3 a(0, 0, 0), b(1, 2, 0), c(3, 2, 1), d(4, 0, 0);
  const std::vector<std::vector<glm::dvec3>> polygons{
      {a, a, b, c}, {a, b, b, c, d}, {a, b, c, c, c, d}, {a, b, c, d, d},
      {a, a},       {a, a, a, a},    {a, b, b, c, a},    {a, a, b, c, d, a}};
  const int steps = 64;
  for (const auto& polygon : polygons) {
    for (const bool planar : {false, true}) {
      std::vector<glm::dvec3> p = polygon;
      if (planar) {
        for (auto& point : p) point.z = 0.0;
      }
      int index = 0;
      for (const sweep::CurveSamples& curve : curves_through(p, steps, planar)) {
        const std::string what = "polygon of " + std::to_string(p.size()) + " curve " + std::to_string(index++);
        for (std::size_t i = 0; i < curve.frames.size(); ++i) {
          ASSERT_EQ(sweep::test::frame_problem(curve.frames[i], 1e-12), "") << what << " sample " << i;
        }
        for (std::size_t k = 0; k + 1 < p.size(); ++k) {
          if (p[k] != p[k + 1]) continue;
          // A zero-length segment is the point itself, facing along its neighbouring samples.
          for (std::size_t i = k * steps; i <= (k + 1) * steps; ++i) {
            EXPECT_EQ(curve.frames[i].V, p[k]) << what << " sample " << i;
          }
          const std::size_t before = k * steps, after = (k + 1) * steps;
          const std::size_t neighbour = after + 1 < curve.frames.size() ? after + 1 : (before > 0 ? before - 1 : 0);
          if (curve.frames[neighbour].V == p[k]) continue;  // every point equal: no direction to follow
          EXPECT_GT(glm::dot(curve.frames[after].T, curve.frames[neighbour].T), 0.9) << what << " segment " << k;
        }
      }
    }
  }
}

TEST(CatmullRom, EvaluateCurveDispatchesCatmullRomObjects) {
  sweep::Object object;
  object.set_kind(sweep::ObjectKind::CatmullRom2);
  object.as<sweep::PointsPart>().points = kOpen2D;
  object.as<sweep::StepsPart>().steps = 7;
  object.as<sweep::AlphaPart>().alpha = 1.0;
  object.as<sweep::TensionPart>().tension = 0.25;
  const sweep::CurveSamples curve = sweep::evaluate_curve(object);
  ASSERT_EQ(static_cast<std::int64_t>(curve.frames.size()), sweep::curve_sample_count(object));
  const sweep::CurveSamples direct = sweep::evaluate_catmull_rom(kOpen2D, 7, 1.0, 0.25, true);
  for (std::size_t i = 0; i < curve.frames.size(); ++i) {
    EXPECT_EQ(curve.frames[i].V, direct.frames[i].V);
    EXPECT_EQ(curve.frames[i].N, direct.frames[i].N);
    EXPECT_EQ(curve.frames[i].B, glm::dvec3(0, 0, 1));
  }
  EXPECT_TRUE(curve.planar);
  object.set_kind(sweep::ObjectKind::CatmullRom3);  // a new kind starts from its defaults
  object.as<sweep::PointsPart>().points = kClosed3D;
  object.as<sweep::StepsPart>().steps = 7;
  EXPECT_TRUE(sweep::evaluate_curve(object).closed);
  EXPECT_FALSE(sweep::evaluate_curve(object).planar);
}

}  // namespace
