// Inserting a point at a clicked curve parameter: a Bezier and a polyline keep their exact
// shape, a Catmull-Rom curve still passes through its old points and the new one, a B-spline
// passes exactly through the clicked place, closed curves stay closed, and the refusals.
#include "model/edit/edit_insert.hpp"

#include "io/swp/read.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace sweep {
namespace {

using glm::dvec3;
using sweep::test::edit_error;

constexpr const char* kText =
    "bez2 wave 8 7\n[0 0]\n[1 2]\n[2 2]\n[3 0]\n[4 -2]\n[5 -1]\n[6 1]\n"
    "bez2 drop 8 7\n[0 0]\n[1 1]\n[2 1]\n[2 0]\n[2 -1]\n[1 -1]\n[0 0]\n"
    "poly3 zig 4\n[0 0 0]\n[1 2 3]\n[2 0 1]\n[4 4 4]\n"
    "poly2 square 5\n[-1 -1]\n[1 -1]\n[1 1]\n[-1 1]\n[-1 -1]\n"
    "cr2 open 8 4\n[0 0]\n[1 1]\n[2 0]\n[3 1]\n"
    "cr2 loop 8 5\n[1 0]\n[0 1]\n[-1 0]\n[0 -1]\n[1 0]\n"
    "bsp2 arc 8 6\n[0 0]\n[1 2]\n[2 3]\n[3 3]\n[4 2]\n[5 0]\n"
    "bsp2 ring 8 8\n[1 0]\n[0 1]\n[-1 0]\n[0 -1]\n[1 -1]\n[1 0]\n[0 1]\n[-1 0]\n"
    "kb3 bent 8 3 continuity 0.5\n[0 0 0]\n[1 1 1]\n[2 0 0]\n"
    "circ round 16 1\n";

enum Index { kWave, kDrop, kZig, kSquare, kOpen, kLoop, kArc, kRing, kBent, kRound };

const std::vector<dvec3>& points(const Document& doc, int object) {
  return doc.objects[std::size_t(object)].as<PointsPart>().points;
}

std::size_t count(const Document& doc, int object) {
  return points(doc, object).size();
}

/// Where old parameter `u` of a Bezier curve went after piece `piece` was split at `t`.
double after_split(double u, int piece, double t) {
  if (u <= piece) return u;
  if (u >= piece + 1) return u + 1.0;
  const double s = u - piece;
  return s < t ? piece + s / t : piece + 1.0 + (s - t) / (1.0 - t);
}

/// The smallest distance from `p` to the curve, searched finely along its parameter range.
double distance_to_curve(const Object& curve, const dvec3& p, double pieces) {
  double best = INFINITY;
  const int n = 4000;
  for (int i = 0; i <= n; ++i) best = std::min(best, glm::length(curve_position(curve, pieces * i / n) - p));
  return best;
}

TEST(EditInsertAt, ABezierClickSplitsThePieceAndKeepsTheExactShape) {
  for (const int object : {int(kWave), int(kDrop)}) {
    for (const double parameter : {0.3, 1.75}) {
      Document doc = io::parse_swp(kText);
      const Object before = doc.objects[std::size_t(object)];
      EXPECT_EQ(inserted_point_index(before, parameter), parameter < 1 ? 3 : 6);
      insert_point_at(doc, object, parameter);
      const Object& after = doc.objects[std::size_t(object)];
      ASSERT_EQ(count(doc, object), before.as<PointsPart>().points.size() + 3);
      const int piece = int(std::floor(parameter));
      const double t = parameter - piece;
      EXPECT_NEAR(glm::length(points(doc, object)[std::size_t(3 * piece + 3)] - curve_position(before, parameter)), 0.0,
                  1e-12)
          << "the new joint is the clicked place";
      for (int i = 0; i <= 200; ++i) {
        const double u = 2.0 * i / 200;
        EXPECT_NEAR(glm::length(curve_position(after, after_split(u, piece, t)) - curve_position(before, u)), 0.0, 1e-9)
            << "object " << object << " parameter " << parameter << " at u = " << u;
      }
      EXPECT_EQ(is_closed_polygon(after), is_closed_polygon(before)) << "the drop stays closed";
    }
  }
}

TEST(EditInsertAt, ABezierJointIsRefused) {
  Document doc = io::parse_swp(kText);
  EXPECT_EQ(inserted_point_index(doc.objects[kWave], 1.0), -1);
  EXPECT_EQ(edit_error(doc, [&] { insert_point_at(doc, kWave, 1.0); }),
            "parameter 1 of curve 'wave' is the joint at point 3: there is a point there already");
}

TEST(EditInsertAt, APolylineGainsThePointOnItsSegmentAndKeepsItsShape) {
  for (const int object : {int(kZig), int(kSquare)}) {
    Document doc = io::parse_swp(kText);
    const Object before = doc.objects[std::size_t(object)];
    const double parameter = 1.25;
    EXPECT_EQ(inserted_point_index(before, parameter), 2);
    insert_point_at(doc, object, parameter);
    const Object& after = doc.objects[std::size_t(object)];
    ASSERT_EQ(count(doc, object), before.as<PointsPart>().points.size() + 1);
    const dvec3 expected = 0.75 * points(doc, object)[1] + 0.25 * points(doc, object)[3];
    EXPECT_NEAR(glm::length(points(doc, object)[2] - expected), 0.0, 1e-12) << "on its segment";
    // The same path: old parameters map to new ones piecewise linearly.
    for (int i = 0; i <= 300; ++i) {
      const double u = double(count(doc, object) - 2) * i / 300;
      const double v = u <= 1.0 ? u : u <= 1.25 ? 1.0 + (u - 1.0) / 0.25 : u <= 2.0 ? 2.0 + (u - 1.25) / 0.75 : u + 1;
      EXPECT_NEAR(glm::length(curve_position(after, v) - curve_position(before, u)), 0.0, 1e-9) << u;
    }
    EXPECT_EQ(is_closed_polygon(after), is_closed_polygon(before));
  }
}

TEST(EditInsertAt, ACatmullRomPassesThroughItsOldPointsAndTheClickedOne) {
  for (const int object : {int(kOpen), int(kLoop), int(kBent)}) {
    Document doc = io::parse_swp(kText);
    const Object before = doc.objects[std::size_t(object)];
    const double parameter = 1.4;
    const dvec3 clicked = curve_position(before, parameter);
    const int index = inserted_point_index(before, parameter);
    EXPECT_EQ(index, 2);
    insert_point_at(doc, object, parameter);
    const Object& after = doc.objects[std::size_t(object)];
    ASSERT_EQ(count(doc, object), before.as<PointsPart>().points.size() + 1);
    EXPECT_EQ(points(doc, object)[std::size_t(index)], clicked);
    // Each point k of the curve is at parameter k: the old ones, then the new one at 2.
    const std::vector<dvec3>& old = before.as<PointsPart>().points;
    for (std::size_t k = 0; k < old.size(); ++k) {
      const double v = k < 2 ? double(k) : double(k + 1);
      EXPECT_NEAR(glm::length(curve_position(after, v) - old[k]), 0.0, 1e-9) << "old point " << k;
    }
    EXPECT_NEAR(glm::length(curve_position(after, 2.0) - clicked), 0.0, 1e-9);
    EXPECT_EQ(is_closed_polygon(after), is_closed_polygon(before)) << "the loop stays closed";
  }
}

TEST(EditInsertAt, ACatmullRomPointIsRefused) {
  Document doc = io::parse_swp(kText);
  EXPECT_EQ(edit_error(doc, [&] { insert_point_at(doc, kOpen, 2.0); }),
            "parameter 2 of curve 'open' is point 2: there is a point there already");
}

TEST(EditInsertAt, ABSplinePassesExactlyThroughTheClickedPlaceAndChangesOnlyNearIt) {
  Document doc = io::parse_swp(kText);
  const Object before = doc.objects[kArc];
  const double parameter = 1.3;  // piece 1: points 1..4; the new point goes between 2 and 3
  const dvec3 clicked = curve_position(before, parameter);
  EXPECT_EQ(inserted_point_index(before, parameter), 3);
  insert_point_at(doc, kArc, parameter);
  const Object& after = doc.objects[kArc];
  ASSERT_EQ(count(doc, kArc), 7u);
  EXPECT_NEAR(glm::length(curve_position(after, 2.0) - clicked), 0.0, 1e-12) << "the joint Q centres";
  // Every piece of this short curve uses the new point, yet the curve stays within a few
  // percent of the control polygon's size of the old one, and its ends stay.
  const double size = 6.0;
  for (int i = 0; i <= 100; ++i) {
    const double u = 3.0 * i / 100;
    EXPECT_LT(distance_to_curve(after, curve_position(before, u), 4.0), 0.05 * size) << u;
  }
  EXPECT_EQ(curve_position(after, 0.0), curve_position(before, 0.0)) << "the start stays";
  EXPECT_EQ(curve_position(after, 4.0), curve_position(before, 3.0)) << "the end stays";
}

TEST(EditInsertAt, AClosedBSplineStaysClosedAndPassesThroughTheClickedPlace) {
  for (const double parameter : {0.5, 2.5, 4.25}) {  // 4.25: piece 4 wraps into the seam repeats
    Document doc = io::parse_swp(kText);
    const Object before = doc.objects[kRing];
    const dvec3 clicked = curve_position(before, parameter);
    const int index = inserted_point_index(before, parameter);
    insert_point_at(doc, kRing, parameter);
    const Object& after = doc.objects[kRing];
    ASSERT_EQ(count(doc, kRing), 9u);
    EXPECT_TRUE(is_closed_polygon(after)) << parameter;
    // The new point Q is at `index`; the joint it centres is at parameter index - 1.
    EXPECT_NEAR(glm::length(curve_position(after, double(index - 1)) - clicked), 0.0, 1e-12) << parameter;
    EXPECT_EQ(points(doc, kRing)[std::size_t(index)], (6.0 * clicked - points(doc, kRing)[std::size_t(index - 1)] -
                                                       points(doc, kRing)[std::size_t(index + 1)]) /
                                                          4.0);
  }
}

TEST(EditInsertAt, OtherKindsAndParametersOutOfRangeAreRefused) {
  Document doc = io::parse_swp(kText);
  EXPECT_EQ(edit_error(doc, [&] { insert_point_at(doc, kRound, 0.5); }),
            "'round' is a circle: it has no control points");
  EXPECT_EQ(edit_error(doc, [&] { insert_point_at(doc, kArc, 3.0); }),
            "cannot insert a point at parameter 3 of curve 'arc': it must be strictly between 0 and 3");
  EXPECT_EQ(edit_error(doc, [&] { insert_point_at(doc, kArc, 0.0); }),
            "cannot insert a point at parameter 0 of curve 'arc': it must be strictly between 0 and 3");
  EXPECT_EQ(edit_error(doc, [&] { insert_point_at(doc, kArc, NAN); }),
            "cannot insert a point at parameter nan of curve 'arc': it must be strictly between 0 and 3");
  EXPECT_EQ(inserted_point_index(doc.objects[kRound], 0.5), -1);
  EXPECT_EQ(inserted_point_index(doc.objects[kArc], 3.0), -1);
}

}  // namespace
}  // namespace sweep
