// SVG out, then SVG in (svg/export.hpp, svg/import.hpp): importing what `sweep export --format svg`
// wrote gives each planar curve back as a bez2 whose control points are the curve's Bezier pieces
// to 1e-9 (a bez2 its own points; bsp2, cr2 and kb2 their exact conversions; a polyline its
// segments as straight cubics), a closed curve closed, and a circle within the importer's arc
// tolerance.
#include "io/svg/export.hpp"
#include "io/svg/import.hpp"

#include "io/swp/read.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace sweep {
namespace {

using test::ScratchFolder;

// Awkward decimals and coordinates far from 1, so only exact numbers survive the trip.
constexpr const char* kCurves =
    "bez2 wave 8 7\n[0.1 0.2] [1 2.3] [3 2.5] [4.7 -1e-7] [6 0] [7 3.3333333333333335] [9 123.456789]\n"
    "bez2 loop 8 7\n[1 0] [1 1] [-1 1] [-1 0] [-1 -1] [1 -1] [1 0]\n"
    "bsp2 spline 8 6\n[-1 1] [-1.2 0.5] [-0.8 0] [-1 -0.5] [-1 -1] [-0.5 -1.2]\n"
    "cr2 through 8 5 tension 0.2\n[0 0] [1 0.7] [2.5 0.1] [3 -2] [4 -1]\n"
    "kb2 star 8 6 tension 0.1 continuity 0.5 bias -0.2\n[2 0] [0.3 0.4] [0 2] [-2 0] [0 -2] [2 0]\n"
    "poly2 zig 4\n[0 0] [1 1] [2 -0.5] [3.25 1]\n"
    "circ ring 16 1.5\n";

/// The document `sweep import` makes of `sweep export --format svg` of kCurves.
Document exported_and_imported(const Document& doc) {
  const ScratchFolder folder("svg_round_trip");
  const io::SvgExport written = io::export_curves_svg(doc, "curves.swp", (folder.path() / "curves").string());
  EXPECT_EQ(written.curves, 7u);
  return io::import_svg_drawing(written.path, "unnamed", 1.0);
}

/// The control points of `pieces` as one Bezier curve: the first point, then three per piece.
std::vector<glm::dvec3> joined(const std::vector<BezierPiece>& pieces) {
  std::vector<glm::dvec3> points{pieces.front()[0]};
  for (const BezierPiece& piece : pieces) points.insert(points.end(), piece.begin() + 1, piece.end());
  return points;
}

void expect_same_points(const std::vector<glm::dvec3>& got, const std::vector<glm::dvec3>& expected,
                        const std::string& name) {
  ASSERT_EQ(got.size(), expected.size()) << name;
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_LE(glm::distance(got[i], expected[i]), 1e-9) << name << " point " << i;
  }
}

class SvgRoundTrip : public ::testing::Test {
 protected:
  const Document original = io::parse_swp(kCurves, "curves.swp");
  const Document imported = exported_and_imported(original);
};

TEST_F(SvgRoundTrip, EveryCurveComesBackUnderItsNameAsABez2) {
  ASSERT_EQ(imported.objects.size(), original.objects.size());
  for (std::size_t i = 0; i < original.objects.size(); ++i) {
    EXPECT_EQ(imported.objects[i].name, original.objects[i].name);
    EXPECT_EQ(imported.objects[i].kind(), ObjectKind::Bezier2) << original.objects[i].name;
  }
}

TEST_F(SvgRoundTrip, ControlPointCurvesComeBackAsTheirBezierPiecesTo1e9) {
  // The six control-point curves: a bez2 its own points, the others their exact Bezier pieces.
  for (std::size_t i = 0; i < 6; ++i) {
    const Object& curve = original.objects[i];
    const std::vector<glm::dvec3> expected = joined(bezier_pieces(describe_curve(curve)));
    expect_same_points(imported.objects[i].as<PointsPart>().points, expected, curve.name);
  }
  expect_same_points(imported.objects[0].as<PointsPart>().points, original.objects[0].as<PointsPart>().points,
                     "wave as written");
}

TEST_F(SvgRoundTrip, ClosedCurvesStayClosedAndOpenOnesOpen) {
  for (std::size_t i = 0; i < 6; ++i) {
    const std::vector<glm::dvec3>& points = imported.objects[i].as<PointsPart>().points;
    const bool closed_before = bezier_pieces(describe_curve(original.objects[i])).back()[3] ==
                               bezier_pieces(describe_curve(original.objects[i])).front()[0];
    EXPECT_EQ(points.back() == points.front(), closed_before) << original.objects[i].name;
  }
  EXPECT_EQ(imported.objects[1].as<PointsPart>().points.back(), glm::dvec3(1, 0, 0));
}

TEST_F(SvgRoundTrip, ACircleComesBackOnItsCircleWithinTheArcTolerance) {
  // The importer splits arcs into cubics within 2.8e-4 times the radius (svg/import.hpp).
  const Object& ring = imported.objects[6];
  const CurveSamples samples = evaluate_curve(ring);
  ASSERT_FALSE(samples.frames.empty());
  for (const Frame& f : samples.frames) {
    EXPECT_NEAR(glm::length(f.V), 1.5, 2.8e-4 * 1.5);
  }
  const std::vector<glm::dvec3>& points = ring.as<PointsPart>().points;
  EXPECT_EQ(points.front(), points.back());
}

}  // namespace
}  // namespace sweep
