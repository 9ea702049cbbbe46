// The pen (issue 61, item 1) in the real window under Xvfb (pen_gui_driver.sh): in the profile
// view five clicks and a click on the first make a closed B-spline through the clicked places, and
// three dragged presses make an open Bezier whose handles follow the drags; the saved file is read
// back. The profile view is a front view, so a window position (x, y) is the model point
// (a + s x, b - s y): the test finds a, b and s from two clicks and checks every other point.
#include "io/swp/read.hpp"
#include "support/gui_driver_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace sweep {
namespace {

namespace fs = std::filesystem;

/// The numbers of the driver's lines starting with `key`, one vector per line.
std::vector<std::vector<double>> lines_of(const std::string& out, const std::string& key) {
  std::vector<std::vector<double>> rows;
  std::istringstream lines(out);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind(key + " ", 0) != 0) continue;
    std::istringstream numbers(line.substr(key.size() + 1));
    std::vector<double> row;
    for (double v; numbers >> v;) row.push_back(v);
    rows.push_back(row);
  }
  return rows;
}

/// The last object of `kind` in `doc`.
const Object* last_of(const Document& doc, ObjectKind kind) {
  const Object* found = nullptr;
  for (const Object& o : doc.objects) {
    if (o.kind() == kind) found = &o;
  }
  return found;
}

/// The front view's map from window to model, from two points seen at two window positions.
struct WindowToModel {
  double a, b, s;
  glm::dvec2 point(double x, double y) const { return {a + s * x, b - s * y}; }
  glm::dvec2 vector(double dx, double dy) const { return {s * dx, -s * dy}; }
};

TEST(PenGui, DrawsAClosedBSplineAndABezierWithDraggedHandles) {
  if (!test::can_drive_window()) GTEST_SKIP() << "xvfb-run or xdotool is not installed";
  const fs::path dir = test::fresh_test_folder(SWEEP_TEST_OUTPUT_DIR, "pen");
  fs::copy_file(fs::path(SWEEP_SWP_DIR) / "wineglass.swp", dir / "wineglass.swp");
  const std::string out = test::run_gui_driver("", SWEEP_PEN_DRIVER, dir / "wineglass.swp", "wineglass", dir, 120);
  for (const char* part : {"ok pen on\n", "ok closed bspline\n", "ok bezier\n", "done\n"}) {
    ASSERT_NE(out.find(part), std::string::npos) << part << out;
  }
  const Document saved = io::load_swp_file(dir / "wineglass.swp");
  const Object* bspline = last_of(saved, ObjectKind::BSpline2);
  const Object* bezier = last_of(saved, ObjectKind::Bezier2);
  ASSERT_TRUE(bspline != nullptr && bezier != nullptr);
  ASSERT_NE(bspline->name, "profile") << "the wineglass's own profile is the first bsp2";
  const std::vector<glm::dvec3>& b = bspline->as<PointsPart>().points;
  const auto clicks = lines_of(out, "bsp");
  ASSERT_EQ(clicks.size(), 5u);
  ASSERT_EQ(b.size(), 8u);
  for (std::size_t i = 0; i < 3; ++i) EXPECT_EQ(b[5 + i], b[i]) << "closed: the first three repeat";

  const double s = (b[1].x - b[0].x) / (clicks[1][0] - clicks[0][0]);
  ASSERT_GT(s, 0.0);
  const WindowToModel map{b[0].x - s * clicks[0][0], b[0].y + s * clicks[0][1], s};
  const double tolerance = 1.5 * s;  // a window unit and a half: where the click's pixel lands
  for (std::size_t i = 0; i < 5; ++i) {
    const glm::dvec2 expected = map.point(clicks[i][0], clicks[i][1]);
    EXPECT_NEAR(b[i].x, expected.x, tolerance) << "node " << i;
    EXPECT_NEAR(b[i].y, expected.y, tolerance) << "node " << i;
  }

  const std::vector<glm::dvec3>& z = bezier->as<PointsPart>().points;
  const auto drags = lines_of(out, "bez");
  ASSERT_EQ(drags.size(), 3u);
  ASSERT_EQ(z.size(), 7u);
  for (std::size_t i = 0; i < 3; ++i) {
    const glm::dvec2 joint = map.point(drags[i][0], drags[i][1]);
    EXPECT_NEAR(z[3 * i].x, joint.x, tolerance) << "joint " << i;
    EXPECT_NEAR(z[3 * i].y, joint.y, tolerance) << "joint " << i;
  }
  // The handles follow the drags: out of the first joint, both sides of the middle one
  // (symmetric), into the last one from the other side.
  const auto expect_vector = [&](const glm::dvec3& v, const glm::dvec2& expected, const char* what) {
    EXPECT_NEAR(v.x, expected.x, 2.0 * tolerance) << what;
    EXPECT_NEAR(v.y, expected.y, 2.0 * tolerance) << what;
  };
  expect_vector(z[1] - z[0], map.vector(drags[0][2], drags[0][3]), "the first joint's handle");
  expect_vector(z[4] - z[3], map.vector(drags[1][2], drags[1][3]), "the middle joint's outgoing handle");
  EXPECT_NEAR(glm::length(z[2] + z[4] - 2.0 * z[3]), 0.0, 1e-5) << "the middle joint's handles are symmetric";
  expect_vector(z[6] - z[5], map.vector(drags[2][2], drags[2][3]), "the last joint's handle");
}

}  // namespace
}  // namespace sweep
