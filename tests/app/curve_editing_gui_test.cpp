// Curve editing through the real window: under Xvfb, tests/app/curve_editing_gui_driver.sh drags
// a handle next to a smooth Bezier joint, or selects three handles with a rubber band and grabs
// them (G, move, click), then saves with Ctrl+S. The saved file must keep the joint smooth, or
// have moved exactly the three points by one vector.
#include "io/swp/read.hpp"
#include "model/document.hpp"
#include "support/gui_driver_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <filesystem>
#include <string>
#include <vector>

namespace sweep {
namespace {

namespace fs = std::filesystem;

// An open bez2 of two pieces whose joint 3 is smooth: its handles 2 and 4 lie on one line
// through it, 4 twice as far out as 2. Handle 4 is the rightmost point.
constexpr const char* kSmoothJoint =
    "bez2 wave 20 7\n[-2.000000 2.000000]\n[-1.500000 2.000000]\n[-1.000000 1.000000]\n[0.000000 0.000000]\n"
    "[2.000000 -2.000000]\n[1.500000 -2.500000]\n[0.500000 -3.000000]\n";

class CurveEditingGui : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!test::can_drive_window()) GTEST_SKIP() << "xvfb-run or xdotool is not installed";
    dir_ =
        test::fresh_test_folder(SWEEP_TEST_OUTPUT_DIR, ::testing::UnitTest::GetInstance()->current_test_info()->name());
  }

  /// Writes `text` to a file, runs the driver on it with `object` selected and `env` (NAME=value
  /// words). Returns the document saved.
  Document run_driver(const std::string& text, const std::string& object, const std::string& env) {
    const fs::path file = dir_ / "curve.swp";
    test::write_text(file, text);
    test::run_gui_driver(env, SWEEP_CURVE_EDITING_DRIVER, file, object, dir_);
    return io::load_swp_file(file);
  }

  fs::path dir_;
};

const std::vector<glm::dvec3>& points_of_first(const Document& doc) {
  return doc.objects.at(0).as<PointsPart>().points;
}

TEST_F(CurveEditingGui, DraggingAHandleOfASmoothJointTurnsTheOtherHandleToStayInLine) {
  const Document original = io::parse_swp(kSmoothJoint, "curve.swp");
  const Document saved = run_driver(kSmoothJoint, "wave", "SWEEP_DRIVER_HANDLE=4");
  const std::vector<glm::dvec3>& before = points_of_first(original);
  const std::vector<glm::dvec3>& after = points_of_first(saved);
  ASSERT_EQ(after.size(), before.size());
  EXPECT_NE(after[4], before[4]) << "the handle did not move";
  EXPECT_NE(after[2], before[2]) << "the opposite handle did not turn";
  for (int i : {0, 1, 3, 5, 6}) EXPECT_EQ(after[std::size_t(i)], before[std::size_t(i)]) << "point " << i << " moved";
  const glm::dvec3 in = after[3] - after[2];
  const glm::dvec3 out = after[4] - after[3];
  // Collinear and pointing the same way (to the precision of the six decimals the file writes).
  EXPECT_LT(glm::length(glm::cross(glm::normalize(in), glm::normalize(out))), 1e-5);
  EXPECT_GT(glm::dot(in, out), 0.0);
  EXPECT_NEAR(glm::length(in), glm::length(before[3] - before[2]), 1e-5) << "the opposite handle keeps its length";
}

TEST_F(CurveEditingGui, ThreePointsInARubberBandGrabbedTogetherMoveByOneVector) {
  const std::string text = "bsp2 row 10 6\n[-3 0]\n[-2 1]\n[-1 0]\n[0 1]\n[1 0]\n[2 1]\n";
  const Document original = io::parse_swp(text, "curve.swp");
  const Document saved = run_driver(text, "row", "SWEEP_DRIVER_BAND='2 3 4'");
  const std::vector<glm::dvec3>& before = points_of_first(original);
  const std::vector<glm::dvec3>& after = points_of_first(saved);
  ASSERT_EQ(after.size(), before.size());
  const glm::dvec3 moved = after[2] - before[2];
  EXPECT_GT(glm::length(moved), 0.1) << "the grab moved nothing";
  for (int i : {3, 4}) {
    EXPECT_LT(glm::length(after[std::size_t(i)] - before[std::size_t(i)] - moved), 1e-5)
        << "point " << i << " moved by another vector";
  }
  for (int i : {0, 1, 5}) EXPECT_EQ(after[std::size_t(i)], before[std::size_t(i)]) << "point " << i << " moved";
}

TEST_F(CurveEditingGui, ADoubleClickOnAPolylineInsertsAPointOnTheSegmentClicked) {
  const std::string text = "poly2 zig 4\n[-2 0]\n[0 2]\n[2 0]\n[4 2]\n";
  const Document original = io::parse_swp(text, "curve.swp");
  const Document saved = run_driver(text, "zig", "SWEEP_DRIVER_DOUBLE='1 2'");
  const std::vector<glm::dvec3>& before = points_of_first(original);
  const std::vector<glm::dvec3>& after = points_of_first(saved);
  ASSERT_EQ(after.size(), before.size() + 1);
  for (std::size_t i : {0u, 1u}) EXPECT_EQ(after[i], before[i]);
  for (std::size_t i : {2u, 3u}) EXPECT_EQ(after[i + 1], before[i]);
  // The new point lies on the segment from point 1 to point 2, near its middle.
  const glm::dvec3 along = glm::normalize(before[2] - before[1]);
  EXPECT_LT(glm::length(glm::cross(after[2] - before[1], along)), 1e-5);
  EXPECT_NEAR(glm::dot(after[2] - before[1], along) / glm::length(before[2] - before[1]), 0.5, 0.1);
}

}  // namespace
}  // namespace sweep
