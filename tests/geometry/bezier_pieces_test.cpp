// The Bezier pieces a basis exposes (bezier_pieces, CurveBasis::pieces) are the curve: each piece
// evaluates to the basis's own positions and samples, consecutive pieces meet, and the analytic
// bases have none.
#include "geometry/curves/bezier.hpp"
#include "geometry/curves/catmull_rom.hpp"
#include "geometry/curves/circle.hpp"
#include "geometry/curves/curve.hpp"
#include "geometry/curves/helix.hpp"
#include "geometry/curves/kochanek_bartels.hpp"
#include "geometry/curves/polyline.hpp"
#include "geometry/curves/torus_knot.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace {

using sweep::BezierPiece;
using sweep::CurveDescriptor;

const std::vector<glm::dvec3> kWave{{0, 0, 0.5}, {1, 2, 0}, {3, 2.5, 1}, {4, -1, 0}, {6, 0, 2}, {7, 3, 0}, {9, 1, 0}};
// Closed rings: the last point repeats the first (Bezier, 3n + 1 points, and the interpolating
// bases), or the last three the first three (B-spline).
const std::vector<glm::dvec3> kRing{{2, 0, 0}, {2, 2, 0}, {-2, 2, 0}, {-2, 0, 0}, {-1, -3, 0}, {2, -2, 0}, {2, 0, 0}};
const std::vector<glm::dvec3> kBSplineRing{{2, 0, 0}, {0, 2, 0}, {-2, 0, 0}, {0, -3, 0},
                                           {2, 0, 0}, {0, 2, 0}, {-2, 0, 0}};

CurveDescriptor curve_of(const sweep::CurveBasis& basis, const std::vector<glm::dvec3>& points, bool planar) {
  CurveDescriptor c;
  c.basis = &basis;
  c.points = points;
  c.planar = planar;
  c.steps = 7;
  c.alpha = 0.5;
  c.spline = {0.25, basis.name == "Kochanek-Bartels" ? 0.5 : 0.0, -0.3};  // a kb with corners
  return c;
}

/// A curve of every control-point basis through `points`, or closed rings.
std::vector<CurveDescriptor> piece_curves(const std::vector<glm::dvec3>& points, bool closed, bool planar) {
  std::vector<CurveDescriptor> curves;
  for (const sweep::CurveBasis* basis : {&sweep::kBezierBasis, &sweep::kBSplineBasis, &sweep::kCatmullRomBasis,
                                         &sweep::kKochanekBartelsBasis, &sweep::kPolylineBasis}) {
    const bool bspline = basis == &sweep::kBSplineBasis;
    curves.push_back(curve_of(*basis, !closed ? points : bspline ? kBSplineRing : kRing, planar));
    EXPECT_EQ(sweep::is_closed(curves.back()), closed) << basis->name;
  }
  return curves;
}

/// The point of piece k at t in SWP terms: the curve parameter k + t.
glm::dvec3 piece_point(const std::vector<BezierPiece>& pieces, double parameter) {
  const double k = std::clamp(std::floor(parameter), 0.0, static_cast<double>(pieces.size() - 1));
  return sweep::evaluate_bezier_piece(pieces[static_cast<std::size_t>(k)], parameter - k).position;
}

void expect_pieces_are_the_curve(const CurveDescriptor& c) {
  SCOPED_TRACE(std::string(c.basis->name) + (c.planar ? " planar" : " 3D") +
               (sweep::is_closed(c) ? " closed" : " open"));
  const std::vector<BezierPiece> pieces = sweep::bezier_pieces(c);
  ASSERT_FALSE(pieces.empty());
  const sweep::CurveSamples samples = sweep::evaluate_curve(c);
  EXPECT_DOUBLE_EQ(samples.parameters.back(), static_cast<double>(pieces.size()));  // piece k: k..k+1
  const double tolerance = 1e-12 * sweep::curve_extent(c);
  for (std::size_t k = 0; k + 1 < pieces.size(); ++k) {
    EXPECT_LE(glm::distance(pieces[k][3], pieces[k + 1][0]), tolerance) << "joint " << k;
  }
  if (c.planar) {
    for (const BezierPiece& piece : pieces) {
      for (const glm::dvec3& p : piece) EXPECT_EQ(p.z, 0.0);
    }
  }
  for (std::size_t i = 0; i < samples.frames.size(); ++i) {
    const double u = samples.parameters[i];
    EXPECT_LE(glm::distance(piece_point(pieces, u), sweep::curve_position(c, u)), tolerance) << "at " << u;
    EXPECT_LE(glm::distance(piece_point(pieces, u), samples.frames[i].V), 1e-9 * sweep::curve_extent(c)) << "at " << u;
  }
}

