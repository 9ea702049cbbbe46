// Editing operations: each edit does what it says on real starter files, keeps closed polygons
// closed, keeps the document valid, and on error throws EditError with the exact message and
// leaves the document as it was.
#include "model/edit/edit.hpp"

#include "geometry/curves/bezier.hpp"
#include "geometry/curves/curve.hpp"
#include "geometry/surfaces/surface.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/file_limits.hpp"
#include "support/core_test_support.hpp"

#include "model/evaluation/curve_evaluation.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <functional>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;
using glm::dvec3;
using sweep::Change;
using sweep::Document;
using sweep::EditError;
using sweep::ObjectKind;

using sweep::test::load_starter;

using sweep::test::edit_error;

void expect_valid(const Document& doc) {
  EXPECT_NO_THROW(sweep::io::validate_document(doc));
}

/// A closed bez2 of two pieces (last point == first).
Document closed_bezier_document() {
  Document doc;
  sweep::Object curve;
  curve.set_kind(ObjectKind::Bezier2);
  curve.name = "loop";
  curve.as<sweep::StepsPart>().steps = 8;
  curve.as<sweep::PointsPart>().points = {{1, 0, 0},   {1, 1, 0},  {-1, 1, 0}, {-1, 0, 0},
                                          {-1, -1, 0}, {1, -1, 0}, {1, 0, 0}};
  doc.objects.push_back(curve);
  return doc;
}

// ---- move_point -------------------------------------------------------------------------------

TEST(EditMove, PlanarCurveDropsZAndChangesOnlyThatPoint) {
  Document doc = load_starter("core.swp");
  const Document before = doc;
  ASSERT_EQ(doc.objects[1].kind(), ObjectKind::BSpline2);
  const Change change = sweep::move_point(doc, 1, 2, {5.5, -6.25, 7.0});
  EXPECT_EQ(change.objects, std::vector<int>{1});
  EXPECT_FALSE(change.structure);
  for (std::size_t i = 0; i < doc.objects[1].as<sweep::PointsPart>().points.size(); ++i) {
    if (i == 2) {
      EXPECT_EQ(doc.objects[1].as<sweep::PointsPart>().points[i], dvec3(5.5, -6.25, 0.0));
    } else {
      EXPECT_EQ(doc.objects[1].as<sweep::PointsPart>().points[i], before.objects[1].as<sweep::PointsPart>().points[i]);
    }
  }
  for (std::size_t k : {0u, 2u, 3u}) EXPECT_EQ(doc.objects[k], before.objects[k]);
  expect_valid(doc);
}

TEST(EditMove, SpaceCurveKeepsZ) {
  Document doc = load_starter("core.swp");
  ASSERT_EQ(doc.objects[3].kind(), ObjectKind::BSpline3);
  sweep::move_point(doc, 3, 0, {1.5, 2.5, -3.5});
  EXPECT_EQ(doc.objects[3].as<sweep::PointsPart>().points[0], dvec3(1.5, 2.5, -3.5));
  expect_valid(doc);
}

TEST(EditMove, ClosedBSplineMovesTheRepeatedPointWithIt) {
  Document doc = load_starter("weird.swp");
  const sweep::Object& profile = doc.objects[0];
  ASSERT_EQ(profile.as<sweep::PointsPart>().points.size(), 11u);
  ASSERT_TRUE(sweep::is_closed_polygon(profile));
  EXPECT_EQ(sweep::seam_partners(profile, 1), (std::vector<int>{1, 9}));
  EXPECT_EQ(sweep::seam_partners(profile, 10), (std::vector<int>{10, 2}));
  EXPECT_EQ(sweep::seam_partners(profile, 5), (std::vector<int>{5}));
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(sweep::seam_partners(profile, i), (std::vector<int>{i, i + 8}));
    EXPECT_EQ(sweep::seam_partners(profile, i + 8), (std::vector<int>{i + 8, i}));
  }
  for (int i = 3; i < 8; ++i) EXPECT_EQ(sweep::seam_partners(profile, i), std::vector<int>{i});
  EXPECT_EQ(edit_error(doc, [&] { sweep::seam_partners(profile, 11); }),
            "point 11 is out of range: the curve has 11 points");
  const Document before = doc;
  sweep::move_point(doc, 0, 10, {0.5, 0.125, 0.0});
  for (std::size_t i = 0; i < 11; ++i) {
    if (i == 2 || i == 10) {
      EXPECT_EQ(profile.as<sweep::PointsPart>().points[i], dvec3(0.5, 0.125, 0.0));
    } else {
      EXPECT_EQ(profile.as<sweep::PointsPart>().points[i], before.objects[0].as<sweep::PointsPart>().points[i]);
    }
  }
  EXPECT_TRUE(sweep::is_closed_polygon(profile));
  // The evaluated curve is still closed.
  EXPECT_TRUE(sweep::evaluate_curve(profile).closed);
  expect_valid(doc);
}

TEST(EditMove, ClosedBezierMovesFirstAndLastButNotTheHandles) {
  Document doc = closed_bezier_document();
  const Document before = doc;
  ASSERT_TRUE(sweep::is_closed_polygon(doc.objects[0]));
  EXPECT_EQ(sweep::seam_partners(doc.objects[0], 6), (std::vector<int>{6, 0}));
  sweep::move_point(doc, 0, 0, {2, 0.5, 0});
  const auto& p = doc.objects[0].as<sweep::PointsPart>().points;
  EXPECT_EQ(p[0], dvec3(2, 0.5, 0));
  EXPECT_EQ(p[6], dvec3(2, 0.5, 0));
  for (std::size_t i = 1; i < 6; ++i) EXPECT_EQ(p[i], before.objects[0].as<sweep::PointsPart>().points[i]);
}

