// move_points: several control points move as one edit, each with its seam partners; a refused
// move (bad index, out-of-range position, a surface that would no longer accept the curve)
// changes none of them.
#include "model/edit/edit.hpp"

#include "model/file_limits.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <vector>

namespace {

using glm::dvec3;
using sweep::Document;
using sweep::PointMove;
using sweep::PointsPart;
using sweep::test::edit_error;
using sweep::test::load_starter;

TEST(EditMovePoints, MovesEveryListedPointAndItsSeamPartnersAndNothingElse) {
  Document doc = load_starter("weird.swp");  // profile: a closed bsp2 of 11 points (0-2 repeat as 8-10)
  const std::vector<dvec3> before = doc.objects[0].as<PointsPart>().points;
  const std::vector<PointMove> moves = {{1, {0.5, 0.25, 3.0}}, {5, {-0.75, 1.5, 0.0}}};
  const sweep::Change change = sweep::move_points(doc, 0, moves);
  EXPECT_EQ(change.objects, std::vector<int>{0});
  EXPECT_FALSE(change.structure);
  const std::vector<dvec3>& after = doc.objects[0].as<PointsPart>().points;
  for (std::size_t i = 0; i < after.size(); ++i) {
    if (i == 1 || i == 9) {
      EXPECT_EQ(after[i], dvec3(0.5, 0.25, 0.0)) << i;  // planar: z dropped
    } else if (i == 5) {
      EXPECT_EQ(after[i], dvec3(-0.75, 1.5, 0.0));
    } else {
      EXPECT_EQ(after[i], before[i]) << i;
    }
  }
  EXPECT_TRUE(sweep::is_closed_polygon(doc.objects[0]));
}

TEST(EditMovePoints, AMoveThatIsRefusedChangesNoneOfThePoints) {
  Document doc = load_starter("weird.swp");
  const Document before = doc;
  const double far = 2.0 * sweep::limits::kMaxCoordinate;
  const std::vector<PointMove> out_of_range = {{3, {0.5, 0.5, 0.0}}, {4, {far, 0.0, 0.0}}};
  EXPECT_EQ(edit_error(doc, [&] { sweep::move_points(doc, 0, out_of_range); }), edit_error(doc, [&] {
              sweep::move_point(doc, 0, 4, {far, 0.0, 0.0});
            }));
  EXPECT_EQ(doc, before);
  const std::vector<PointMove> bad_index = {{3, {0.5, 0.5, 0.0}}, {11, {0.0, 0.0, 0.0}}};
  EXPECT_EQ(edit_error(doc, [&] { sweep::move_points(doc, 0, bad_index); }),
            "point 11 is out of range: curve 'profile' has 11 points");
  EXPECT_EQ(doc, before);
}

TEST(EditMovePoints, NoMovesChangeNothingAndTheLastMoveOfAPointWins) {
  Document doc = load_starter("weird.swp");
  const Document before = doc;
  sweep::move_points(doc, 0, {});
  EXPECT_EQ(doc, before);
  const std::vector<PointMove> twice = {{4, {1.0, 1.0, 0.0}}, {4, {2.0, -1.0, 0.0}}};
  sweep::move_points(doc, 0, twice);
  EXPECT_EQ(doc.objects[0].as<PointsPart>().points[4], dvec3(2.0, -1.0, 0.0));
}

}  // namespace
