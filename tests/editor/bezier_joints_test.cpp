// Bezier joint rules (editor/bezier_joints.hpp): the starter files' joints classify as their
// points were drawn, each drag rule moves what it says (and nothing else), conversions keep or
// equalise the handles' lengths, and JointTypes keeps a user's choice until the points renumber.
#include "editor/bezier_joints.hpp"
#include "io/swp/read.hpp"
#include "model/edit/edit.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <map>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

namespace sweep::editor {

void PrintTo(JointType type, std::ostream* out) {
  *out << joint_type_label(type);
}

namespace {

using glm::dvec3;

/// Two bez2 pieces meeting at joint 3 = (2, 1): a smooth joint (handles 1 and 2 long along +x).
constexpr const char* kSmooth = "bez2 s 8 7\n[0 0]\n[0.5 1]\n[1 1]\n[2 1]\n[4 1]\n[4.5 0]\n[5 0]\n";
/// A closed bez2 of three pieces; its seam joint 0 = 9 at (0, -1) has handles 1 and 8, (+-1, -1).
constexpr const char* kClosed =
    "bez2 loop 8 10\n[0 -1]\n[1 -1]\n[2 0]\n[1 1]\n[0 1.5]\n[-1 1]\n[-2 0]\n[-1.5 -1]\n[-1 -1]\n[0 -1]\n";

Object curve_of(const char* text) {
  return io::parse_swp(text).objects.at(0);
}

const dvec3& at(const Object& curve, int point) {
  return curve.as<PointsPart>().points.at(static_cast<std::size_t>(point));
}

/// |(joint - in) x (out - joint)| relative to the lengths: 0 for collinear handles.
double turn(const dvec3& in, const dvec3& joint, const dvec3& out) {
  return glm::length(glm::cross(joint - in, out - joint)) / (glm::length(joint - in) * glm::length(out - joint));
}

/// The moves as a map point -> position (a point listed twice: its last move).
std::map<int, dvec3> moved(const std::vector<PointMove>& moves) {
  std::map<int, dvec3> result;
  for (const PointMove& m : moves) result[m.point] = m.to;
  return result;
}

TEST(BezierJoints, StarterFilesClassifyAsTheirPointsWereDrawn) {
  // Read off the files: corners.swp's square, box and inner are closed and start mid-edge, so
  // their seam's handles run along that edge, equally long (+-0.666667, +-0.1, +-0.333333): a
  // symmetric joint; every other joint of them, of bent, zigzag and of subdivision.swp's chunky is a
  // polygon's vertex with its handles on the two edges' thirds: a corner. The other starter Bezier
  // curves have one piece: no joints. bezier-vase's profile has two smooth joints (handles in
  // line, 0.8 and 0.6 long at 3; 0.7 and 0.5 at 6). vase's profile, imported from vase.svg: the
  // foot's line runs on into the first cubic (smooth, 8.33 and 8 long at 3), the belly's joint is
  // symmetric (+-2, -+23), the waist smooth, the lip's curl a corner (12) and the arc's two
  // pieces meet symmetric (15).
  const JointType c = JointType::Corner, s = JointType::Symmetric, m = JointType::Smooth;
  const std::map<std::pair<std::string, std::string>, std::map<int, JointType>> expected{
      {{"corners", "square"}, {{0, s}, {3, c}, {6, c}, {9, c}, {12, c}}},
      {{"corners", "box"}, {{0, s}, {3, c}, {6, c}, {9, c}, {12, c}}},
      {{"corners", "inner"}, {{0, s}, {3, c}, {6, c}, {9, c}, {12, c}}},
      {{"corners", "bent"}, {{3, c}, {6, c}, {9, c}, {12, c}}},
      {{"corners", "zigzag"}, {{3, c}, {6, c}, {9, c}, {12, c}}},
      {{"subdivision", "chunky"}, {{3, c}, {6, c}, {9, c}, {12, c}}},
      {{"bezier-vase", "profile"}, {{3, m}, {6, m}}},
      {{"vase", "vase_profile"}, {{3, m}, {6, s}, {9, m}, {12, c}, {15, s}}},
  };
  int checked = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(SWEEP_SWP_DIR)) {
    if (entry.path().extension() != ".swp") continue;
    const Document doc = io::load_swp_file(entry.path());
    for (const Object& o : doc.objects) {
      if (o.kind() != ObjectKind::Bezier2 && o.kind() != ObjectKind::Bezier3) continue;
      const std::string where = entry.path().stem().string() + ": " + o.name;
      const auto found = expected.find({entry.path().stem().string(), o.name});
      std::map<int, JointType> types;
      for (int joint : bezier_joints(o)) types[joint] = classify_joint(o, joint);
      const std::map<int, JointType> none;
      EXPECT_EQ(types, found == expected.end() ? none : found->second) << where;
      ++checked;
    }
  }
  EXPECT_GE(checked, 15);  // norm, taper, core (2), birail (2), corners (5), subdivision, solids, bezier-vase, vase
}

TEST(BezierJoints, JointsAndTheirHandles) {
  const Object open = curve_of(kSmooth);
  EXPECT_EQ(bezier_joints(open), std::vector<int>{3});
  EXPECT_EQ(joint_of(open, 2), 3);
  EXPECT_EQ(joint_of(open, 3), 3);
  EXPECT_EQ(joint_of(open, 4), 3);
  for (int end : {0, 1, 5, 6}) EXPECT_EQ(joint_of(open, end), -1) << end;
  const Object closed = curve_of(kClosed);
  EXPECT_EQ(bezier_joints(closed), (std::vector<int>{0, 3, 6}));
  for (int seam : {0, 1, 8, 9}) EXPECT_EQ(joint_of(closed, seam), 0) << seam;
  EXPECT_EQ(joint_of(closed, 7), 6);
  EXPECT_TRUE(bezier_joints(curve_of("bez3 one 8 4\n[0 0 0]\n[1 0 0]\n[2 1 0]\n[3 1 1]\n")).empty());
  const Object spline = curve_of("cr2 c 8 5\n[0 0]\n[1 1]\n[2 0]\n[3 1]\n[4 0]\n");
  EXPECT_TRUE(bezier_joints(spline).empty());
  EXPECT_EQ(joint_of(spline, 3), -1);
  EXPECT_EQ(joint_type_label(JointType::Smooth), "smooth");
}

TEST(BezierJoints, ClassifiesWithinSixDigitRoundingAndCallsZeroHandlesCorners) {
  EXPECT_EQ(classify_joint(curve_of(kSmooth), 3), JointType::Smooth);
  // A smooth joint along 30 degrees, written with six digits: handles 0.1 and 0.2 long.
  const char* rounded = "bez2 r 8 7\n[0 0]\n[3 0]\n[3.91340 2.95]\n[4 3]\n[4.17321 3.1]\n[7 5]\n[8 5]\n";
  EXPECT_EQ(classify_joint(curve_of(rounded), 3), JointType::Smooth);
  // Symmetric when six-digit lengths agree: thirds written as 0.333333 and 0.333334.
  const char* thirds = "bez2 t 8 7\n[0 0]\n[0 0]\n[0.666667 1]\n[1 1]\n[1.333334 1]\n[2 0]\n[2 0]\n";
  EXPECT_EQ(classify_joint(curve_of(thirds), 3), JointType::Symmetric);
  // A bend of 0.01 rad (0.57 degrees) is meant: a corner.
  const char* bend = "bez2 b 8 7\n[0 0]\n[0 0]\n[0 1]\n[1 1]\n[2 1.01]\n[3 0]\n[3 0]\n";
  EXPECT_EQ(classify_joint(curve_of(bend), 3), JointType::Corner);
  // A cusp (the out handle back along the in one) and a retracted (zero) handle: corners.
  const char* cusp = "bez2 c 8 7\n[0 0]\n[0 0]\n[0 1]\n[1 1]\n[0.5 1]\n[3 0]\n[3 0]\n";
  EXPECT_EQ(classify_joint(curve_of(cusp), 3), JointType::Corner);
  const char* zero = "bez2 z 8 7\n[0 0]\n[0 0]\n[0 1]\n[1 1]\n[1 1]\n[3 0]\n[3 0]\n";
  EXPECT_EQ(classify_joint(curve_of(zero), 3), JointType::Corner);
}

TEST(BezierJointDrag, AJointCarriesBothHandlesByItsVector) {
  const Object curve = curve_of(kSmooth);
  const dvec3 to(2.25, 1.5, 0.0);
  for (JointType type : {JointType::Corner, JointType::Smooth, JointType::Symmetric}) {
    const std::map<int, dvec3> m = moved(drag_moves(curve, 3, to, type, false));
    ASSERT_EQ(m.size(), 3u);
    EXPECT_EQ(m.at(3), to);
    EXPECT_EQ(m.at(2) - at(curve, 2), to - at(curve, 3));
    EXPECT_EQ(m.at(4) - at(curve, 4), to - at(curve, 3));
  }
}

TEST(BezierJointDrag, ASmoothHandleTurnsTheOppositeKeepingItsLength) {
  const Object curve = curve_of(kSmooth);
  for (const dvec3& to : {dvec3(1.3, 0.2, 0.0), dvec3(2.7, 3.9, 0.0), dvec3(-7.0, 1.0 + 1e-9, 0.0)}) {
    for (int handle : {2, 4}) {
      const std::vector<PointMove> moves = drag_moves(curve, handle, to, JointType::Smooth, false);
      ASSERT_EQ(moves.size(), 2u);
      EXPECT_EQ(moves[0].point, handle);
      const int opposite = handle == 2 ? 4 : 2;
      ASSERT_EQ(moves[1].point, opposite);
      const dvec3 in = handle == 2 ? to : moves[1].to, out = handle == 2 ? moves[1].to : to;
      EXPECT_LE(turn(in, at(curve, 3), out), 1e-12);
      EXPECT_GT(glm::dot(at(curve, 3) - in, out - at(curve, 3)), 0.0);  // opposite sides
      EXPECT_NEAR(glm::length(moves[1].to - at(curve, 3)), glm::length(at(curve, opposite) - at(curve, 3)), 1e-12);
    }
  }
}

TEST(BezierJointDrag, ASymmetricHandleMirrorsTheOpposite) {
  const Object curve = curve_of(kSmooth);
  const dvec3 to(1.25, 0.5, 0.0);
  const std::map<int, dvec3> m = moved(drag_moves(curve, 2, to, JointType::Symmetric, false));
  ASSERT_EQ(m.size(), 2u);
  EXPECT_EQ(m.at(4), 2.0 * at(curve, 3) - to);
}

TEST(BezierJointDrag, CornersBrokenRulesEndHandlesAndOtherKindsMoveAlone) {
  const Object curve = curve_of(kSmooth);
  const dvec3 to(1.0, 2.0, 0.0);
  EXPECT_EQ(moved(drag_moves(curve, 2, to, JointType::Corner, false)), (std::map<int, dvec3>{{2, to}}));
  for (int point : {2, 3, 4, 0, 6}) {
    EXPECT_EQ(moved(drag_moves(curve, point, to, JointType::Symmetric, true)), (std::map<int, dvec3>{{point, to}}))
        << point;
  }
  for (int handle : {1, 5}) {
    EXPECT_EQ(moved(drag_moves(curve, handle, to, JointType::Smooth, false)), (std::map<int, dvec3>{{handle, to}}));
  }
  const Object spline = curve_of("cr2 c 8 5\n[0 0]\n[1 1]\n[2 0]\n[3 1]\n[4 0]\n");
  EXPECT_EQ(moved(drag_moves(spline, 3, to, JointType::Smooth, false)), (std::map<int, dvec3>{{3, to}}));
}

TEST(BezierJointDrag, AnOpenEndCarriesItsHandle) {
  const Object curve = curve_of(kSmooth);
  const std::map<int, dvec3> first = moved(drag_moves(curve, 0, dvec3(-1.0, 0.5, 0.0), JointType::Corner, false));
  EXPECT_EQ(first, (std::map<int, dvec3>{{0, dvec3(-1.0, 0.5, 0.0)}, {1, dvec3(-0.5, 1.5, 0.0)}}));
  const std::map<int, dvec3> last = moved(drag_moves(curve, 6, dvec3(5.0, 1.0, 0.0), JointType::Corner, false));
  EXPECT_EQ(last, (std::map<int, dvec3>{{6, dvec3(5.0, 1.0, 0.0)}, {5, dvec3(4.5, 1.0, 0.0)}}));
}

TEST(BezierJointDrag, AHandleDraggedOntoItsJointLeavesTheOppositeWhereItIs) {
  const Object curve = curve_of(kSmooth);
  const std::vector<PointMove> moves = drag_moves(curve, 4, at(curve, 3), JointType::Smooth, false);
  EXPECT_EQ(moved(moves), (std::map<int, dvec3>{{4, at(curve, 3)}}));
}

TEST(BezierJointDrag, APlanarCurveStaysInThePlane) {
  const Object curve = curve_of(kSmooth);
  for (int point : {0, 2, 3, 4}) {
    for (JointType type : {JointType::Smooth, JointType::Symmetric}) {
      for (const PointMove& m : drag_moves(curve, point, dvec3(1.5, 0.25, 0.75), type, false)) {
        EXPECT_EQ(m.to.z, 0.0) << point;
      }
    }
  }
}

TEST(BezierJointDrag, TheSeamOfAClosedCurveIsAJoint) {
  Document doc = io::parse_swp(kClosed);
  const Object before = doc.objects[0];
  ASSERT_EQ(classify_joint(before, 0), JointType::Symmetric);
  // Dragging the seam point 0 moves 9 (move_points keeps it closed) and handles 1 and 8.
  const dvec3 to(0.25, -1.5, 0.0);
  move_points(doc, 0, drag_moves(before, 0, to, JointType::Symmetric, false));
  const Object& after = doc.objects[0];
  EXPECT_EQ(at(after, 0), to);
  EXPECT_EQ(at(after, 9), to);
  EXPECT_EQ(at(after, 1) - at(before, 1), to - at(before, 0));
  EXPECT_EQ(at(after, 8) - at(before, 8), to - at(before, 0));
  // Dragging seam handle 1 mirrors handle 8 about the seam; dragging 8 turns 1 (smooth).
  const dvec3 handle(1.0, -0.5, 0.0);
  const std::map<int, dvec3> mirrored = moved(drag_moves(after, 1, handle, JointType::Symmetric, false));
  EXPECT_EQ(mirrored.at(8), 2.0 * to - handle);
  const std::vector<PointMove> turned = drag_moves(after, 8, dvec3(-1.0, -2.0, 0.0), JointType::Smooth, false);
  ASSERT_EQ(turned.size(), 2u);
  EXPECT_EQ(turned[1].point, 1);
  EXPECT_LE(turn(turned[0].to, to, turned[1].to), 1e-12);
  // Dragging the repeat 9 is dragging the seam.
  EXPECT_EQ(moved(drag_moves(after, 9, to, JointType::Corner, false)).size(), 3u);
}

TEST(BezierJointConvert, ACornerMadeSmoothKeepsItsLengthsAndSymmetricEqualisesThem) {
  const Object corner = curve_of("bez3 k 8 7\n[0 0 0]\n[0 0 0]\n[0 1 0]\n[1 1 1]\n[1 3 1]\n[3 0 0]\n[3 0 0]\n");
  ASSERT_EQ(classify_joint(corner, 3), JointType::Corner);
  const double in_length = glm::length(at(corner, 3) - at(corner, 2));
  const double out_length = glm::length(at(corner, 4) - at(corner, 3));
  const std::map<int, dvec3> smooth = moved(convert_joint(corner, 3, JointType::Smooth));
  ASSERT_EQ(smooth.size(), 2u);
  EXPECT_LE(turn(smooth.at(2), at(corner, 3), smooth.at(4)), 1e-12);
  EXPECT_NEAR(glm::length(at(corner, 3) - smooth.at(2)), in_length, 1e-12);
  EXPECT_NEAR(glm::length(smooth.at(4) - at(corner, 3)), out_length, 1e-12);
  Object converted = corner;
  for (const auto& [point, to] : smooth) converted.as<PointsPart>().points[static_cast<std::size_t>(point)] = to;
  EXPECT_EQ(classify_joint(converted, 3), JointType::Smooth);

  const std::map<int, dvec3> symmetric = moved(convert_joint(corner, 3, JointType::Symmetric));
  EXPECT_LE(turn(symmetric.at(2), at(corner, 3), symmetric.at(4)), 1e-12);
  EXPECT_NEAR(glm::length(at(corner, 3) - symmetric.at(2)), 0.5 * (in_length + out_length), 1e-12);
  EXPECT_NEAR(glm::length(symmetric.at(4) - at(corner, 3)), 0.5 * (in_length + out_length), 1e-12);
  EXPECT_TRUE(convert_joint(corner, 3, JointType::Corner).empty());
}

TEST(BezierJointConvert, AZeroHandleTakesTheOtherOnesDirection) {
  const Object zero = curve_of("bez2 z 8 7\n[0 0]\n[0 0]\n[0 1]\n[1 1]\n[1 1]\n[3 0]\n[3 0]\n");
  const std::map<int, dvec3> smooth = moved(convert_joint(zero, 3, JointType::Smooth));
  EXPECT_EQ(smooth.at(4), at(zero, 3));  // its length 0 kept
  const std::map<int, dvec3> symmetric = moved(convert_joint(zero, 3, JointType::Symmetric));
  EXPECT_NEAR(glm::length(symmetric.at(4) - dvec3(1.5, 1.0, 0.0)), 0.0, 1e-15);
  const Object both = curve_of("bez2 b 8 7\n[0 0]\n[0 0]\n[1 1]\n[1 1]\n[1 1]\n[3 0]\n[3 0]\n");
  EXPECT_TRUE(convert_joint(both, 3, JointType::Smooth).empty());
}

TEST(BezierJointTypes, AChosenCornerOverridesCollinearHandlesUntilTheJointsRenumber) {
  Document doc = io::parse_swp(kSmooth);
  JointTypes types;
  const ObjectId id = 7;
  EXPECT_EQ(types.type(doc.objects[0], id, 3), JointType::Smooth);
  types.set(doc.objects[0], id, 3, JointType::Corner);
  EXPECT_EQ(types.type(doc.objects[0], id, 3), JointType::Corner);
  EXPECT_EQ(types.type(doc.objects[0], id + 1, 3), JointType::Smooth);  // another object
  split_bezier_piece(doc, 0, 1, 0.5);                                   // joints 3 and 6 now
  // The split halves handle 4 (to 1 long, as handle 2): joint 3 is what its points say again.
  EXPECT_EQ(types.type(doc.objects[0], id, 3), JointType::Symmetric);
  types.set(doc.objects[0], id, 6, JointType::Corner);
  EXPECT_EQ(types.type(doc.objects[0], id, 6), JointType::Corner);
  types.clear();
  EXPECT_EQ(types.type(doc.objects[0], id, 6), JointType::Symmetric);  // split at 0.5: equal handles
}

TEST(BezierJointTypes, AChoiceThePointsContradictIsNotShown) {
  const Object corner = curve_of("bez2 k 8 7\n[0 0]\n[0 0]\n[0 1]\n[1 1]\n[1 3]\n[3 0]\n[3 0]\n");
  JointTypes types;
  types.set(corner, 1, 3, JointType::Smooth);  // e.g. an undo brought the corner's points back
  EXPECT_EQ(types.type(corner, 1, 3), JointType::Corner);
  const Object symmetric = curve_of("bez2 s 8 7\n[0 0]\n[0 0]\n[0 1]\n[1 1]\n[2 1]\n[3 0]\n[3 0]\n");
  types.set(symmetric, 2, 3, JointType::Smooth);  // equal lengths by chance: the user wants smooth
  EXPECT_EQ(types.type(symmetric, 2, 3), JointType::Smooth);
  const Object zero = curve_of("bez2 z 8 7\n[0 0]\n[0 0]\n[0 1]\n[1 1]\n[1 1]\n[3 0]\n[3 0]\n");
  types.set(zero, 3, 3, JointType::Smooth);  // a zero handle lies on every line
  EXPECT_EQ(types.type(zero, 3, 3), JointType::Smooth);
}

}  // namespace
}  // namespace sweep::editor
