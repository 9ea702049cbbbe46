// Modal grab, rotate and scale of selected points: typed numbers are exact (four quarter turns
// come back within 1e-12), the pointer drives them through a real camera, axis constraints
// leave the other coordinates exactly, cancel restores, planar curves stay in z = 0, and applied
// with move_points the seam points follow and out-of-range moves are refused.
#include "editor/point_transform.hpp"

#include "model/file_limits.hpp"
#include "support/core_test_support.hpp"
#include "support/screen_mapping_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <string_view>
#include <vector>

namespace sweep::editor {
namespace {

using glm::dvec2;
using glm::dvec3;

constexpr int kProfile = 0;  // weird.swp: a closed bsp2 of 11 points, 0-2 repeated as 8-10
constexpr int kSweep = 1;    // weird.swp: a closed bsp3 of 11 points
// In the orthographic test camera world (x, y) lands on window (400 + 100 x, 300 - 100 y).
const dvec2 kOrigin{400.0, 300.0};

const std::vector<dvec3>& points_of(const Document& doc, int object) {
  return doc.objects[std::size_t(object)].as<PointsPart>().points;
}

PointSelection all_points(const Document& doc, int object) {
  PointSelection selection;
  selection.select_all(static_cast<int>(points_of(doc, object).size()));
  return selection;
}

PointTransform begin(const Document& doc, int object, const PointSelection& selection, TransformMode mode,
                     dvec2 pointer = {500.0, 300.0}, const ScreenMapping& mapping = test::ortho_mapping(),
                     dvec3 view_forward = {0.0, 0.0, -1.0}) {
  TransformStart start = transform_start(mode, points_of(doc, object), selection, object == kProfile);
  start.pointer = pointer;
  start.mapping = mapping;
  start.view_forward = view_forward;
  PointTransform transform;
  transform.start(std::move(start));
  return transform;
}

void type_text(PointTransform& transform, std::string_view text) {
  for (char key : text) ASSERT_TRUE(transform.type(key)) << key;
}

/// One transform of `selection` by the typed `text` (about `axis`, -1 none), confirmed and applied.
void typed_transform(Document& doc, int object, const PointSelection& selection, TransformMode mode, int axis,
                     std::string_view text, dvec3 view_forward = {0.0, 0.0, -1.0}) {
  PointTransform transform = begin(doc, object, selection, mode, {500.0, 300.0}, test::ortho_mapping(), view_forward);
  if (axis >= 0) {
    ASSERT_TRUE(transform.toggle_axis(axis));
  }
  type_text(transform, text);
  move_points(doc, object, transform.confirm());
}

void expect_near(const std::vector<dvec3>& actual, const std::vector<dvec3>& expected, double tolerance) {
  ASSERT_EQ(actual.size(), expected.size());
  for (std::size_t i = 0; i < actual.size(); ++i) {
    EXPECT_LT(glm::length(actual[i] - expected[i]), tolerance) << "point " << i;
  }
}

TEST(PointTransform, GrabByTyped1Point5MovesEveryPointByExactlyThatAlongX) {
  const Document doc = sweep::test::load_starter("weird.swp");
  PointSelection selection;
  selection.select(std::vector<int>{0, 3, 5});
  PointTransform grab = begin(doc, kSweep, selection, TransformMode::Grab);
  type_text(grab, "1.5");
  const std::vector<PointMove> moves = grab.update({123.0, 456.0});  // the typed number overrides the pointer
  ASSERT_EQ(moves.size(), 3u);
  for (const PointMove& move : moves) {
    EXPECT_EQ(move.to, points_of(doc, kSweep)[std::size_t(move.point)] + dvec3(1.5, 0.0, 0.0)) << move.point;
  }
  EXPECT_EQ(grab.status(), "Grab along x: [1.5]");
}

TEST(PointTransform, GrabAlongAnAxisByPointerChangesOnlyThatCoordinate) {
  const Document doc = sweep::test::load_starter("weird.swp");
  const ScreenMapping mapping = test::perspective_mapping();
  const dvec3 forward = glm::normalize(test::kTarget - test::kEye);
  PointTransform grab =
      begin(doc, kSweep, all_points(doc, kSweep), TransformMode::Grab, {400.0, 300.0}, mapping, forward);
  ASSERT_TRUE(grab.toggle_axis(1));
  const std::vector<PointMove> moves = grab.update({430.0, 250.0});
  for (const PointMove& move : moves) {
    const dvec3& from = points_of(doc, kSweep)[std::size_t(move.point)];
    EXPECT_EQ(move.to.x, from.x);
    EXPECT_GT(move.to.y, from.y) << "up on the screen is up";
    EXPECT_EQ(move.to.z, from.z);
  }
}

TEST(PointTransform, APlanarGrabFollowsThePointerInTheXyPlaneAndComesBackExactly) {
  const Document doc = sweep::test::load_starter("weird.swp");
  PointTransform grab = begin(doc, kProfile, all_points(doc, kProfile), TransformMode::Grab, {500.0, 300.0});
  for (const PointMove& move : grab.update({600.0, 250.0})) {
    const dvec3& from = points_of(doc, kProfile)[std::size_t(move.point)];
    EXPECT_LT(glm::length(move.to - (from + dvec3(1.0, 0.5, 0.0))), 1e-12);
    EXPECT_EQ(move.to.z, 0.0);
  }
  EXPECT_EQ(grab.status(), "Grab 1, 0.5");
  for (const PointMove& move : grab.update({500.0, 300.0})) {
    EXPECT_EQ(move.to, points_of(doc, kProfile)[std::size_t(move.point)]);
  }
  const dvec3 forward = glm::normalize(test::kTarget - test::kEye);
  PointTransform oblique = begin(doc, kProfile, all_points(doc, kProfile), TransformMode::Grab, {400.0, 300.0},
                                 test::perspective_mapping(), forward);
  for (const PointMove& move : oblique.update({520.0, 210.0})) EXPECT_EQ(move.to.z, 0.0);
}

/// A grab of weird.swp's sweep points 2, 4 and 6 held by point 4, pressed where it shows in the
/// perspective mapping, snapping to `grid` (0: none).
TransformStart drag_by_point_4(const Document& doc, const ScreenMapping& mapping, double grid) {
  PointSelection selection;
  selection.select(std::vector<int>{2, 4, 6});
  TransformStart start = transform_start(TransformMode::Grab, points_of(doc, kSweep), selection, false);
  start.anchor = points_of(doc, kSweep)[4];
  start.pointer = to_screen(mapping, *start.anchor).value_or(dvec2(-1.0));
  start.mapping = mapping;
  start.view_forward = glm::normalize(test::kTarget - test::kEye);
  start.grid = grid;
  return start;
}

TEST(PointTransform, DraggingTheSelectionByOneOfItsPointsKeepsThatPointUnderThePointer) {
  const Document doc = sweep::test::load_starter("weird.swp");
  const ScreenMapping mapping = test::perspective_mapping();
  const dvec3 held = points_of(doc, kSweep)[4];
  const std::optional<dvec2> pressed = to_screen(mapping, held);
  ASSERT_TRUE(pressed);
  PointTransform drag;
  drag.start(drag_by_point_4(doc, mapping, 0.0));
  const dvec2 pointer = *pressed + dvec2(-70.0, 40.0);
  const std::vector<PointMove> moves = drag.update(pointer);
  ASSERT_EQ(moves.size(), 3u);
  const std::optional<dvec2> shown = to_screen(mapping, moves[1].to);
  ASSERT_TRUE(shown);
  EXPECT_LT(glm::length(*shown - pointer), 1e-6);
  const dvec3 offset = moves[1].to - held;
  EXPECT_LT(glm::length(moves[0].to - (points_of(doc, kSweep)[2] + offset)), 1e-12) << "the others move with it";
  EXPECT_LT(glm::length(moves[2].to - (points_of(doc, kSweep)[6] + offset)), 1e-12);
}

// Issue 61, item 4: with grid snapping on, a selection dragged by one of its points puts that
// point on the grid and the others keep their offsets from it.
TEST(PointTransform, ASnappedDragPutsTheGrabbedPointOnTheGridAndKeepsTheOffsets) {
  const Document doc = sweep::test::load_starter("weird.swp");
  const ScreenMapping mapping = test::perspective_mapping();
  const dvec3 held = points_of(doc, kSweep)[4];
  const std::optional<dvec2> pressed = to_screen(mapping, held);
  ASSERT_TRUE(pressed);
  PointTransform drag;
  drag.start(drag_by_point_4(doc, mapping, 0.25));
  const std::vector<PointMove> moves = drag.update(*pressed + dvec2(-70.0, 40.0));
  ASSERT_EQ(moves.size(), 3u);
  for (int axis = 0; axis < 3; ++axis) {
    EXPECT_NEAR(moves[1].to[axis] / 0.25, std::round(moves[1].to[axis] / 0.25), 1e-9) << axis;
  }
  const dvec3 offset = moves[1].to - held;
  EXPECT_LT(glm::length(moves[0].to - (points_of(doc, kSweep)[2] + offset)), 1e-12) << "the others keep their offsets";
  EXPECT_LT(glm::length(moves[2].to - (points_of(doc, kSweep)[6] + offset)), 1e-12);
}

TEST(PointTransform, FourTypedQuarterTurnsReturnThePointsWithin1eMinus12) {
  Document doc = sweep::test::load_starter("weird.swp");
  const dvec3 forward = glm::normalize(test::kTarget - test::kEye);
  for (int axis : {0, 1, 2, -1}) {
    const std::vector<dvec3> start = points_of(doc, kSweep);
    for (int round = 0; round < 4; ++round) {
      typed_transform(doc, kSweep, all_points(doc, kSweep), TransformMode::Rotate, axis, "90", forward);
    }
    expect_near(points_of(doc, kSweep), start, 1e-12);
  }
}

TEST(PointTransform, ATypedQuarterTurnAboutZIsRightHandedAndKeepsZExactly) {
  const Document doc = sweep::test::load_starter("weird.swp");
  const PointSelection selection = all_points(doc, kSweep);
  PointTransform rotate = begin(doc, kSweep, selection, TransformMode::Rotate);
  ASSERT_TRUE(rotate.toggle_axis(2));
  type_text(rotate, "90");
  const dvec3 c = centre(points_of(doc, kSweep), selection);
  for (const PointMove& move : rotate.moves()) {
    const dvec3& p = points_of(doc, kSweep)[std::size_t(move.point)];
    EXPECT_EQ(move.to, dvec3(c.x - (p.y - c.y), c.y + (p.x - c.x), p.z));
  }
  EXPECT_EQ(rotate.status(), "Rotate [90]\xC2\xB0 about z");
}

TEST(PointTransform, APlanarCurveTurnsAboutZStaysInTheXyPlaneAndClosed) {
  Document doc = sweep::test::load_starter("weird.swp");
  const std::vector<dvec3> start = points_of(doc, kProfile);
  const dvec3 oblique = glm::normalize(dvec3(1.0, -2.0, -0.5));
  for (int round = 0; round < 4; ++round) {
    typed_transform(doc, kProfile, all_points(doc, kProfile), TransformMode::Rotate, -1, "90", oblique);
    for (const dvec3& p : points_of(doc, kProfile)) EXPECT_EQ(p.z, 0.0);
    EXPECT_TRUE(is_closed_polygon(doc.objects[kProfile]));
  }
  expect_near(points_of(doc, kProfile), start, 1e-12);
}

TEST(PointTransform, ThePointerTurnsAnticlockwiseOnScreenAndPastAHalfTurn) {
  const Document doc = sweep::test::load_starter("weird.swp");  // the profile's centre is the origin
  PointTransform rotate =
      begin(doc, kProfile, all_points(doc, kProfile), TransformMode::Rotate, kOrigin + dvec2(100, 0));
  for (const PointMove& move : rotate.update(kOrigin + dvec2(0.0, -100.0))) {
    const dvec3& p = points_of(doc, kProfile)[std::size_t(move.point)];
    EXPECT_LT(glm::length(move.to - dvec3(-p.y, p.x, 0.0)), 1e-12);
  }
  EXPECT_EQ(rotate.status(), "Rotate 90\xC2\xB0 about z");
  rotate.update(kOrigin + dvec2(-100.0, 0.0));
  rotate.update(kOrigin + dvec2(0.0, 100.0));
  rotate.update(kOrigin + dvec2(0.0, 0.5));  // too close to the centre: ignored
  EXPECT_EQ(rotate.status(), "Rotate 270\xC2\xB0 about z");
  rotate.update(kOrigin + dvec2(100.0, 0.0));
  EXPECT_EQ(rotate.status(), "Rotate 360\xC2\xB0 about z");
  const std::vector<PointMove> moves = rotate.confirm();
  EXPECT_FALSE(rotate.active());
  for (const PointMove& move : moves) {
    EXPECT_LT(glm::length(move.to - points_of(doc, kProfile)[std::size_t(move.point)]), 1e-12);
  }
}

TEST(PointTransform, ScalingBy2Then0Point5ReturnsThePoints) {
  Document doc = sweep::test::load_starter("weird.swp");
  const std::vector<dvec3> start = points_of(doc, kSweep);
  typed_transform(doc, kSweep, all_points(doc, kSweep), TransformMode::Scale, -1, "2");
  const std::vector<dvec3> doubled = points_of(doc, kSweep);
  typed_transform(doc, kSweep, all_points(doc, kSweep), TransformMode::Scale, -1, "0.5");
  expect_near(points_of(doc, kSweep), start, 1e-12);
  EXPECT_GT(glm::length(doubled[0] - start[0]), 0.1);
}

TEST(PointTransform, ScalingAlongYChangesOnlyY) {
  const Document doc = sweep::test::load_starter("weird.swp");
  const PointSelection selection = all_points(doc, kSweep);
  PointTransform scale = begin(doc, kSweep, selection, TransformMode::Scale);
  ASSERT_TRUE(scale.toggle_axis(1));
  type_text(scale, "3");
  const dvec3 c = centre(points_of(doc, kSweep), selection);
  for (const PointMove& move : scale.moves()) {
    const dvec3& p = points_of(doc, kSweep)[std::size_t(move.point)];
    EXPECT_EQ(move.to, dvec3(p.x, c.y + 3.0 * (p.y - c.y), p.z));
  }
  EXPECT_EQ(scale.status(), "Scale [3] along y");
}

TEST(PointTransform, ThePointersDistanceFromTheCentreScales) {
  const Document doc = sweep::test::load_starter("weird.swp");
  PointTransform scale = begin(doc, kProfile, all_points(doc, kProfile), TransformMode::Scale, kOrigin + dvec2(60, 80));
  for (const PointMove& move : scale.update(kOrigin + dvec2(-200.0, 0.0))) {
    EXPECT_LT(glm::length(move.to - 2.0 * points_of(doc, kProfile)[std::size_t(move.point)]), 1e-12);
  }
  EXPECT_EQ(scale.status(), "Scale 2");
}

TEST(PointTransform, CancelGivesTheOriginalPositions) {
  const Document doc = sweep::test::load_starter("weird.swp");
  PointSelection selection;
  selection.select(std::vector<int>{2, 6});
  for (TransformMode mode : {TransformMode::Grab, TransformMode::Rotate, TransformMode::Scale}) {
    PointTransform transform = begin(doc, kSweep, selection, mode);
    transform.update({650.0, 120.0});
    ASSERT_TRUE(transform.toggle_axis(0));
    type_text(transform, "7");
    const std::vector<PointMove> moves = transform.cancel();
    EXPECT_FALSE(transform.active());
    ASSERT_EQ(moves.size(), 2u);
    EXPECT_EQ(moves[0].point, 2);
    EXPECT_EQ(moves[0].to, points_of(doc, kSweep)[2]);
    EXPECT_EQ(moves[1].point, 6);
    EXPECT_EQ(moves[1].to, points_of(doc, kSweep)[6]);
  }
}

TEST(PointTransform, TheSameAxisAgainRemovesTheConstraintAndAPlanarCurveRefusesZ) {
  const Document doc = sweep::test::load_starter("weird.swp");
  PointTransform sweep_grab = begin(doc, kSweep, all_points(doc, kSweep), TransformMode::Grab);
  EXPECT_TRUE(sweep_grab.toggle_axis(0) && sweep_grab.axis() == 0);
  EXPECT_TRUE(sweep_grab.toggle_axis(0) && sweep_grab.axis() == -1);
  EXPECT_TRUE(sweep_grab.toggle_axis(1));
  EXPECT_TRUE(sweep_grab.toggle_axis(2));
  EXPECT_EQ(sweep_grab.axis(), 2);
  PointTransform profile_grab = begin(doc, kProfile, all_points(doc, kProfile), TransformMode::Grab);
  EXPECT_TRUE(profile_grab.toggle_axis(1));
  EXPECT_FALSE(profile_grab.toggle_axis(2));
  EXPECT_EQ(profile_grab.axis(), 1);
}

TEST(PointTransform, TypingTakesDigitsOnePointAndASignThatFlips) {
  const Document doc = sweep::test::load_starter("weird.swp");
  PointTransform scale = begin(doc, kSweep, all_points(doc, kSweep), TransformMode::Scale);
  EXPECT_FALSE(scale.type('a'));
  EXPECT_TRUE(scale.type('-'));
  EXPECT_EQ(scale.status(), "Scale [-]") << "a sign alone shows but does not override the pointer";
  EXPECT_EQ(scale.moves()[0].to, points_of(doc, kSweep)[0]);
  type_text(scale, "1.2");
  EXPECT_FALSE(scale.type('.'));
  EXPECT_TRUE(scale.type('-'));
  EXPECT_EQ(scale.typed(), "1.2");
  EXPECT_TRUE(scale.type('-'));
  scale.backspace();
  EXPECT_EQ(scale.typed(), "-1.");
  for (int i = 0; i < 4; ++i) scale.backspace();
  EXPECT_EQ(scale.typed(), "");
}

TEST(PointTransform, SeamPartnersFollowWhenAppliedWithMovePoints) {
  Document doc = sweep::test::load_starter("weird.swp");
  PointSelection selection;
  selection.select(std::vector<int>{1, 4});
  typed_transform(doc, kProfile, selection, TransformMode::Rotate, -1, "90");
  const std::vector<dvec3>& points = points_of(doc, kProfile);
  EXPECT_EQ(points[9], points[1]);
  EXPECT_TRUE(is_closed_polygon(doc.objects[kProfile]));
}

TEST(PointTransform, AMoveBeyondTheCoordinateRangeIsRefusedAndChangesNothing) {
  Document doc = sweep::test::load_starter("weird.swp");
  const Document before = doc;
  PointSelection selection;
  selection.select(std::vector<int>{3, 4});
  PointTransform grab = begin(doc, kProfile, selection, TransformMode::Grab);
  type_text(grab, std::to_string(2.0 * limits::kMaxCoordinate));
  const std::vector<PointMove> moves = grab.confirm();
  EXPECT_EQ(sweep::test::edit_error(doc, [&] { move_points(doc, kProfile, moves); }),
            sweep::test::edit_error(doc, [&] { move_point(doc, kProfile, 3, moves[0].to); }));
  EXPECT_EQ(doc, before);
}

}  // namespace
}  // namespace sweep::editor
