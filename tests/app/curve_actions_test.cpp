// The curve-editing actions behind the commands, without a window: a joint's conversion, select
// all and mirror are each one undo step; a corner choice survives collinear handles; the comb is
// made again only when its curve was evaluated again or its scale changed.
#include "app/viewer/curve_actions.hpp"

#include "app/viewer/actions.hpp"
#include "io/swp/read.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <string>

namespace {

using sweep::editor::JointType;
using sweep::viewer::ViewerState;

// An open bez2 of two pieces: joint 3 is a corner (its handles at right angles).
constexpr const char* kCorner = "bez2 wave 20 7\n[-2 2]\n[-1 2]\n[-1 1]\n[0 0]\n[1 0]\n[2 -1]\n[3 -1]\n";

void open_text(ViewerState& s, const std::string& text) {
  s.session.load(sweep::io::parse_swp(text, "wave.swp"), "wave.swp");
  s.selection.select(s.session.id_of(0));
}

const glm::dvec3& point(const ViewerState& s, int i) {
  return s.doc().objects[0].as<sweep::PointsPart>().points[std::size_t(i)];
}

TEST(CurveActions, MakingACornerSmoothIsOneUndoStepThatPutsItsHandlesInLine) {
  ViewerState s;
  open_text(s, kCorner);
  s.selection.point = 4;  // a handle of joint 3
  ASSERT_EQ(sweep::viewer::selected_joint(s), 3);
  EXPECT_EQ(sweep::viewer::selected_joint_type(s), JointType::Corner);
  const double in_length = glm::length(point(s, 3) - point(s, 2));
  sweep::viewer::convert_selected_joint(s, JointType::Smooth);
  EXPECT_EQ(sweep::viewer::selected_joint_type(s), JointType::Smooth);
  const glm::dvec3 in = point(s, 3) - point(s, 2), out = point(s, 4) - point(s, 3);
  EXPECT_LT(glm::length(glm::cross(glm::normalize(in), glm::normalize(out))), 1e-12);
  EXPECT_NEAR(glm::length(in), in_length, 1e-12) << "each handle keeps its length";
  EXPECT_EQ(s.session.undo_label(), "make joint 3 smooth");
  ASSERT_TRUE(s.session.undo());
  EXPECT_EQ(sweep::viewer::selected_joint_type(s), JointType::Corner);
  EXPECT_FALSE(s.session.can_undo()) << "one step";
}

TEST(CurveActions, ACornerChosenForInLineHandlesStaysACornerAndMovesNothing) {
  ViewerState s;
  open_text(s, "bez2 line 20 7\n[-3 0]\n[-2 0]\n[-1 0]\n[0 0]\n[2 0]\n[3 0]\n[4 0]\n");
  s.selection.point = 3;
  ASSERT_EQ(sweep::viewer::selected_joint_type(s), JointType::Smooth);
  const sweep::Document before = s.doc();
  sweep::viewer::convert_selected_joint(s, JointType::Corner);
  EXPECT_EQ(sweep::viewer::selected_joint_type(s), JointType::Corner);
  EXPECT_EQ(s.doc(), before);
  EXPECT_FALSE(s.session.dirty());
}

TEST(CurveActions, MirroringSelectedPointsTwiceIsTwoStepsAndGivesThemBack) {
  ViewerState s;
  open_text(s, "bsp2 row 10 5\n[-3 0]\n[-2 1]\n[-1 0.5]\n[0 1]\n[1 0]\n");
  s.selection.group.click(1);
  s.selection.group.toggle(2);
  s.selection.point = 2;
  const sweep::Document before = s.doc();
  sweep::viewer::mirror_selected_points(s, 0);
  EXPECT_EQ(point(s, 1), glm::dvec3(-1, 1, 0)) << "about x = -1.5, the middle of their box";
  EXPECT_EQ(point(s, 2), glm::dvec3(-2, 0.5, 0));
  EXPECT_EQ(point(s, 0), before.objects[0].as<sweep::PointsPart>().points[0]);
  sweep::viewer::mirror_selected_points(s, 0);
  EXPECT_EQ(s.doc(), before);
  ASSERT_TRUE(s.session.undo());
  ASSERT_TRUE(s.session.undo());
  EXPECT_FALSE(s.session.can_undo());
}

TEST(CurveActions, SelectAllTakesEveryPointAndKeepsTheActiveOne) {
  ViewerState s;
  open_text(s, kCorner);
  s.selection.point = 2;
  sweep::viewer::select_all_points(s);
  EXPECT_EQ(s.selection.points(), (std::vector<int>{0, 1, 2, 3, 4, 5, 6}));
  EXPECT_EQ(s.selection.point, 2);
  // A selected joint brings its handles into a transform.
  s.selection.group.click(3);
  s.selection.point = 3;
  EXPECT_EQ(sweep::viewer::points_with_handles(s), (std::vector<int>{2, 3, 4}));
}

TEST(CurveActions, TheCombIsMadeAgainOnlyWhenItsCurveOrScaleChanged) {
  ViewerState s;
  open_text(s, kCorner);
  EXPECT_EQ(sweep::viewer::selected_comb(s), nullptr) << "off until asked";
  s.curve_editing.comb = true;
  const sweep::editor::CurvatureComb* first = sweep::viewer::selected_comb(s);
  ASSERT_NE(first, nullptr);
  const std::vector<glm::dvec3> tips = first->tips;
  const std::uint64_t revision = s.curve_editing.comb_cache.revision;
  EXPECT_EQ(sweep::viewer::selected_comb(s)->tips, tips);
  EXPECT_EQ(s.curve_editing.comb_cache.revision, revision) << "the same curve: the cached comb";
  ASSERT_TRUE(sweep::viewer::run_edit(s, "move", [](sweep::Document& d) {
    return sweep::move_point(d, 0, 1, {-1.0, 2.5, 0.0});
  }));
  EXPECT_NE(sweep::viewer::selected_comb(s)->tips, tips) << "a moved point changes the comb";
  EXPECT_NE(s.curve_editing.comb_cache.revision, revision);
  const double scale = sweep::viewer::selected_comb(s)->scale;
  s.curve_editing.comb_scale = 2.0;
  EXPECT_DOUBLE_EQ(sweep::viewer::selected_comb(s)->scale, 2.0 * scale);
}

}  // namespace