TEST(EditMove, ClosedWithinToleranceButNotBeyond) {
  Document doc = load_starter("weird.swp");
  sweep::Object near = doc.objects[0];
  near.as<sweep::PointsPart>().points[9].x += 1e-12;  // the curve's size is about 1.5
  EXPECT_TRUE(sweep::is_closed_polygon(near));
  sweep::Object open = doc.objects[0];
  open.as<sweep::PointsPart>().points[9].x += 1e-6;
  EXPECT_FALSE(sweep::is_closed_polygon(open));
  EXPECT_EQ(sweep::seam_partners(open, 1), std::vector<int>{1});
  // Moving a point of a nearly closed curve closes it exactly.
  doc.objects[0] = near;
  sweep::move_point(doc, 0, 1, {0.25, -0.5, 0});
  EXPECT_EQ(doc.objects[0].as<sweep::PointsPart>().points[9], doc.objects[0].as<sweep::PointsPart>().points[1]);
  // An open starter curve is not closed.
  EXPECT_FALSE(sweep::is_closed_polygon(load_starter("core.swp").objects[1]));
}

TEST(EditMove, Errors) {
  Document doc = load_starter("weird.swp");
  EXPECT_EQ(edit_error(doc,
                       [&] {
                         sweep::move_point(doc, 0, 11, {0, 0, 0});
                       }),
            "point 11 is out of range: curve 'profile' has 11 points");
  EXPECT_EQ(edit_error(doc,
                       [&] {
                         sweep::move_point(doc, 0, -1, {0, 0, 0});
                       }),
            "point -1 is out of range: curve 'profile' has 11 points");
  EXPECT_EQ(edit_error(doc,
                       [&] {
                         sweep::move_point(doc, 3, 0, {0, 0, 0});
                       }),
            "object 3 is out of range: the document has 3 objects");
  EXPECT_EQ(edit_error(doc,
                       [&] {
                         sweep::move_point(doc, 2, 0, {0, 0, 0});
                       }),
            "'weird' is a surface (gcyl): it has no control points");
  EXPECT_EQ(edit_error(doc,
                       [&] {
                         sweep::move_point(doc, 0, 1, {std::nan(""), 0, 0});
                       }),
            "coordinate x = nan is not a finite number");
  EXPECT_EQ(edit_error(doc,
                       [&] {
                         sweep::move_point(doc, 1, 1, {0, 0, -std::numeric_limits<double>::infinity()});
                       }),
            "coordinate z = -inf is not a finite number");
  EXPECT_EQ(edit_error(doc,
                       [&] {
                         sweep::move_point(doc, 0, 1, {0, 2e12, 0});
                       }),
            "coordinate y = 2e+12 is out of range: coordinates must be from -1e12 to 1e12");
  // z of a planar curve is dropped, not checked.
  EXPECT_NO_THROW(sweep::move_point(doc, 0, 4, {0, 1e12, std::nan("")}));
  EXPECT_EQ(doc.objects[0].as<sweep::PointsPart>().points[4], dvec3(0, 1e12, 0));

  Document circles = load_starter("circles.swp");
  ASSERT_EQ(circles.objects[0].kind(), ObjectKind::Circle);
  EXPECT_EQ(edit_error(circles,
                       [&] {
                         sweep::move_point(circles, 0, 0, {0, 0, 0});
                       }),
            "'" + sweep::display_name(circles, 0) + "' is a circle: it has no control points");
}

// ---- set_steps_or_levels, set_radius --------------------------------------------------------------------

TEST(EditSteps, CurvesAndRevolutions) {
  Document doc = load_starter("wineglass.swp");
  EXPECT_EQ(sweep::set_steps_or_levels(doc, 0, 3).objects, std::vector<int>{0});
  EXPECT_EQ(doc.objects[0].as<sweep::StepsPart>().steps, 3);
  sweep::set_steps_or_levels(doc, 1, 12);
  EXPECT_EQ(doc.objects[1].as<sweep::CopiesPart>().copies, 12);
  expect_valid(doc);
  EXPECT_EQ(sweep::evaluate_curve(doc.objects[0]).frames.size(), 23u * 3u + 1u);
}

TEST(EditSteps, Errors) {
  Document doc = load_starter("wineglass.swp");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_steps_or_levels(doc, 0, 0); }), "STEPS must be from 1 to 100000, not 0");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_steps_or_levels(doc, 1, 100001); }),
            "STEPS must be from 1 to 100000, not 100001");
  // 23 pieces * 100000 steps is within the curve cap, but the 90 copies of the glass are not.
  const std::int64_t vertices = sweep::revolution_vertex_count(23 * 100000 + 1, false, 90);
  ASSERT_GT(vertices, sweep::limits::kMaxMeshVertices);
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_steps_or_levels(doc, 0, 100000); }),
            "surface 'wineglass': expected a surface of at most 50000000 vertices (this one would have " +
                std::to_string(vertices) + ")");
  Document weird = load_starter("weird.swp");
  EXPECT_EQ(edit_error(weird, [&] { sweep::set_steps_or_levels(weird, 2, 4); }),
            "surface 'weird' is a generalized cylinder (gcyl): it has no STEPS; it takes its samples from its curves");
}

// Found by the session's state machine test (tests/desktop/session_state_machine_test.cpp): STEPS
// asked of a material or a rider aborted (a missing part) instead of refusing.
TEST(EditSteps, AMaterialOrARiderHasNoSteps) {
  Document doc =
      sweep::io::parse_swp("circ path 8 1\nmaterial clay color 1 0 0\nsrev ball 8 path\nrider r path ball\n");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_steps_or_levels(doc, 1, 4); }), "material 'clay' has no STEPS");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_steps_or_levels(doc, 3, 4); }), "rider 'r' has no STEPS");
}

TEST(EditSteps, CurveSampleCap) {
  // A B-spline of 201 pieces reaches 201 * 100000 + 1 > 10^7 samples.
  Document doc;
  sweep::Object curve;
  curve.set_kind(ObjectKind::BSpline3);
  curve.name = "long";
  curve.as<sweep::StepsPart>().steps = 1;
  for (int i = 0; i < 204; ++i) curve.as<sweep::PointsPart>().points.push_back({i, 0, 0});
  doc.objects.push_back(curve);
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_steps_or_levels(doc, 0, 100000); }),
            "curve 'long': expected at most 10000000 samples per curve (STEPS 100000 gives 20100001)");
  sweep::set_steps_or_levels(doc, 0, 49000);
  expect_valid(doc);
}

