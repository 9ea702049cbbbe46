// Editing operations: each edit does what it says on real starter files, keeps closed polygons
// closed, keeps the document valid, and on error throws EditError with the exact message and
// leaves the document as it was.
#include "core/edit.hpp"

#include "core/bezier.hpp"
#include "core/curve.hpp"
#include "core/limits.hpp"
#include "core/surface.hpp"
#include "core/swp_parser.hpp"
#include "core/swp_writer.hpp"
#include "core_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
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
using sweep::Change;
using sweep::Document;
using sweep::EditError;
using sweep::ObjectKind;
using glm::dvec3;

Document starter(const char* name) { return sweep::load_swp_file(fs::path(SWEEP_SWP_DIR) / name); }

/// Runs an edit that must fail; checks that the document did not change and returns the message.
std::string edit_error(Document& doc, const std::function<void()>& edit) {
  const Document before = doc;
  try {
    edit();
  } catch (const EditError& e) {
    EXPECT_EQ(doc, before) << "the failed edit changed the document";
    return e.what();
  }
  ADD_FAILURE() << "no EditError";
  return {};
}

void expect_valid(const Document& doc) { EXPECT_NO_THROW(sweep::validate_document(doc)); }

/// A closed bez2 of two pieces (last point == first).
Document closed_bezier_document() {
  Document doc;
  sweep::Object curve;
  curve.kind = ObjectKind::Bezier2;
  curve.name = "loop";
  curve.steps = 8;
  curve.points = {{1, 0, 0}, {1, 1, 0}, {-1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}, {1, -1, 0}, {1, 0, 0}};
  doc.objects.push_back(curve);
  return doc;
}

// ---- move_point -------------------------------------------------------------------------------

TEST(EditMove, PlanarCurveDropsZAndChangesOnlyThatPoint) {
  Document doc = starter("core.swp");
  const Document before = doc;
  ASSERT_EQ(doc.objects[1].kind, ObjectKind::BSpline2);
  const Change change = sweep::move_point(doc, 1, 2, {5.5, -6.25, 7.0});
  EXPECT_EQ(change.objects, std::vector<int>{1});
  EXPECT_FALSE(change.structure);
  for (std::size_t i = 0; i < doc.objects[1].points.size(); ++i) {
    if (i == 2) {
      EXPECT_EQ(doc.objects[1].points[i], dvec3(5.5, -6.25, 0.0));
    } else {
      EXPECT_EQ(doc.objects[1].points[i], before.objects[1].points[i]);
    }
  }
  for (std::size_t k : {0u, 2u, 3u}) EXPECT_EQ(doc.objects[k], before.objects[k]);
  expect_valid(doc);
}

TEST(EditMove, SpaceCurveKeepsZ) {
  Document doc = starter("core.swp");
  ASSERT_EQ(doc.objects[3].kind, ObjectKind::BSpline3);
  sweep::move_point(doc, 3, 0, {1.5, 2.5, -3.5});
  EXPECT_EQ(doc.objects[3].points[0], dvec3(1.5, 2.5, -3.5));
  expect_valid(doc);
}

