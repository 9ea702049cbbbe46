// The curve-editing actions behind the commands, without a window: a joint's conversion, select
// all and mirror are each one undo step; a corner choice survives collinear handles; the comb is
// made again only when its curve was evaluated again or its scale changed.
#include "app/viewer/curve_actions.hpp"

#include "app/viewer/actions.hpp"
#include "io/swp_parser.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <string>

namespace {

using sweep::editor::JointType;
using sweep::viewer::ViewerState;

// An open bez2 of two pieces: joint 3 is a corner (its handles at right angles).
constexpr const char* kCorner = "bez2 wave 20 7\n[-2 2]\n[-1 2]\n[-1 1]\n[0 0]\n[1 0]\n[2 -1]\n[3 -1]\n";

void open_text(ViewerState& s, const std::string& text) {
  s.session.load(sweep::parse_swp(text, "wave.swp"), "wave.swp");
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