TEST(EditSteps, DocumentSampleCap) {
  // Three B-splines of 91 pieces: two at STEPS 100000 fit the document's 2 * 10^7 samples, the
  // third does not.
  Document doc;
  for (const char* name : {"a", "b", "c"}) {
    sweep::Object curve;
    curve.set_kind(ObjectKind::BSpline2);
    curve.name = name;
    curve.as<sweep::StepsPart>().steps = 1;
    for (int i = 0; i < 94; ++i) curve.as<sweep::PointsPart>().points.push_back({i, i % 2, 0});
    doc.objects.push_back(curve);
  }
  sweep::set_steps_or_levels(doc, 0, 100000);
  sweep::set_steps_or_levels(doc, 1, 100000);
  EXPECT_EQ(
      edit_error(doc, [&] { sweep::set_steps_or_levels(doc, 2, 100000); }),
      "curve 'c': expected at most 20000000 curve samples in the whole document (this curve brings the total to " +
          std::to_string(3 * (91 * 100000 + 1)) + ")");
  expect_valid(doc);
}

TEST(EditRadius, SetAndErrors) {
  Document doc = load_starter("circles.swp");
  const int circle = 0;
  EXPECT_EQ(sweep::set_radius(doc, circle, 2.5).objects, std::vector<int>{circle});
  EXPECT_EQ(doc.objects[0].as<sweep::RadiusPart>().radius, 2.5);
  expect_valid(doc);
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_radius(doc, circle, 0.0); }),
            "the radius must be from 1e-12 to 1e12, not 0");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_radius(doc, circle, 1e-13); }),
            "the radius must be from 1e-12 to 1e12, not 1e-13");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_radius(doc, circle, std::nan("")); }),
            "the radius must be from 1e-12 to 1e12, not nan");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_radius(doc, circle, 1.5e12); }),
            "the radius must be from 1e-12 to 1e12, not 1.5e+12");
  Document core = load_starter("core.swp");
  EXPECT_EQ(edit_error(core, [&] { sweep::set_radius(core, 1, 1.0); }),
            "'bsp2#1' is not a circle (it is a bsp2): it has no radius");
}

// ---- split and join Bezier pieces -------------------------------------------------------------