TEST(EditMove, ClosedBSplineMovesTheRepeatedPointWithIt) {
  Document doc = starter("weird.swp");
  const sweep::Object& profile = doc.objects[0];
  ASSERT_EQ(profile.points.size(), 11u);
  ASSERT_TRUE(sweep::is_closed_polygon(profile));
  EXPECT_EQ(sweep::seam_partners(profile, 1), (std::vector<int>{1, 9}));
  EXPECT_EQ(sweep::seam_partners(profile, 10), (std::vector<int>{10, 2}));
  EXPECT_EQ(sweep::seam_partners(profile, 5), (std::vector<int>{5}));
  const Document before = doc;
  sweep::move_point(doc, 0, 10, {0.5, 0.125, 0.0});
  for (std::size_t i = 0; i < 11; ++i) {
    if (i == 2 || i == 10) {
      EXPECT_EQ(profile.points[i], dvec3(0.5, 0.125, 0.0));
    } else {
      EXPECT_EQ(profile.points[i], before.objects[0].points[i]);
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
  const auto& p = doc.objects[0].points;
  EXPECT_EQ(p[0], dvec3(2, 0.5, 0));
  EXPECT_EQ(p[6], dvec3(2, 0.5, 0));
  for (std::size_t i = 1; i < 6; ++i) EXPECT_EQ(p[i], before.objects[0].points[i]);
}

TEST(EditMove, ClosedWithinToleranceButNotBeyond) {
  Document doc = starter("weird.swp");
  sweep::Object near = doc.objects[0];
  near.points[9].x += 1e-12;  // the curve's size is about 1.5
  EXPECT_TRUE(sweep::is_closed_polygon(near));
  sweep::Object open = doc.objects[0];
  open.points[9].x += 1e-6;
  EXPECT_FALSE(sweep::is_closed_polygon(open));
  EXPECT_EQ(sweep::seam_partners(open, 1), std::vector<int>{1});
  // Moving a point of a nearly closed curve closes it exactly.
  doc.objects[0] = near;
  sweep::move_point(doc, 0, 1, {0.25, -0.5, 0});
  EXPECT_EQ(doc.objects[0].points[9], doc.objects[0].points[1]);
  // An open starter curve is not closed.
  EXPECT_FALSE(sweep::is_closed_polygon(starter("core.swp").objects[1]));
}

TEST(EditMove, Errors) {
  Document doc = starter("weird.swp");
  EXPECT_EQ(edit_error(doc, [&] { sweep::move_point(doc, 0, 11, {0, 0, 0}); }),
            "point 11 is out of range: curve 'profile' has 11 points");
  EXPECT_EQ(edit_error(doc, [&] { sweep::move_point(doc, 0, -1, {0, 0, 0}); }),
            "point -1 is out of range: curve 'profile' has 11 points");
  EXPECT_EQ(edit_error(doc, [&] { sweep::move_point(doc, 3, 0, {0, 0, 0}); }),
            "object 3 is out of range: the document has 3 objects");
  EXPECT_EQ(edit_error(doc, [&] { sweep::move_point(doc, 2, 0, {0, 0, 0}); }),
            "'weird' is a surface (gcyl): it has no control points");
  EXPECT_EQ(edit_error(doc, [&] { sweep::move_point(doc, 0, 1, {std::nan(""), 0, 0}); }),
            "coordinate x = nan is not a finite number");
  EXPECT_EQ(edit_error(doc, [&] { sweep::move_point(doc, 1, 1, {0, 0, -std::numeric_limits<double>::infinity()}); }),
            "coordinate z = -inf is not a finite number");
  EXPECT_EQ(edit_error(doc, [&] { sweep::move_point(doc, 0, 1, {0, 2e12, 0}); }),
            "coordinate y = 2e+12 is out of range: coordinates must be from -1e12 to 1e12");
  // z of a planar curve is dropped, not checked.
  EXPECT_NO_THROW(sweep::move_point(doc, 0, 4, {0, 1e12, std::nan("")}));
  EXPECT_EQ(doc.objects[0].points[4], dvec3(0, 1e12, 0));

  Document circles = starter("circles.swp");
  ASSERT_EQ(circles.objects[0].kind, ObjectKind::Circle);
  EXPECT_EQ(edit_error(circles, [&] { sweep::move_point(circles, 0, 0, {0, 0, 0}); }),
            "'" + sweep::display_name(circles, 0) + "' is a circle: it has no control points");
}

// ---- set_steps, set_radius --------------------------------------------------------------------

TEST(EditSteps, CurvesAndRevolutions) {
  Document doc = starter("wineglass.swp");
  EXPECT_EQ(sweep::set_steps(doc, 0, 3).objects, std::vector<int>{0});
  EXPECT_EQ(doc.objects[0].steps, 3);
  sweep::set_steps(doc, 1, 12);
  EXPECT_EQ(doc.objects[1].steps, 12);
  expect_valid(doc);
  EXPECT_EQ(sweep::evaluate_curve(doc.objects[0]).frames.size(), 23u * 3u + 1u);
}

TEST(EditSteps, Errors) {
  Document doc = starter("wineglass.swp");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_steps(doc, 0, 0); }), "STEPS must be from 1 to 100000, not 0");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_steps(doc, 1, 100001); }), "STEPS must be from 1 to 100000, not 100001");
  // 23 pieces * 100000 steps is within the curve cap, but the 90 copies of the glass are not.
  const std::int64_t vertices = sweep::revolution_vertex_count(23 * 100000 + 1, false, 90);
  ASSERT_GT(vertices, sweep::limits::kMaxMeshVertices);
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_steps(doc, 0, 100000); }),
            "surface 'wineglass' would have " + std::to_string(vertices) + " vertices: at most 50000000 are allowed");
  Document weird = starter("weird.swp");
  EXPECT_EQ(edit_error(weird, [&] { sweep::set_steps(weird, 2, 4); }),
            "surface 'weird' is a generalized cylinder (gcyl): it has no STEPS; it takes its samples from its curves");
}

TEST(EditSteps, CurveSampleCap) {
  // A B-spline of 201 pieces reaches 201 * 100000 + 1 > 10^7 samples.
  Document doc;
  sweep::Object curve;
  curve.kind = ObjectKind::BSpline3;
  curve.name = "long";
  curve.steps = 1;
  for (int i = 0; i < 204; ++i) curve.points.push_back({i, 0, 0});
  doc.objects.push_back(curve);
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_steps(doc, 0, 100000); }),
            "curve 'long' would have 20100001 samples: at most 10000000 are allowed");
  sweep::set_steps(doc, 0, 49000);
  expect_valid(doc);
}

TEST(EditRadius, SetAndErrors) {
  Document doc = starter("circles.swp");
  const int circle = 0;
  EXPECT_EQ(sweep::set_radius(doc, circle, 2.5).objects, std::vector<int>{circle});
  EXPECT_EQ(doc.objects[0].radius, 2.5);
  expect_valid(doc);
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_radius(doc, circle, 0.0); }),
            "the radius must be from 1e-12 to 1e12, not 0");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_radius(doc, circle, 1e-13); }),
            "the radius must be from 1e-12 to 1e12, not 1e-13");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_radius(doc, circle, std::nan("")); }),
            "the radius must be from 1e-12 to 1e12, not nan");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_radius(doc, circle, 1.5e12); }),
            "the radius must be from 1e-12 to 1e12, not 1.5e+12");
  Document core = starter("core.swp");
  EXPECT_EQ(edit_error(core, [&] { sweep::set_radius(core, 1, 1.0); }),
            "'bsp2#1' is not a circle (it is a bsp2): it has no radius");
}

}  // namespace
