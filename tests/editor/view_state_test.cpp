// View state and selection keyed by object id: visibility and the selection follow their object
// through deletions, undo and redo instead of sticking to a position in the document.
#include "editor/view_state.hpp"
#include "io/swp/read.hpp"
#include "model/edit/edit.hpp"
#include "support/editor_test_support.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace sweep::editor {
namespace {

constexpr const char* kThreeCircles = "circ a 8 1\ncirc b 8 1\ncirc c 8 1\n";

// A B-spline of six points (indices 0..5) and a circle after it.
constexpr const char* kCurves =
    "circ ring 16 0.5\n"
    "bsp2 arc 4 6\n[0 0]\n[1 1]\n[2 0]\n[3 1]\n[4 0]\n[5 1]\n";

using test::session_of;

TEST(ViewStates, EveryObjectIsVisibleUntilHidden) {
  ViewStates states;
  EXPECT_TRUE(states.visible(1));
  EXPECT_TRUE(states.visible(12345));
  EXPECT_TRUE(states.get(7).visible);
  states.set_visible(7, false);
  EXPECT_FALSE(states.visible(7));
  EXPECT_FALSE(states.get(7).visible);
  EXPECT_TRUE(states.visible(8)) << "only the object with that id is hidden";
  states.at(8).visible = false;
  EXPECT_FALSE(states.visible(8));
  states.set_visible(7, true);
  EXPECT_TRUE(states.visible(7));
  states.clear();
  EXPECT_TRUE(states.visible(8)) << "clear forgets everything";
}

TEST(ViewStates, VisibilityIsInDocumentOrder) {
  const EditSession session = session_of(kThreeCircles);
  ViewStates states;
  EXPECT_EQ(states.visibility(session.document()), (std::vector<bool>{true, true, true}));
  states.set_visible(session.id_of(1), false);
  EXPECT_EQ(states.visibility(session.document()), (std::vector<bool>{true, false, true}));
  states.set_visible(session.id_of(2), false);
  states.set_visible(session.id_of(1), true);
  EXPECT_EQ(states.visibility(session.document()), (std::vector<bool>{true, true, false}));
}

// The defect this design fixes: visibility was a vector indexed by position, so deleting an
// object and undoing the deletion moved a hidden flag onto a neighbour.
TEST(ViewStates, AHiddenObjectStaysHiddenThroughADeletionAndItsUndo) {
  EditSession session = session_of(kThreeCircles);
  ViewStates states;
  const ObjectId a = session.id_of(0);
  const ObjectId b = session.id_of(1);
  const ObjectId c = session.id_of(2);
  states.set_visible(c, false);

  ASSERT_TRUE(session.edit("delete a", [](Document& d) { return delete_object(d, 0); }));
  EXPECT_EQ(states.visibility(session.document()), (std::vector<bool>{true, false})) << "b shown, c hidden";

  ASSERT_TRUE(session.undo());
  ASSERT_EQ(session.document().objects[2].name, "c");
  EXPECT_EQ(states.visibility(session.document()), (std::vector<bool>{true, true, false}));
  EXPECT_TRUE(states.visible(a));
  EXPECT_TRUE(states.visible(b));
  EXPECT_FALSE(states.visible(c));
  EXPECT_EQ(session.id_of(2), c);

  ASSERT_TRUE(session.redo());
  EXPECT_EQ(states.visibility(session.document()), (std::vector<bool>{true, false}));
}

TEST(Selection, SelectKeepsThePointOnlyForTheSameObject) {
  const EditSession session = session_of(kCurves);
  Selection selection;
  EXPECT_EQ(selection.index(session), -1);
  selection.select(session.id_of(1));
  EXPECT_EQ(selection.object, session.id_of(1));
  EXPECT_EQ(selection.point, -1);
  EXPECT_EQ(selection.index(session), 1);
  selection.point = 3;
  selection.select(session.id_of(1));
  EXPECT_EQ(selection.point, 3) << "selecting the same object keeps its point";
  selection.select(session.id_of(0));
  EXPECT_EQ(selection.point, -1);
  EXPECT_EQ(selection.index(session), 0);
  selection.point = 2;
  selection.hovered_point = 1;
  selection.clear();
  EXPECT_EQ(selection.object, kNoObject);
  EXPECT_EQ(selection.point, -1);
  EXPECT_EQ(selection.hovered_point, -1);
  EXPECT_EQ(selection.index(session), -1);
}

TEST(Selection, TheGroupCountsWhileItHoldsTheActivePointAndGoesWithTheObject) {
  const EditSession session = session_of(kCurves);
  Selection selection;
  selection.select(session.id_of(1));
  EXPECT_TRUE(selection.points().empty());
  selection.group.click(1);
  selection.group.toggle(3);
  selection.group.toggle(2);
  selection.point = selection.group.active();
  EXPECT_EQ(selection.points(), (std::vector<int>{1, 2, 3}));
  selection.point = 0;  // the point table or an insert chose one point
  EXPECT_EQ(selection.points(), std::vector<int>{0});
  selection.point = 3;
  selection.select(session.id_of(1));
  EXPECT_EQ(selection.points(), (std::vector<int>{1, 2, 3})) << "the same object keeps its points";
  selection.select(session.id_of(0));
  EXPECT_TRUE(selection.points().empty());
  EXPECT_TRUE(selection.group.empty());
}

TEST(Selection, FixDropsTheSelectionOfADeletedObject) {
  EditSession session = session_of(kCurves);
  Selection selection;
  selection.select(session.id_of(0));
  ASSERT_TRUE(session.edit("delete ring", [](Document& d) { return delete_object(d, 0); }));
  selection.fix(session);
  EXPECT_EQ(selection.object, kNoObject);
  EXPECT_EQ(selection.index(session), -1);
}

TEST(Selection, FixFollowsTheObjectWhenItMovesAndThroughUndoAndRedo) {
  EditSession session = session_of(kCurves);
  Selection selection;
  const ObjectId arc = session.id_of(1);
  selection.select(arc);
  selection.point = 4;
  ASSERT_TRUE(session.edit("delete ring", [](Document& d) { return delete_object(d, 0); }));
  selection.fix(session);
  EXPECT_EQ(selection.object, arc);
  EXPECT_EQ(selection.index(session), 0) << "the arc moved up";
  EXPECT_EQ(selection.point, 4);

  ASSERT_TRUE(session.undo());
  selection.fix(session);
  EXPECT_EQ(selection.index(session), 1);
  EXPECT_EQ(selection.point, 4);
  ASSERT_TRUE(session.redo());
  selection.fix(session);
  EXPECT_EQ(selection.index(session), 0);
  EXPECT_EQ(selection.point, 4);
}

TEST(Selection, FixKeepsThePointsWithinTheCurveAfterADeletedPoint) {
  EditSession session = session_of(kCurves);
  Selection selection;
  selection.select(session.id_of(1));
  selection.point = 5;  // the last of six
  selection.hovered_point = 5;
  ASSERT_TRUE(session.edit("delete point", [](Document& d) { return delete_point(d, 1, 5); }));
  ASSERT_EQ(session.document().objects[1].as<sweep::PointsPart>().points.size(), 5u);
  selection.fix(session);
  EXPECT_EQ(selection.index(session), 1);
  EXPECT_EQ(selection.point, 4) << "clamped to the new last point";
  EXPECT_EQ(selection.hovered_point, -1) << "the hovered handle is gone";

  selection.point = 2;
  selection.hovered_point = 3;
  selection.fix(session);
  EXPECT_EQ(selection.point, 2) << "points in range stay";
  EXPECT_EQ(selection.hovered_point, 3);

  ASSERT_TRUE(session.undo());
  selection.fix(session);
  EXPECT_EQ(selection.index(session), 1);
  EXPECT_EQ(selection.point, 2);
}

TEST(Selection, FixOnACircleLeavesNoPointSelected) {
  const EditSession session = session_of(kCurves);
  Selection selection;
  selection.select(session.id_of(0));
  selection.point = 0;
  selection.hovered_point = 0;
  selection.fix(session);
  EXPECT_EQ(selection.index(session), 0);
  EXPECT_EQ(selection.point, -1) << "a circle has no control points";
  EXPECT_EQ(selection.hovered_point, -1);
}

}  // namespace
}  // namespace sweep::editor