/// Bounding-box diagonal of a control polygon: the scale for relative tolerances.
double polygon_size(const std::vector<dvec3>& points) {
  dvec3 lo = points[0], hi = points[0];
  for (const dvec3& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return glm::length(hi - lo);
}

/// Piece k of a Bezier polygon evaluated at u by the library.
dvec3 bezier_at(const std::vector<dvec3>& points, std::size_t piece, double u) {
  return sweep::evaluate_bezier_piece(
             {points[3 * piece], points[3 * piece + 1], points[3 * piece + 2], points[3 * piece + 3]}, u)
      .position;
}

struct SplitCase {
  const char* file;
  int object;
  int piece;
};

TEST(EditSplit, TheCurveKeepsItsExactShapeAndJoinUndoesIt) {
  const SplitCase cases[] = {{"core.swp", 0, 0},    {"core.swp", 2, 0},    {"corners.swp", 0, 0},
                             {"corners.swp", 0, 3}, {"corners.swp", 0, 4}, {"corners.swp", 1, 2}};
  for (const SplitCase& c : cases) {
    for (const double t : {0.1, 0.37, 0.5, 0.93}) {
      SCOPED_TRACE(std::string(c.file) + " object " + std::to_string(c.object) + " piece " + std::to_string(c.piece) +
                   " t " + std::to_string(t));
      Document doc = load_starter(c.file);
      const std::vector<dvec3> before = doc.objects[static_cast<std::size_t>(c.object)].as<sweep::PointsPart>().points;
      const Change change = sweep::split_bezier_piece(doc, c.object, c.piece, t);
      EXPECT_EQ(change.objects, std::vector<int>{c.object});
      const std::vector<dvec3>& after = doc.objects[static_cast<std::size_t>(c.object)].as<sweep::PointsPart>().points;
      ASSERT_EQ(after.size(), before.size() + 3);
      expect_valid(doc);
      const double tolerance = 1e-12 * polygon_size(before);
      const auto k = static_cast<std::size_t>(c.piece);
      // Other pieces are untouched, point for point.
      for (std::size_t i = 0; i <= 3 * k; ++i) EXPECT_EQ(after[i], before[i]);
      for (std::size_t i = 3 * k + 3; i < before.size(); ++i) EXPECT_EQ(after[i + 3], before[i]);
      // The split piece: the original at u equals the left half at u/t or the right at (u-t)/(1-t).
      for (int j = 0; j <= 200; ++j) {
        const double u = j / 200.0;
        const dvec3 expected = bezier_at(before, k, u);
        const dvec3 got = u <= t ? bezier_at(after, k, u / t) : bezier_at(after, k + 1, (u - t) / (1.0 - t));
        EXPECT_LE(sweep::test::distance(expected, got), tolerance) << "u = " << u;
        EXPECT_LE(sweep::test::distance(expected, sweep::test::direct_bezier(before, k, u)), tolerance);
      }
      // Joining at the new joint gives the original points back.
      sweep::join_bezier_pieces(doc, c.object, 3 * c.piece + 3);
      const std::vector<dvec3>& joined = doc.objects[static_cast<std::size_t>(c.object)].as<sweep::PointsPart>().points;
      ASSERT_EQ(joined.size(), before.size());
      for (std::size_t i = 0; i < before.size(); ++i)
        EXPECT_LE(sweep::test::distance(joined[i], before[i]), tolerance) << i;
    }
  }
}

TEST(EditSplit, EvaluatedSamplesAreUnchangedAtHalf) {
  // A one-piece curve at STEPS 20 split in half and evaluated at STEPS 10 samples the same
  // parameters, so evaluate_bezier must give the same points and tangents.
  Document doc = load_starter("core.swp");
  const sweep::CurveSamples before = sweep::evaluate_curve(doc.objects[2]);
  sweep::split_bezier_piece(doc, 2, 0, 0.5);
  sweep::set_steps_or_levels(doc, 2, 10);
  const sweep::CurveSamples after = sweep::evaluate_curve(doc.objects[2]);
  ASSERT_EQ(after.frames.size(), before.frames.size());
  const double size = polygon_size(load_starter("core.swp").objects[2].as<sweep::PointsPart>().points);
  for (std::size_t i = 0; i < before.frames.size(); ++i) {
    EXPECT_LE(sweep::test::distance(after.frames[i].V, before.frames[i].V), 1e-12 * size) << i;
    EXPECT_GE(glm::dot(after.frames[i].T, before.frames[i].T), 1.0 - 1e-12) << i;
  }
}

TEST(EditJoin, CornerJointKeepsTheOuterHandlesDirections) {
  Document doc = load_starter("corners.swp");
  const std::vector<dvec3> before =
      doc.objects[0].as<sweep::PointsPart>().points;  // square: corner at point 3, handles at right angles
  sweep::join_bezier_pieces(doc, 0, 3);
  const std::vector<dvec3>& after = doc.objects[0].as<sweep::PointsPart>().points;
  ASSERT_EQ(after.size(), before.size() - 3);
  EXPECT_EQ(after[0], before[0]);
  EXPECT_EQ(after[3], before[6]);
  for (std::size_t i = 4; i < after.size(); ++i) EXPECT_EQ(after[i], before[i + 3]);
  // t from the handle lengths at the joint; the outer handles are scaled by 1/t and 1/(1-t).
  const double left = glm::length(before[3] - before[2]);
  const double right = glm::length(before[4] - before[3]);
  const double t = left / (left + right);
  const double tolerance = 1e-12 * polygon_size(before);
  EXPECT_LE(sweep::test::distance(after[1], before[0] + (before[1] - before[0]) / t), tolerance);
  EXPECT_LE(sweep::test::distance(after[2], before[6] + (before[5] - before[6]) / (1.0 - t)), tolerance);
  EXPECT_TRUE(sweep::is_closed_polygon(doc.objects[0]));
  expect_valid(doc);
  // delete_point at a joint is the same join.
  Document by_delete = load_starter("corners.swp");
  sweep::delete_point(by_delete, 0, 3);
  EXPECT_EQ(by_delete, doc);
}

/// A bez2 of two pieces from 7 points.
Document two_piece_bezier(const std::vector<dvec3>& points) {
  Document doc;
  sweep::Object curve;
  curve.set_kind(ObjectKind::Bezier2);
  curve.name = "s";
  curve.as<sweep::StepsPart>().steps = 4;
  curve.as<sweep::PointsPart>().points = points;
  doc.objects.push_back(curve);
  return doc;
}

TEST(EditJoin, AJointWithoutAHandleUsesTheChordRatio) {
  // The left handle sits on the joint, so the handle lengths say nothing about t.
  Document doc = two_piece_bezier({{0, 0, 0}, {0, 1, 0}, {1, 1, 0}, {1, 1, 0}, {2, 1, 0}, {3, 2, 0}, {3, 0, 0}});
  const std::vector<dvec3> p = doc.objects[0].as<sweep::PointsPart>().points;
  sweep::join_bezier_pieces(doc, 0, 3);
  const double left = glm::length(p[3] - p[0]);
  const double right = glm::length(p[6] - p[3]);
  const double t = left / (left + right);
  const std::vector<dvec3>& q = doc.objects[0].as<sweep::PointsPart>().points;
  ASSERT_EQ(q.size(), 4u);
  EXPECT_EQ(q[0], p[0]);
  EXPECT_EQ(q[3], p[6]);
  EXPECT_LE(sweep::test::distance(q[1], p[0] + (p[1] - p[0]) / t), 1e-12);
  EXPECT_LE(sweep::test::distance(q[2], p[6] + (p[5] - p[6]) / (1.0 - t)), 1e-12);
  expect_valid(doc);
}

TEST(EditJoin, RefusesHandlesOutOfRange) {
  // t = 1e-9 from the joint's handles would put the joined left handle at 1e13.
  Document doc =
      two_piece_bezier({{0, 0, 0}, {1e4, 0, 0}, {1, 0, 0}, {1 + 1e-9, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}});
  EXPECT_EQ(
      edit_error(doc, [&] { sweep::join_bezier_pieces(doc, 0, 3); }),
      "cannot join the pieces at point 3: the joined handles would be out of range (coordinates from -1e12 to 1e12)");
}

TEST(EditSplitJoin, Errors) {
  Document doc = load_starter("corners.swp");  // square: 16 points, 5 pieces
  EXPECT_EQ(edit_error(doc, [&] { sweep::split_bezier_piece(doc, 0, 5, 0.5); }),
            "piece 5 is out of range: curve 'square' has 5 pieces");
  EXPECT_EQ(edit_error(doc, [&] { sweep::split_bezier_piece(doc, 0, -1, 0.5); }),
            "piece -1 is out of range: curve 'square' has 5 pieces");
  EXPECT_EQ(edit_error(doc, [&] { sweep::split_bezier_piece(doc, 0, 0, 0.0); }),
            "the split parameter must be strictly between 0 and 1, not 0");
  EXPECT_EQ(edit_error(doc, [&] { sweep::split_bezier_piece(doc, 0, 0, 1.0); }),
            "the split parameter must be strictly between 0 and 1, not 1");
  EXPECT_EQ(edit_error(doc, [&] { sweep::split_bezier_piece(doc, 0, 0, std::nan("")); }),
            "the split parameter must be strictly between 0 and 1, not nan");
  EXPECT_EQ(edit_error(doc, [&] { sweep::join_bezier_pieces(doc, 0, 4); }),
            "point 4 of 'square' is a handle: only joints between pieces (every third point) can be removed");
  EXPECT_EQ(edit_error(doc, [&] { sweep::join_bezier_pieces(doc, 0, 15); }),
            "point 15 of 'square' is an end point: a Bezier curve keeps its end points");
  EXPECT_EQ(edit_error(doc, [&] { sweep::delete_point(doc, 0, 0); }),
            "point 0 of 'square' is an end point: a Bezier curve keeps its end points");
  EXPECT_EQ(edit_error(doc, [&] { sweep::delete_point(doc, 0, 1); }),
            "point 1 of 'square' is a handle: only joints between pieces (every third point) can be removed");
  EXPECT_EQ(edit_error(doc, [&] { sweep::join_bezier_pieces(doc, 0, 16); }),
            "point 16 is out of range: curve 'square' has 16 points");
  Document core = load_starter("core.swp");
  EXPECT_EQ(edit_error(core, [&] { sweep::join_bezier_pieces(core, 0, 3); }),
            "curve 'bez2#0' has a single piece: there is no joint to remove");
  EXPECT_EQ(edit_error(core, [&] { sweep::split_bezier_piece(core, 1, 0, 0.5); }),
            "curve 'bsp2#1' is a B-spline (bsp2): only Bezier curves are split into pieces");
  EXPECT_EQ(edit_error(core, [&] { sweep::join_bezier_pieces(core, 3, 3); }),
            "curve 'bsp3#3' is a B-spline (bsp3): only Bezier curves have pieces to join");
}

// ---- insert and delete B-spline points ----------------------------------------------------------

TEST(EditInsert, OpenBSpline) {
  for (const int before : {0, 2, 4}) {
    Document doc = load_starter("core.swp");
    const std::vector<dvec3> old = doc.objects[1].as<sweep::PointsPart>().points;
    const Change change = sweep::insert_bspline_point(doc, 1, before, {0.5, 0.25, 3.0});
    EXPECT_EQ(change.objects, std::vector<int>{1});
    const std::vector<dvec3>& p = doc.objects[1].as<sweep::PointsPart>().points;
    ASSERT_EQ(p.size(), 5u);
    const auto at = static_cast<std::size_t>(before);
    EXPECT_EQ(p[at], dvec3(0.5, 0.25, 0.0));  // planar: z dropped
    for (std::size_t i = 0; i < old.size(); ++i) EXPECT_EQ(p[i < at ? i : i + 1], old[i]);
    expect_valid(doc);
  }
}

/// The distinct points of a closed B-spline polygon (all but the last three).
std::vector<dvec3> distinct(const std::vector<dvec3>& points) {
  return {points.begin(), points.end() - 3};
}

TEST(EditInsert, ClosedBSplineStaysClosedAtAndAwayFromTheSeam) {
  const Document original = load_starter("weird.swp");
  const std::vector<dvec3> old =
      distinct(original.objects[0].as<sweep::PointsPart>().points);  // 8 distinct + 3 repeats
  ASSERT_EQ(old.size(), 8u);
  const dvec3 q(0.1, 0.9, 0.0);
  // before -> where the new point lands among the distinct points
  const std::pair<int, std::size_t> cases[] = {{0, 0}, {1, 1}, {5, 5}, {8, 8}, {9, 1}, {10, 2}, {11, 3}};
  for (const auto& [before, at] : cases) {
    SCOPED_TRACE("before " + std::to_string(before));
    Document doc = original;
    sweep::insert_bspline_point(doc, 0, before, q);
    const std::vector<dvec3>& p = doc.objects[0].as<sweep::PointsPart>().points;
    ASSERT_EQ(p.size(), 12u);
    EXPECT_TRUE(sweep::is_closed_polygon(doc.objects[0]));
    std::vector<dvec3> expected = old;
    expected.insert(expected.begin() + static_cast<std::ptrdiff_t>(at), q);
    EXPECT_EQ(distinct(p), expected);
    EXPECT_EQ(p[9], p[0]);
    EXPECT_EQ(p[10], p[1]);
    EXPECT_EQ(p[11], p[2]);
    EXPECT_TRUE(sweep::evaluate_curve(doc.objects[0]).closed);
    expect_valid(doc);
  }
}

TEST(EditInsert, Errors) {
  Document doc = load_starter("weird.swp");
  EXPECT_EQ(edit_error(doc,
                       [&] {
                         sweep::insert_bspline_point(doc, 0, 12, {0, 0, 0});
                       }),
            "cannot insert before point 12: curve 'profile' has 11 points (insert before 0 to 11)");
  EXPECT_EQ(edit_error(doc,
                       [&] {
                         sweep::insert_bspline_point(doc, 1, -1, {0, 0, 0});
                       }),
            "cannot insert before point -1: curve 'sweep' has 11 points (insert before 0 to 11)");
  EXPECT_EQ(edit_error(doc,
                       [&] {
                         sweep::insert_bspline_point(doc, 1, 0, {0, 0, 1e13});
                       }),
            "coordinate z = 1e+13 is out of range: coordinates must be from -1e12 to 1e12");
  Document corners = load_starter("corners.swp");
  EXPECT_EQ(edit_error(corners,
                       [&] {
                         sweep::insert_bspline_point(corners, 0, 1, {0, 0, 0});
                       }),
            "curve 'square' is a Bezier curve (bez2): split a piece to add points");
}

TEST(EditDelete, OpenBSpline) {
  Document doc = load_starter("wineglass.swp");
  const std::vector<dvec3> old = doc.objects[0].as<sweep::PointsPart>().points;
  EXPECT_EQ(sweep::delete_point(doc, 0, 5).objects, std::vector<int>{0});
  std::vector<dvec3> expected = old;
  expected.erase(expected.begin() + 5);
  EXPECT_EQ(doc.objects[0].as<sweep::PointsPart>().points, expected);
  expect_valid(doc);

  Document core = load_starter("core.swp");  // the bsp2 has 4 points
  EXPECT_EQ(edit_error(core, [&] { sweep::delete_point(core, 1, 0); }), "a B-spline needs at least 4 control points");
  EXPECT_EQ(edit_error(core, [&] { sweep::delete_point(core, 1, 4); }),
            "point 4 is out of range: curve 'bsp2#1' has 4 points");
}

TEST(EditDelete, ClosedBSplineStaysClosedDownToFourDistinctPoints) {
  Document doc = load_starter("weird.swp");
  std::vector<dvec3> expected = distinct(doc.objects[0].as<sweep::PointsPart>().points);
  // Point 9 repeats point 1: deleting it deletes point 1.
  sweep::delete_point(doc, 0, 9);
  expected.erase(expected.begin() + 1);
  EXPECT_EQ(distinct(doc.objects[0].as<sweep::PointsPart>().points), expected);
  EXPECT_TRUE(sweep::is_closed_polygon(doc.objects[0]));
  expect_valid(doc);
  // Point 0 (and with it its repeat).
  sweep::delete_point(doc, 0, 0);
  expected.erase(expected.begin());
  EXPECT_EQ(distinct(doc.objects[0].as<sweep::PointsPart>().points), expected);
  EXPECT_TRUE(sweep::is_closed_polygon(doc.objects[0]));
  sweep::delete_point(doc, 0, 3);
  sweep::delete_point(doc, 0, 3);
  ASSERT_EQ(doc.objects[0].as<sweep::PointsPart>().points.size(), 7u);
  EXPECT_TRUE(sweep::is_closed_polygon(doc.objects[0]));
  EXPECT_TRUE(sweep::evaluate_curve(doc.objects[0]).closed);
  EXPECT_EQ(edit_error(doc, [&] { sweep::delete_point(doc, 0, 2); }),
            "a closed B-spline needs at least 4 distinct control points (besides the 3 it repeats)");
}

TEST(EditDelete, ObjectsWithoutPoints) {
  Document doc = load_starter("tor.swp");  // profile (circ), sweep (circ), fbf (gcyl)
  EXPECT_EQ(edit_error(doc, [&] { sweep::delete_point(doc, 0, 0); }),
            "'profile' is a circle: it has no control points");
  EXPECT_EQ(edit_error(doc, [&] { sweep::delete_point(doc, 2, 0); }),
            "'fbf' is a surface (gcyl): it has no control points");
}

// ---- templates, names, surfaces, deletion ---------------------------------------------------------

TEST(EditTemplates, EveryTemplateIsAValidShapeOfSizeAboutOne) {
  struct Expected {
    std::string_view shape;
    ObjectKind kind;
    int steps;
    bool closed;
  };
  const Expected all[] = {
      {"open B-spline (2D)", ObjectKind::BSpline2, 16, false}, {"closed B-spline (2D)", ObjectKind::BSpline2, 16, true},
      {"open B-spline (3D)", ObjectKind::BSpline3, 16, false}, {"Bezier (2D)", ObjectKind::Bezier2, 16, false},
      {"Bezier (3D)", ObjectKind::Bezier3, 16, false},         {"circle", ObjectKind::Circle, 32, true}};
  Document doc = load_starter("weird.swp");
  for (const Expected& e : all) {
    const std::size_t count = doc.objects.size();
    const std::string name = sweep::unique_name(doc, "shape");
    const int index = sweep::add_curve(doc, e.shape, name);
    ASSERT_EQ(index, static_cast<int>(count));
    ASSERT_EQ(doc.objects.size(), count + 1);
    const sweep::Object& curve = doc.objects.back();
    SCOPED_TRACE(std::string(sweep::keyword(curve.kind())) + " " + name);
    EXPECT_EQ(curve.name, name);
    EXPECT_EQ(curve.kind(), e.kind);
    EXPECT_EQ(curve.as<sweep::StepsPart>().steps, e.steps);
    expect_valid(doc);
    const sweep::CurveSamples samples = sweep::evaluate_curve(curve);
    EXPECT_EQ(samples.closed, e.closed);
    if (sweep::has_control_points(curve.kind())) {
      EXPECT_EQ(sweep::is_closed_polygon(curve), e.closed);
    }
    dvec3 lo = samples.frames[0].V, hi = lo;
    for (const auto& f : samples.frames) {
      lo = glm::min(lo, f.V);
      hi = glm::max(hi, f.V);
      if (sweep::is_planar_curve(curve.kind())) {
        EXPECT_EQ(f.V.z, 0.0);
      }
    }
    EXPECT_GE(glm::length(hi - lo), 0.5);
    EXPECT_LE(glm::length(hi - lo), 3.0);
    if (sweep::is_planar_curve(curve.kind()) && !e.closed) {
      // A profile (issue 25): left of the y axis, top to bottom, so a srev of it is a solid's side.
      EXPECT_LT(hi.x, 0.0);
      EXPECT_GT(samples.frames.front().V.y, samples.frames.back().V.y);
      EXPECT_LE(std::abs(0.5 * (lo.y + hi.y)), 0.25);
    } else {
      EXPECT_LE(glm::length(0.5 * (lo + hi)), 0.25);  // centred near the origin
    }
  }
  EXPECT_EQ(doc.objects[3].name, "shape");
  EXPECT_EQ(doc.objects[4].name, "shape2");
  EXPECT_EQ(doc.objects[8].name, "shape6");
  // Anonymous curves are allowed.
  EXPECT_EQ(doc.objects[static_cast<std::size_t>(sweep::add_curve(doc, "circle", ""))].name, "");
}

TEST(EditNames, UniqueNames) {
  Document doc = load_starter("weird.swp");
  EXPECT_EQ(sweep::unique_name(doc, "curve"), "curve");
  EXPECT_EQ(sweep::unique_name(doc, "profile"), "profile2");
  sweep::add_curve(doc, "circle", "profile2");
  EXPECT_EQ(sweep::unique_name(doc, "profile"), "profile3");
  EXPECT_EQ(sweep::unique_name(doc, "my curve"), "my_curve");
  EXPECT_EQ(sweep::unique_name(doc, "2d"), "_2d");
  EXPECT_EQ(sweep::unique_name(doc, ""), "object");
  EXPECT_EQ(sweep::unique_name(doc, std::string(300, 'a')).size(), sweep::limits::kMaxNameLength - 20);
}

TEST(EditNames, AddAndRenameErrors) {
  Document doc = load_starter("weird.swp");
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_curve(doc, "circle", "profile"); }),
            "name 'profile' is already used by another object");
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_curve(doc, "circle", "x y"); }),
            "name 'x y' is not a valid SWP name: use letters, digits, '_', '-' or '.'");
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_curve(doc, "circle", "2d"); }),
            "name '2d' is not a valid SWP name: start with a letter or '_'");
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_curve(doc, "circle", "."); }),
            "name '.' is not a valid SWP name: start with a letter or '_'");
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_curve(doc, "circle", "tab\there"); }),
            "name 'tab\\x09here' is not a valid SWP name: use letters, digits, '_', '-' or '.'");
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_curve(doc, "circle", std::string(201, 'n')); }),
            "name '" + std::string(40, 'n') + "...' is too long: at most 200 characters");
  EXPECT_EQ(edit_error(doc, [&] { sweep::rename_object(doc, 0, "sweep"); }),
            "name 'sweep' is already used by another object");
  EXPECT_EQ(edit_error(doc, [&] { sweep::rename_object(doc, 0, "a/b"); }),
            "name 'a/b' is not a valid SWP name: use letters, digits, '_', '-' or '.'");
  EXPECT_EQ(edit_error(doc, [&] { sweep::rename_object(doc, 1, ""); }),
            "cannot remove the name of 'sweep': surface 'weird' uses it");
  EXPECT_EQ(edit_error(doc, [&] { sweep::rename_object(doc, 7, "x"); }),
            "object 7 is out of range: the document has 3 objects");
}

