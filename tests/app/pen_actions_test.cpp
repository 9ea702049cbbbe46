// The pen's actions without a window: a stroke is one undo step and becomes a curve of the
// document once it has the nodes its kind needs (and stops being one when taken back below them),
// ended with too few it draws nothing and says how many it needs, a closed one closes; from a
// selected end it continues that curve, each node an undo step, a drag shaping the new end.
#include "app/viewer/pen_actions.hpp"

#include "app/viewer/actions.hpp"
#include "io/swp/read.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using sweep::ObjectKind;
using sweep::PointsPart;
using sweep::viewer::ViewerState;
using P = glm::dvec3;

void open_text(ViewerState& s, const std::string& text) {
  s.session.load(sweep::io::parse_swp(text, "pen.swp"), "pen.swp");
}

const std::vector<P>& points(const ViewerState& s, int i) {
  return s.doc().objects[std::size_t(i)].as<PointsPart>().points;
}

TEST(PenActions, AStrokeIsACurveOnceItHasTheNodesItsKindNeedsAndOneUndoStep) {
  ViewerState s;
  open_text(s, "circ ring 8 1\n");
  sweep::viewer::toggle_pen(s);
  ASSERT_TRUE(s.pen.on);
  for (const P& at : {P(0, 0, 0), P(1, 0, 0), P(1, 1, 0)}) sweep::viewer::pen_place(s, at);
  EXPECT_EQ(s.doc().objects.size(), 1u) << "a B-spline needs 4 nodes";
  sweep::viewer::pen_place(s, P(0, 1, 0));
  ASSERT_EQ(s.doc().objects.size(), 2u);
  EXPECT_EQ(s.selected(), 1) << "the drawn curve is selected as soon as it is one";
  sweep::viewer::pen_take_back(s);
  EXPECT_EQ(s.doc().objects.size(), 1u) << "taken back below 4: no curve";
  sweep::viewer::pen_place(s, P(0, 1, 0));
  sweep::viewer::pen_place(s, P(-1, 0.5, 0));
  sweep::viewer::pen_finish(s);
  EXPECT_EQ(s.status, "drew bsp2 'profile' (5 points)");
  EXPECT_EQ(points(s, 1).size(), 5u);
  EXPECT_EQ(s.session.undo_label(), "draw curve");
  ASSERT_TRUE(s.session.undo());
  EXPECT_EQ(s.doc().objects.size(), 1u);
  EXPECT_FALSE(s.session.can_undo()) << "one step";
}

TEST(PenActions, TooFewNodesDrawNothingAndSaySoAndAClickOnTheFirstCloses) {
  ViewerState s;
  open_text(s, "circ ring 8 1\n");
  s.pen.on = true;
  s.pen.kind = ObjectKind::CatmullRom2;
  sweep::viewer::pen_place(s, P(0, 0, 0));
  sweep::viewer::pen_finish(s);
  EXPECT_EQ(s.status, "a cr2 needs 2 clicks: nothing drawn");
  EXPECT_FALSE(s.session.can_undo());
  sweep::viewer::pen_place(s, P(0, 0, 0));
  sweep::viewer::pen_place(s, P(1, 0, 0));
  EXPECT_FALSE(sweep::viewer::pen_close(s));
  EXPECT_EQ(s.status, "a closed cr2 needs 3 clicks");
  sweep::viewer::pen_place(s, P(0, 1, 0));
  EXPECT_TRUE(sweep::viewer::pen_close(s));
  EXPECT_EQ(s.status, "drew cr2 'profile' (4 points, closed)");
  EXPECT_TRUE(sweep::is_closed_polygon(s.doc().objects[1]));
}

TEST(PenActions, FromASelectedEndThePenContinuesThatCurveANodeAStep) {
  ViewerState s;
  open_text(s, "bez2 wave 20 4\n[0 0]\n[1 1]\n[2 1]\n[3 0]\n");
  s.selection.select(s.session.id_of(0));
  s.selection.point = 3;  // the last joint
  s.pen.on = true;
  ASSERT_EQ(sweep::viewer::pen_continues(s), 0);
  sweep::viewer::pen_place(s, P(6, 0, 0));
  sweep::viewer::pen_drag(s, P(6, 1, 0));
  sweep::viewer::pen_release(s);
  ASSERT_EQ(points(s, 0).size(), 7u);
  EXPECT_EQ(points(s, 0)[6], P(6, 0, 0));
  EXPECT_EQ(points(s, 0)[5], P(6, -1, 0)) << "the joint's incoming handle mirrors the drag";
  EXPECT_EQ(points(s, 0)[4], P(4, -1, 0)) << "the old end stays smooth (mirrored handle)";
  EXPECT_EQ(s.selection.point, 6) << "the new end is selected: the next node goes on from it";
  sweep::viewer::pen_place(s, P(9, 0, 0));
  sweep::viewer::pen_release(s);
  EXPECT_EQ(points(s, 0).size(), 10u);
  sweep::viewer::pen_take_back(s);
  EXPECT_EQ(points(s, 0).size(), 7u);
  sweep::viewer::pen_finish(s);
  EXPECT_EQ(s.status, "continued 'wave' by 1 node");
  EXPECT_EQ(s.doc().objects.size(), 1u);
  EXPECT_EQ(s.session.undo_label(), "extend curve");
}

}  // namespace