TEST(BezierPieces, EveryControlPointBasisIsItsPiecesOpenAndClosedPlanarAnd3D) {
  for (const bool planar : {true, false}) {
    for (const bool closed : {false, true}) {
      for (const CurveDescriptor& c : piece_curves(kWave, closed, planar)) expect_pieces_are_the_curve(c);
    }
  }
}

TEST(BezierPieces, ThePieceCountIsTheBasisOwn) {
  EXPECT_EQ(sweep::bezier_pieces(curve_of(sweep::kBezierBasis, kWave, true)).size(), 2u);      // 3n + 1 points
  EXPECT_EQ(sweep::bezier_pieces(curve_of(sweep::kBSplineBasis, kWave, true)).size(), 4u);     // N - 3
  EXPECT_EQ(sweep::bezier_pieces(curve_of(sweep::kCatmullRomBasis, kWave, true)).size(), 6u);  // N - 1
  EXPECT_EQ(sweep::bezier_pieces(curve_of(sweep::kKochanekBartelsBasis, kWave, true)).size(), 6u);
  EXPECT_EQ(sweep::bezier_pieces(curve_of(sweep::kPolylineBasis, kWave, true)).size(), 6u);
}

TEST(BezierPieces, ABezierCurvesPiecesAreItsControlPointsBitForBit) {
  const std::vector<BezierPiece> pieces = sweep::bezier_pieces(curve_of(sweep::kBezierBasis, kWave, false));
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    for (std::size_t j = 0; j < 4; ++j) EXPECT_EQ(pieces[k][j], kWave[3 * k + j]);
  }
}

TEST(BezierPieces, APolylinesPiecesAreStraightFromPointToPoint) {
  EXPECT_TRUE(sweep::kPolylineBasis.straight);
  const std::vector<BezierPiece> pieces = sweep::bezier_pieces(curve_of(sweep::kPolylineBasis, kWave, false));
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    EXPECT_EQ(pieces[k][0], kWave[k]);
    EXPECT_EQ(pieces[k][3], kWave[k + 1]);
    const glm::dvec3 chord = glm::normalize(kWave[k + 1] - kWave[k]);
    for (const glm::dvec3& p : {pieces[k][1], pieces[k][2]}) {
      EXPECT_NEAR(glm::length(glm::cross(p - kWave[k], chord)), 0.0, 1e-12);  // on the segment's line
    }
  }
  for (const sweep::CurveBasis* curved :
       {&sweep::kBezierBasis, &sweep::kBSplineBasis, &sweep::kCatmullRomBasis, &sweep::kKochanekBartelsBasis}) {
    EXPECT_FALSE(curved->straight) << curved->name;
  }
}

TEST(BezierPieces, AnalyticCurvesHaveNone) {
  CurveDescriptor circle;
  circle.basis = &sweep::kCircleBasis;
  circle.radius = 2.0;
  circle.planar = true;
  EXPECT_TRUE(sweep::bezier_pieces(circle).empty());
  for (const sweep::CurveBasis* analytic : {&sweep::kCircleBasis, &sweep::kHelixBasis, &sweep::kTorusKnotBasis}) {
    EXPECT_EQ(analytic->pieces, nullptr) << analytic->name;
  }
}

}  // namespace