TEST(EditNames, RenameKeepsReferences) {
  Document doc = load_starter("weird.swp");
  EXPECT_EQ(sweep::rename_object(doc, 0, "outline").objects, std::vector<int>{0});
  EXPECT_EQ(doc.objects[0].name, "outline");
  EXPECT_NE(sweep::io::write_swp(doc).find("gcyl weird outline sweep"), std::string::npos);
  expect_valid(doc);
  sweep::rename_object(doc, 0, "outline");  // its own name is not taken
  sweep::rename_object(doc, 2, "");         // nothing uses the surface
  EXPECT_EQ(doc.objects[2].name, "");
  expect_valid(doc);
}

TEST(EditSurfaces, AddRevolutionAndCylinder) {
  Document doc = load_starter("weird.swp");
  const int circle = sweep::add_curve(doc, "circle", "ring");
  const int srev = sweep::add_surface(doc, ObjectKind::SurfaceOfRevolution, "turned", 0, -1, 24);
  EXPECT_EQ(srev, 4);
  EXPECT_EQ(doc.objects[4].as<sweep::ProfilePart>().profile, 0);
  EXPECT_EQ(doc.objects[4].kind(), ObjectKind::SurfaceOfRevolution);
  EXPECT_EQ(doc.objects[4].as<sweep::CopiesPart>().copies, 24);
  const int gcyl = sweep::add_surface(doc, ObjectKind::GeneralizedCylinder, "", circle, 1, 99);
  EXPECT_EQ(gcyl, 5);
  EXPECT_EQ(doc.objects[5].as<sweep::ProfilePart>().profile, circle);
  EXPECT_EQ(doc.objects[5].as<sweep::CylinderSurface>().sweep, 1);
  EXPECT_EQ(doc.objects[5].find<sweep::StepsPart>(), nullptr);  // gcyl has no STEPS
  expect_valid(doc);
  EXPECT_EQ(sweep::io::parse_swp(sweep::io::write_swp(doc)), doc);
}