// Issue 61, item 2: I at an open Bezier's last joint adds a whole piece there, one undo step whose
// name the status and the Edit menu give; at a middle joint it says what to do instead.
TEST(CurveActions, IAtAnEndExtendsTheCurveAndUndoNamesTheStep) {
  ViewerState s;
  open_text(s, kCorner);
  s.selection.point = 6;
  EXPECT_EQ(sweep::viewer::insert_label(s), "Add a piece after the end");
  sweep::viewer::insert_after_selected_point(s);
  EXPECT_EQ(s.doc().objects[0].as<sweep::PointsPart>().points.size(), 10u);
  EXPECT_EQ(s.selection.point, 9) << "the new end";
  EXPECT_EQ(s.status, "added a piece after the end");
  sweep::viewer::undo(s);
  EXPECT_EQ(s.status, "undone: add piece");
  sweep::viewer::redo(s);
  EXPECT_EQ(s.status, "redone: add piece");
  s.selection.point = 3;
  EXPECT_EQ(sweep::viewer::insert_label(s), "Insert: select an end to add a piece (or split a piece)");
  sweep::viewer::insert_after_selected_point(s);
  EXPECT_EQ(s.error,
            "a Bezier curve grows at its ends: select its first or last point, or split a piece to add a joint");
}

// Item 4: a status never outlives what it describes: Del after an insert says what Del did.
TEST(CurveActions, TheStatusSaysTheLastStepOnly) {
  ViewerState s;
  open_text(s, "bsp2 arc 4 5\n[0 0]\n[1 1]\n[2 0]\n[3 1]\n[4 0]\n");
  s.selection.point = 1;
  sweep::viewer::insert_after_selected_point(s);
  EXPECT_EQ(s.status, "inserted point 2");
  sweep::viewer::delete_selected_point(s);
  EXPECT_EQ(s.status, "deleted point 2");
  s.selection.point = 0;
  sweep::viewer::insert_after_selected_point(s);
  EXPECT_EQ(s.status, "added a point before the start");
  EXPECT_EQ(point(s, 0), glm::dvec3(-1.0, -1.0, 0.0)) << "one step on from the end, as the last step went";
}

// Item 4: snap selection to grid moves each selected point to the nearest grid point, a joint's
// handles along with it; one undo step.
TEST(CurveActions, SnappingTheSelectionMovesEachPointToTheGridAndAJointsHandlesAlong) {
  ViewerState s;
  open_text(s, "bez2 wave 20 7\n[-2.1 2]\n[-1 2]\n[-1 1.1]\n[0.1 0.12]\n[1 0]\n[2 -1]\n[3 -1]\n");
  s.snap_size = 0.5;
  s.selection.point = 3;
  const glm::dvec3 handle_in = point(s, 2) - point(s, 3);
  sweep::viewer::snap_selected_points(s);
  EXPECT_EQ(point(s, 3), glm::dvec3(0.0, 0.0, 0.0));
  EXPECT_NEAR(glm::length(point(s, 2) - point(s, 3) - handle_in), 0.0, 1e-12) << "the handle went along";
  EXPECT_EQ(point(s, 0), glm::dvec3(-2.1, 2.0, 0.0)) << "unselected points stay";
  EXPECT_EQ(s.status, "snapped 1 point to the grid (0.5)");
  EXPECT_EQ(s.session.undo_label(), "snap points to the grid");
}

// Item 4: F frames the selected points when there are any, not the whole curve.
TEST(CurveActions, FFramesTheSelectedPoints) {
  ViewerState s;
  open_text(s, "bsp3 long 4 5\n[0 0 0]\n[10 0 0]\n[20 0 0]\n[30 0 0]\n[40 0 0]\n");
  s.selection.point = 4;
  sweep::viewer::frame_selection(s);
  EXPECT_NEAR(s.camera.target.x, 40.0, 1e-9) << "centred on the point";
  const double near = s.camera.distance;
  s.selection.point = -1;
  sweep::viewer::frame_selection(s);
  EXPECT_NEAR(s.camera.target.x, 20.0, 1e-6) << "the whole curve";
  EXPECT_GT(s.camera.distance, 2.0 * near);
}
