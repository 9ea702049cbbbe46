// The pen: what its clicks and drags become in each kind's point list (read from the kind's point
// layout, so every kind with control points is drawn without the pen naming it), the smallest
// curves it makes, closing, and the drawn curve through the document and a file and back.
#include "editor/pen.hpp"

#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/edit/edit.hpp"
#include "model/edit/shown_points.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <string>
#include <vector>

namespace sweep::editor {
namespace {

using P = glm::dvec3;

PenStroke clicked(ObjectKind kind, const std::vector<P>& at) {
  PenStroke stroke(kind);
  for (const P& p : at) stroke.press(p);
  return stroke;
}

const std::vector<P> kPentagon = {P(0, 1, 0), P(0.95, 0.31, 0), P(0.59, -0.81, 0), P(-0.59, -0.81, 0),
                                  P(-0.95, 0.31, 0)};

TEST(Pen, FiveClicksClosedMakeAClosedBSplineThroughTheLayoutsSeamRepeats) {
  const PenStroke stroke = clicked(ObjectKind::BSpline2, kPentagon);
  ASSERT_TRUE(stroke.complete(true));
  const std::vector<P> points = stroke.points(true);
  ASSERT_EQ(points.size(), 8u);  // 5 and the first three again
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(points[5 + i], kPentagon[i]);
  Document doc;
  const int index = add_drawn_curve(doc, ObjectKind::BSpline2, "ring", points);
  EXPECT_TRUE(is_closed_polygon(doc.objects[std::size_t(index)]));
}

TEST(Pen, ABezierDragGivesTheJointSymmetricHandlesAndTheCurveASmoothJoint) {
  PenStroke stroke(ObjectKind::Bezier2);
  stroke.press(P(0, 0, 0));
  stroke.press(P(2, 1, 0));
  stroke.drag_to(P(2.5, 1.5, 0));  // the middle joint dragged
  stroke.press(P(4, 0, 0));
  const std::vector<P> points = stroke.points(false);
  ASSERT_EQ(points.size(), 7u);  // J H H J H H J
  EXPECT_EQ(points[3], P(2, 1, 0));
  EXPECT_EQ(points[4], P(2.5, 1.5, 0));                 // outgoing handle under the released pointer
  EXPECT_EQ(points[2], P(1.5, 0.5, 0));                 // incoming: its mirror
  EXPECT_EQ(points[1], P(0, 0, 0) + P(2, 1, 0) / 3.0);  // a clicked end: a third of the chord
  Document doc;
  const int index = add_drawn_curve(doc, ObjectKind::Bezier2, "s", points);
  const Object& curve = doc.objects[std::size_t(index)];
  const double h = 1e-6;
  const P left = (curve_position(curve, 1.0) - curve_position(curve, 1.0 - h)) / h;
  const P right = (curve_position(curve, 1.0 + h) - curve_position(curve, 1.0)) / h;
  EXPECT_NEAR(glm::length(left - right), 0.0, 1e-4 * glm::length(left));  // C1 at the joint
}

TEST(Pen, ClickedBezierJointsMakeStraightPieces) {
  const std::vector<P> points = clicked(ObjectKind::Bezier3, {P(0, 0, 0), P(3, 0, 3)}).points(false);
  ASSERT_EQ(points.size(), 4u);
  EXPECT_EQ(points[1], P(1, 0, 1));
  EXPECT_EQ(points[2], P(2, 0, 2));
}

TEST(Pen, AClosedBezierHasAPieceBackToItsFirstJoint) {
  const std::vector<P> points = clicked(ObjectKind::Bezier2, {P(0, 0, 0), P(3, 0, 0), P(0, 3, 0)}).points(true);
  ASSERT_EQ(points.size(), 10u);  // 3 pieces
  EXPECT_EQ(points.back(), P(0, 0, 0));
  EXPECT_EQ(points[7], P(0, 2, 0));  // the last piece's first handle, a third of the way home
}

TEST(Pen, AHermiteDragPutsTheShownHandleUnderThePointer) {
  PenStroke stroke(ObjectKind::Hermite2);
  stroke.press(P(0, 0, 0));
  stroke.drag_to(P(0, 1, 0));
  stroke.press(P(2, 0, 0));  // a click: the chord from its neighbour
  const std::vector<P> points = stroke.points(false);
  ASSERT_EQ(points.size(), 4u);
  EXPECT_EQ(points[1], P(0, 3, 0));
  EXPECT_EQ(points[3], P(2, 0, 0));
  Document doc;
  const int index = add_drawn_curve(doc, ObjectKind::Hermite2, "h", points);
  EXPECT_EQ(shown_points(doc.objects[std::size_t(index)])[1], P(0, 1, 0));
}

TEST(Pen, KindsOfPositionsOnlyTakeTheNodesAsTheyAre) {
  PenStroke stroke(ObjectKind::CatmullRom2);
  stroke.press(P(0, 0, 0));
  stroke.drag_to(P(5, 5, 0));  // nothing to shape
  stroke.press(P(1, 0, 0));
  stroke.press(P(1, 1, 0));
  EXPECT_EQ(stroke.points(false), (std::vector<P>{P(0, 0, 0), P(1, 0, 0), P(1, 1, 0)}));
  EXPECT_EQ(stroke.points(true), (std::vector<P>{P(0, 0, 0), P(1, 0, 0), P(1, 1, 0), P(0, 0, 0)}));
}

// Every kind the pen draws, from its smallest stroke up, open and closed: the reader's count rule
// holds, the curve is closed exactly when drawn closed, and one node fewer is not complete.
TEST(Pen, EveryKindWithControlPointsIsDrawnFromItsLayout) {
  int kinds = 0;
  for (int k = 0; k <= int(ObjectKind::Rider); ++k) {
    const auto kind = ObjectKind(k);
    if (!pen_draws(kind)) continue;
    ++kinds;
    for (const bool closed : {false, true}) {
      const std::size_t least = pen_least_nodes(kind, closed);
      for (std::size_t n = least; n <= least + 3; ++n) {
        std::vector<P> at;
        for (std::size_t i = 0; i < n; ++i) at.push_back(P(std::cos(double(i)), std::sin(double(i)), 0.0));
        PenStroke stroke = clicked(kind, at);
        stroke.drag_to(at.back() + P(0.1, 0.2, 0.0));
        Document doc;
        const int index = add_drawn_curve(doc, kind, "c", stroke.points(closed));
        EXPECT_EQ(is_closed_polygon(doc.objects[std::size_t(index)]), closed) << keyword(kind) << " " << n;
      }
      EXPECT_FALSE(clicked(kind, std::vector<P>(least - 1, P(0.0))).complete(closed)) << keyword(kind);
    }
  }
  EXPECT_EQ(kinds, 12);  // bez, bsp, cr, kb, poly, herm in 2D and 3D
}

TEST(Pen, ADrawnCurveIsWrittenAndReadBackAsItWasDrawn) {
  PenStroke stroke(ObjectKind::Bezier3);
  stroke.press(P(0, 0, 0));
  stroke.drag_to(P(0.25, 0.5, 0.125));
  stroke.press(P(2, 0, 1));
  stroke.drag_to(P(2.5, 0.25, 1));
  Document doc;
  add_drawn_curve(doc, ObjectKind::Bezier3, "drawn", stroke.points(false));
  const Document back = io::parse_swp(io::write_swp(doc));
  ASSERT_EQ(back.objects.size(), 1u);
  EXPECT_EQ(back.objects[0].name, "drawn");
  EXPECT_EQ(back.objects[0].as<PointsPart>().points, stroke.points(false));
}

TEST(Pen, TheDocumentRefusesWhatTheReaderWouldRefuse) {
  Document doc;
  try {
    add_drawn_curve(doc, ObjectKind::BSpline2, "short", {P(0.0), P(1.0), P(2.0)});
    FAIL();
  } catch (const EditError& e) {
    EXPECT_STREQ(e.what(), "a drawn bsp2: expected at least 4 B-spline control points");
  }
  EXPECT_THROW(add_drawn_curve(doc, ObjectKind::Circle, "c", {}), EditError);
  EXPECT_TRUE(doc.objects.empty());
  const int index = add_drawn_curve(doc, ObjectKind::Polyline2, "p", {P(0, 0, 7), P(1, 0, 7)});
  EXPECT_EQ(doc.objects[std::size_t(index)].as<PointsPart>().points[0], P(0.0));  // planar: z dropped
  set_curve_points(doc, index, {P(0.0), P(1.0, 1.0, 0.0), P(2.0, 0.0, 0.0)});
  EXPECT_EQ(doc.objects[std::size_t(index)].as<PointsPart>().points.size(), 3u);
}

// The pen continuing an open curve from a selected end: extend_curve puts the node down, the drag
// shapes it as a drawn node's drag would.
TEST(Pen, ADragAtAnExtendedBezierEndGivesTheNewJointItsIncomingHandle) {
  Document doc = io::parse_swp("bez2 s 4 4\n[0 0]\n[1 1]\n[2 1]\n[3 0]\n");
  extend_curve(doc, 0, CurveEnd::End, P(6, 0, 0));
  const std::vector<P> before = doc.objects[0].as<PointsPart>().points;
  ASSERT_EQ(before.size(), 7u);
  const std::vector<P> after = pen_shape_end(ObjectKind::Bezier2, before, CurveEnd::End, P(0, 1, 0));
  EXPECT_EQ(after[5], P(6, -1, 0));  // the joint minus the drag
  for (std::size_t i = 0; i < 5; ++i) EXPECT_EQ(after[i], before[i]) << i;
  extend_curve(doc, 0, CurveEnd::Start, P(-3, 0, 0));
  const std::vector<P> start =
      pen_shape_end(ObjectKind::Bezier2, doc.objects[0].as<PointsPart>().points, CurveEnd::Start, P(-1, 0, 0));
  EXPECT_EQ(start[1], P(-2, 0, 0));
}

TEST(Pen, ADragAtAnExtendedHermiteEndSetsItsTangentInTheDirectionOfDrawing) {
  const std::vector<P> points = {P(0, 0, 0), P(1, 0, 0), P(2, 0, 0), P(1, 0, 0)};
  EXPECT_EQ(pen_shape_end(ObjectKind::Hermite2, points, CurveEnd::End, P(0, 1, 0))[3], P(0, 3, 0));
  EXPECT_EQ(pen_shape_end(ObjectKind::Hermite2, points, CurveEnd::Start, P(-1, 0, 0))[1], P(3, 0, 0));
  EXPECT_EQ(pen_shape_end(ObjectKind::BSpline2, points, CurveEnd::End, P(0, 1, 0)), points);
}

}  // namespace
}  // namespace sweep::editor