TEST(EditSurfaces, Errors) {
  Document doc = load_starter("weird.swp");
  const ObjectKind srev = ObjectKind::SurfaceOfRevolution;
  const ObjectKind gcyl = ObjectKind::GeneralizedCylinder;
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_surface(doc, srev, "s", 1, -1, 8); }),
            "'sweep': expected the name of a 2D curve (bez2, bsp2, circ, cr2, kb2, poly2, herm2) defined above as "
            "profile (it "
            "is a 3D curve (bsp3))");
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_surface(doc, gcyl, "s", 2, 1, 8); }),
            "'weird': expected the name of a 2D curve (bez2, bsp2, circ, cr2, kb2, poly2, herm2) defined above as "
            "profile (it "
            "is a surface (gcyl))");
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_surface(doc, gcyl, "s", 0, 2, 8); }),
            "'weird': expected the name of a curve defined above as sweep (it is a surface (gcyl))");
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_surface(doc, gcyl, "s", 0, 3, 8); }),
            "the sweep 3 is out of range: the document has 3 objects");
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_surface(doc, srev, "s", -1, -1, 8); }),
            "the profile -1 is out of range: the document has 3 objects");
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_surface(doc, srev, "weird", 0, -1, 8); }),
            "name 'weird' is already used by another object");
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_surface(doc, srev, "s", 0, -1, 0); }),
            "STEPS must be from 1 to 100000, not 0");
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_surface(doc, ObjectKind::Circle, "s", 0, -1, 8); }),
            "a surface must be a surface of revolution (srev), a generalized cylinder (gcyl) or a birail surface "
            "(birail), not circ");
  Document core = load_starter("core.swp");
  EXPECT_EQ(edit_error(core, [&] { sweep::add_surface(core, srev, "s", 1, -1, 8); }),
            "curve 'bsp2#1' has no name: a surface can only use a named curve (name it first)");
}

