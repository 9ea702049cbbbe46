// Several selected control points: click, Shift+click, select all, the rubber band through a
// real camera, the fix after edits, the box centre, and mirroring about it.
#include "editor/point_selection.hpp"

#include "support/core_test_support.hpp"
#include "support/screen_mapping_support.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace sweep::editor {
namespace {

using glm::dvec3;

const std::vector<dvec3>& points_of_object(const Document& doc, int object) {
  return doc.objects[std::size_t(object)].as<PointsPart>().points;
}

TEST(PointSelection, AClickSelectsOnlyThatPointAndMakesItActive) {
  PointSelection selection;
  EXPECT_TRUE(selection.empty());
  EXPECT_EQ(selection.active(), -1);
  selection.toggle(2);
  selection.toggle(5);
  selection.click(3);
  EXPECT_EQ(selection.points(), std::vector<int>{3});
  EXPECT_EQ(selection.active(), 3);
}

TEST(PointSelection, ShiftClickAddsOrRemovesAndKeepsTheIndicesSorted) {
  PointSelection selection;
  selection.click(4);
  selection.toggle(1);
  selection.toggle(7);
  EXPECT_EQ(selection.points(), (std::vector<int>{1, 4, 7}));
  EXPECT_EQ(selection.active(), 7) << "the point added last is active";
  selection.toggle(4);
  EXPECT_EQ(selection.points(), (std::vector<int>{1, 7}));
  EXPECT_EQ(selection.active(), 7) << "removing another point keeps the active one";
  selection.toggle(7);
  EXPECT_EQ(selection.points(), std::vector<int>{1});
  EXPECT_EQ(selection.active(), -1) << "removing the active point leaves none active";
  EXPECT_TRUE(selection.contains(1));
  EXPECT_FALSE(selection.contains(7));
}

TEST(PointSelection, SelectAllTakesEveryPointAndKeepsTheActiveOne) {
  PointSelection selection;
  selection.click(2);
  selection.select_all(5);
  EXPECT_EQ(selection.points(), (std::vector<int>{0, 1, 2, 3, 4}));
  EXPECT_EQ(selection.active(), 2);
  selection.select_all(0);
  EXPECT_TRUE(selection.empty());
  EXPECT_EQ(selection.active(), -1);
}

TEST(PointSelection, ARubberBandReplacesOrWithAModifierAddsToTheSelection) {
  PointSelection selection;
  selection.click(6);
  const std::vector<int> band = {3, 1, 3};
  selection.select(band, true);
  EXPECT_EQ(selection.points(), (std::vector<int>{1, 3, 6}));
  EXPECT_EQ(selection.active(), 6);
  selection.select(band);
  EXPECT_EQ(selection.points(), (std::vector<int>{1, 3}));
  EXPECT_EQ(selection.active(), -1) << "the active point was not in the band";
}

TEST(PointSelection, TheFixAfterAnEditDropsPointsThatAreGone) {
  PointSelection selection;
  selection.select_all(8);
  selection.click(7);
  selection.select_all(8);
  selection.fix(6);
  EXPECT_EQ(selection.points(), (std::vector<int>{0, 1, 2, 3, 4, 5}));
  EXPECT_EQ(selection.active(), -1);
  selection.fix(0);
  EXPECT_TRUE(selection.empty());
}

TEST(PointsInRect, SelectsThePointsWhoseHandlesAreInsideEitherWayRoundTheCorners) {
  // 8 x 6 world units fill the 800 x 600 window: world (x, y) lands on (400 + 100 x, 300 - 100 y).
  const ScreenMapping mapping = test::ortho_mapping();
  const std::vector<dvec3> points = {{0.0, 0.0, 0.0}, {1.0, 1.0, -3.0}, {-1.0, -1.0, 2.0}, {3.0, 2.0, 0.0}};
  EXPECT_EQ(points_in_rect(mapping, points, {510.0, 410.0}, {290.0, 190.0}), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(points_in_rect(mapping, points, {290.0, 410.0}, {510.0, 190.0}), (std::vector<int>{0, 1, 2}));
  EXPECT_EQ(points_in_rect(mapping, points, {400.0, 300.0}, {500.0, 200.0}), (std::vector<int>{0, 1}))
      << "edges count as inside";
  EXPECT_EQ(points_in_rect(mapping, points, {401.0, 299.0}, {499.0, 201.0}), std::vector<int>{});
}

TEST(PointsInRect, APointBehindTheEyeIsNeverInside) {
  const ScreenMapping mapping = test::perspective_mapping();
  const dvec3 behind = test::kEye + (test::kEye - test::kTarget);
  const std::vector<dvec3> points = {test::kTarget, behind};
  EXPECT_EQ(points_in_rect(mapping, points, {0.0, 0.0}, test::kWindow), std::vector<int>{0});
}

TEST(SelectionCentre, IsTheMeanOfTheSelectedPositionsNotTheCentreOfTheirBox) {
  const std::vector<dvec3> points = {{0.0, 0.0, 0.0}, {1.0, 0.0, 4.0},   {11.0, 2.0, -1.0},
                                     {0.0, 2.0, 1.0}, {-50.0, 9.0, 1.0}, {1.0, 0.0, 4.0}};
  PointSelection selection;
  selection.select(std::vector<int>{0, 1, 2, 3});
  EXPECT_EQ(centre(points, selection), dvec3(3.0, 1.0, 1.0));  // the box centre is (5.5, 1, 1.5)
  selection.toggle(5);
  EXPECT_EQ(centre(points, selection), dvec3(3.0, 1.0, 1.0)) << "a position selected twice counts once";
  EXPECT_EQ(box_centre(points, selection), dvec3(5.5, 1.0, 1.5));
  selection.click(4);
  EXPECT_EQ(centre(points, selection), points[4]);
  EXPECT_EQ(box_centre(points, selection), points[4]);
}

TEST(SelectionCentre, TheRepeatedSeamPointsDoNotPullItTowardsTheSeam) {
  const Document doc = sweep::test::load_starter("weird.swp");  // profile: closed bsp2, 0-2 repeat as 8-10
  const std::vector<dvec3>& points = points_of_object(doc, 0);
  PointSelection all;
  all.select_all(static_cast<int>(points.size()));
  PointSelection distinct;
  distinct.select(std::vector<int>{0, 1, 2, 3, 4, 5, 6, 7});
  EXPECT_EQ(centre(points, all), centre(points, distinct));
  EXPECT_EQ(centre(points, all), dvec3(0.0, 0.0, 0.0));
}

TEST(MirrorMoves, MirrorsOneCoordinateAboutTheCentreAndLeavesTheOthersExactly) {
  const std::vector<dvec3> points = {{0.5, 1.0, 2.0}, {1.5, -1.0, 3.0}, {9.0, 9.0, 9.0}};
  PointSelection selection;
  selection.select(std::vector<int>{0, 1});
  const dvec3 pivot = box_centre(points, selection);
  const std::vector<PointMove> moves = mirror_moves(points, selection, 1, pivot);
  ASSERT_EQ(moves.size(), 2u);
  EXPECT_EQ(moves[0].point, 0);
  EXPECT_EQ(moves[0].to, dvec3(0.5, -1.0, 2.0));
  EXPECT_EQ(moves[1].point, 1);
  EXPECT_EQ(moves[1].to, dvec3(1.5, 1.0, 3.0));
}

TEST(MirrorMoves, MirroringTwiceGivesThePointsBackExactlyAndKeepsASeamClosed) {
  Document doc = sweep::test::load_starter("weird.swp");
  const Document before = doc;
  for (int axis : {0, 1}) {
    PointSelection selection;  // their mean is no binary fraction; their box centre is
    selection.select(std::vector<int>{1, 4, 5, 6, 7});
    for (int round = 0; round < 2; ++round) {
      const std::vector<dvec3>& points = points_of_object(doc, 0);
      move_points(doc, 0, mirror_moves(points, selection, axis, box_centre(points, selection), true));
      EXPECT_TRUE(is_closed_polygon(doc.objects[0]));
    }
    EXPECT_EQ(points_of_object(doc, 0), points_of_object(before, 0)) << "axis " << axis;
  }
}

TEST(MirrorMoves, A3DCurveMirroredTwiceAboutZComesBackWithinRounding) {
  Document doc = sweep::test::load_starter("weird.swp");  // sweep: a closed bsp3 of 11 points
  const std::vector<dvec3> start = points_of_object(doc, 1);
  PointSelection selection;
  selection.select_all(static_cast<int>(start.size()));
  for (int round = 0; round < 2; ++round) {
    const std::vector<dvec3>& points = points_of_object(doc, 1);
    move_points(doc, 1, mirror_moves(points, selection, 2, box_centre(points, selection)));
  }
  for (std::size_t i = 0; i < start.size(); ++i) {
    EXPECT_EQ(points_of_object(doc, 1)[i].x, start[i].x);
    EXPECT_EQ(points_of_object(doc, 1)[i].y, start[i].y);
    EXPECT_NEAR(points_of_object(doc, 1)[i].z, start[i].z, 1e-14) << i;
  }
}

TEST(MirrorMoves, ZOfAPlanarCurveIsRefusedWithNoMoves) {
  const std::vector<dvec3> points = {{0.5, 1.0, 0.0}, {1.5, -1.0, 0.0}};
  PointSelection selection;
  selection.select_all(2);
  EXPECT_TRUE(mirror_moves(points, selection, 2, centre(points, selection), true).empty());
  EXPECT_EQ(mirror_moves(points, selection, 2, centre(points, selection), false).size(), 2u);
}

}  // namespace
}  // namespace sweep::editor