TEST(EditSurfaces, MeshCaps) {
  Document doc = load_starter("wineglass.swp");  // profile: 23 pieces at STEPS 8, 185 samples
  const std::int64_t glass = sweep::revolution_vertex_count(185, false, 90);
  const std::int64_t big = sweep::revolution_vertex_count(185, false, 100000);
  ASSERT_LT(glass + 2 * big, sweep::limits::kMaxMeshVertices);
  ASSERT_GT(glass + 3 * big, sweep::limits::kMaxMeshVertices);
  sweep::add_surface(doc, ObjectKind::SurfaceOfRevolution, "big1", 0, -1, 100000);
  sweep::add_surface(doc, ObjectKind::SurfaceOfRevolution, "big2", 0, -1, 100000);
  EXPECT_EQ(edit_error(doc, [&] { sweep::add_surface(doc, ObjectKind::SurfaceOfRevolution, "big3", 0, -1, 100000); }),
            "surface 'big3': expected at most 50000000 surface vertices in the whole document (this surface brings the "
            "total to " +
                std::to_string(glass + 3 * big) + ")");
  // Growing the shared profile would grow all three surfaces over the cap.
  EXPECT_THROW(sweep::set_steps_or_levels(doc, 0, 16), EditError);
  EXPECT_EQ(doc.objects[0].as<sweep::StepsPart>().steps, 8);
  expect_valid(doc);
}

TEST(EditDeleteObject, RefusesAUsedCurveAndShiftsReferences) {
  Document doc = load_starter("wineglass.swp");
  EXPECT_EQ(edit_error(doc, [&] { sweep::delete_object(doc, 0); }),
            "cannot delete 'profile': surface 'wineglass' uses it");
  sweep::add_surface(doc, ObjectKind::SurfaceOfRevolution, "", 0, -1, 8);
  sweep::add_surface(doc, ObjectKind::SurfaceOfRevolution, "third", 0, -1, 8);
  EXPECT_EQ(edit_error(doc, [&] { sweep::delete_object(doc, 0); }),
            "cannot delete 'profile': surfaces 'wineglass', 'srev#2' and 'third' use it");

  // core.swp has four anonymous curves; add a named circle and a surface of it after them.
  Document core = load_starter("core.swp");
  const int ring = sweep::add_curve(core, "circle", "ring");
  sweep::add_surface(core, ObjectKind::SurfaceOfRevolution, "turned", ring, -1, 8);
  const Document before = core;
  const Change change = sweep::delete_object(core, 1);
  EXPECT_TRUE(change.structure);
  ASSERT_EQ(core.objects.size(), 5u);
  EXPECT_EQ(core.objects[0], before.objects[0]);
  for (std::size_t i = 1; i < 4; ++i) EXPECT_EQ(core.objects[i], before.objects[i + 1]);
  EXPECT_EQ(core.objects[3].name, "ring");
  EXPECT_EQ(core.objects[4].as<sweep::ProfilePart>().profile, 3);  // shifted with the circle
  expect_valid(core);
  EXPECT_NE(sweep::io::write_swp(core).find("srev turned 8 ring"), std::string::npos);
  sweep::delete_object(core, 4);  // a surface
  sweep::delete_object(core, 3);  // the circle, now unused
  expect_valid(core);
  EXPECT_EQ(edit_error(core, [&] { sweep::delete_object(core, 3); }),
            "object 3 is out of range: the document has 3 objects");
}

// ---- saving ------------------------------------------------------------------------------------

using sweep::test::read_file;
using sweep::test::ScratchFolder;
using sweep::test::write_text;

/// Scratch folders are named after this test file, so a leftover says where it came from.
const char* const kScratchPrefix = "sweep-edit";

TEST(EditSave, RoundTripKeepsEditsAndUntouchedNumbers) {
  ScratchFolder folder(kScratchPrefix);
  const fs::path original_path = fs::path(SWEEP_SWP_DIR) / "weird.swp";
  const Document original = sweep::io::load_swp_file(original_path);
  Document doc = original;
  sweep::move_point(doc, 0, 4, {0.0625, 0.3, 0});
  sweep::insert_bspline_point(doc, 0, 10, {0.5, -0.5, 0});
  const fs::path saved = folder.path() / "weird.swp";
  sweep::io::save_swp_file(saved, doc);
  const Document reloaded = sweep::io::load_swp_file(saved);
  EXPECT_EQ(reloaded, doc);
  EXPECT_EQ(reloaded.objects[1], original.objects[1]);
  EXPECT_EQ(reloaded.objects[2], original.objects[2]);
  // The untouched sweep's points are written with the file's own digits.
  const std::string text = read_file(saved);
  std::istringstream lines(read_file(original_path));
  std::string line;
  int sweep_lines = 0;
  for (int number = 1; std::getline(lines, line); ++number) {
    if (number >= 15 && number <= 25) {
      EXPECT_NE(text.find(line + "\n"), std::string::npos) << line;
      ++sweep_lines;
    }
  }
  EXPECT_EQ(sweep_lines, 11);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"weird.swp"});
}

TEST(EditSave, AFailureMidSaveLeavesTheOldFileIntact) {
  ScratchFolder folder(kScratchPrefix);
  const fs::path target = folder.path() / "doc.swp";
  Document doc = load_starter("weird.swp");
  sweep::io::save_swp_file(target, doc);
  const std::string old_text = read_file(target);
  // A big edit: the new text is far larger than the limit the child writes under.
  for (int i = 0; i < 20000; ++i)
    doc.objects[1].as<sweep::PointsPart>().points.push_back({i * 1e-4, 1.0 / (i + 1), 0.25});
  expect_valid(doc);
  ASSERT_GT(sweep::io::write_swp(doc).size(), 100000u);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    // RLIMIT_FSIZE binds root too: the write fails part way as on a full disk. Ignoring SIGXFSZ
    // turns the kill into an EFBIG error.
    std::signal(SIGXFSZ, SIG_IGN);
    rlimit limit{};
    ::getrlimit(RLIMIT_FSIZE, &limit);
    limit.rlim_cur = 16384;
    ::setrlimit(RLIMIT_FSIZE, &limit);
    int code = 2;  // saved without error: the test fails
    try {
      sweep::io::save_swp_file(target, doc);
    } catch (const std::runtime_error& e) {
      code = std::string(e.what()) == "cannot write " + target.string() + ": writing failed: File too large" ? 0 : 1;
    }
    ::_exit(code);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: wrong message, 2: no error";
  EXPECT_EQ(read_file(target), old_text);
  EXPECT_EQ(sweep::io::load_swp_file(target), load_starter("weird.swp"));
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"doc.swp"});  // no temporary left behind
  // Saved without the limit, the edit goes through (the new points at the file's six decimals,
  // within a millionth of the scene's size: write_swp_preserving).
  sweep::io::save_swp_file(target, doc);
  const Document back = sweep::io::load_swp_file(target);
  const auto saved = back.objects[1].as<sweep::PointsPart>().points;
  const auto edited = doc.objects[1].as<sweep::PointsPart>().points;
  ASSERT_EQ(saved.size(), edited.size());
  for (std::size_t k = 0; k < saved.size(); ++k) EXPECT_LE(glm::length(saved[k] - edited[k]), 1e-6 * 3.0) << k;
}

TEST(EditSave, ARenameFailureLeavesTheTargetAndReportsIt) {
  ScratchFolder folder(kScratchPrefix);
  const fs::path target = folder.path() / "taken.swp";
  fs::create_directory(target);  // a folder where the file should go: rename(2) fails, even for root
  fs::path inside = target / "keep.txt";
  write_text(inside, "kept");
  const Document doc = load_starter("core.swp");
  try {
    sweep::io::save_swp_file(target, doc);
    ADD_FAILURE() << "saved over a folder";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()),
              "cannot write " + target.string() + ": cannot rename the temporary file over it: Is a directory");
  }
  EXPECT_EQ(read_file(inside), "kept");
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"taken.swp"});
}

}  // namespace
