// Where on a curve the user clicked: the parameter under the pointer on the window, from the
// sample polyline and refined on the exact curve, in orthographic and perspective views; and a
// click followed by insert_point_at puts the new point there.
#include "editor/insert_at.hpp"

#include "io/swp/read.hpp"
#include "model/edit/edit_insert.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/scene.hpp"
#include "support/screen_mapping_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

namespace sweep::editor {
namespace {

constexpr const char* kText =
    "poly2 zig 4\n[-2 -1]\n[-1 1]\n[1 -1]\n[2 1]\n"
    "bez3 swoop 6 7\n[-1 0 0]\n[-1 1 0.5]\n[0 1.2 1]\n[0.5 0.5 0]\n[1 -0.2 -1]\n[1.5 -1 0]\n[2 0 0.5]\n"
    "bsp2 arc 4 6\n[-2 -1]\n[-1 1]\n[0 1.5]\n[1 1.5]\n[2 1]\n[2.5 -1]\n";

enum Index { kZig, kSwoop, kArc };

struct Fixture {
  Document doc = io::parse_swp(kText);
  Scene scene = evaluate_document(doc);
  const Object& object(int i) const { return doc.objects[std::size_t(i)]; }
  const CurveSamples& samples(int i) const { return scene.objects[std::size_t(i)].curve; }
};

TEST(InsertAt, AClickOnAPolylineGivesItsParameterExactly) {
  const Fixture f;
  for (const ScreenMapping& mapping : {test::ortho_mapping(), test::perspective_mapping()}) {
    for (const double u : {0.25, 1.5, 2.875}) {
      const auto pixel = to_screen(mapping, curve_position(f.object(kZig), u));
      ASSERT_TRUE(pixel);
      const auto found = parameter_at(f.samples(kZig), mapping, *pixel, 7.0);
      ASSERT_TRUE(found);
      EXPECT_NEAR(*found, u, 1e-9) << "perspective-correct along the segment";
    }
  }
}

TEST(InsertAt, APointerBesideTheCurveFindsTheNearestPlaceAndFarAwayNothing) {
  const Fixture f;
  const ScreenMapping mapping = test::ortho_mapping();  // 100 window units per unit
  // Beside the segment from (-1, 1) to (1, -1) (down and right on the window), 5 units off its middle.
  const glm::dvec2 pointer = *to_screen(mapping, {0.0, 0.0, 0.0}) + glm::dvec2(5.0, -5.0) / std::sqrt(2.0);
  const auto found = parameter_at(f.samples(kZig), mapping, pointer, 7.0);
  ASSERT_TRUE(found);
  EXPECT_NEAR(*found, 1.5, 1e-9);
  EXPECT_FALSE(parameter_at(f.samples(kZig), mapping, pointer, 4.0)) << "beyond the radius";
  EXPECT_FALSE(parameter_at(f.samples(kZig), mapping, {5.0, 5.0}, 7.0));
}

TEST(InsertAt, TheExactCurveRefinesTheSampledParameter) {
  const Fixture f;
  const ScreenMapping mapping = test::perspective_mapping();
  for (const double u : {0.3, 0.77, 1.41}) {  // between samples (STEPS 6)
    const auto pixel = to_screen(mapping, curve_position(f.object(kSwoop), u));
    ASSERT_TRUE(pixel);
    const auto sampled = parameter_at(f.samples(kSwoop), mapping, *pixel, 7.0);
    const auto exact = parameter_at(f.object(kSwoop), f.samples(kSwoop), mapping, *pixel, 7.0);
    ASSERT_TRUE(sampled);
    ASSERT_TRUE(exact);
    EXPECT_NEAR(*sampled, u, 0.05) << "within the sampling's error";
    EXPECT_NEAR(*exact, u, 1e-6);
  }
}

TEST(InsertAt, ADoubleClickOnABezierInsertsAJointUnderThePointerAndKeepsTheShape) {
  Fixture f;
  const ScreenMapping mapping = test::perspective_mapping();
  const double u = 1.41;
  const glm::dvec3 clicked = curve_position(f.object(kSwoop), u);
  const auto parameter = parameter_at(f.object(kSwoop), f.samples(kSwoop), mapping, *to_screen(mapping, clicked), 7.0);
  ASSERT_TRUE(parameter);
  const Object before = f.object(kSwoop);
  const int index = inserted_point_index(before, *parameter);
  EXPECT_EQ(index, 6);
  insert_point_at(f.doc, kSwoop, *parameter);
  const std::vector<glm::dvec3>& points = f.object(kSwoop).as<PointsPart>().points;
  ASSERT_EQ(points.size(), 10u);
  EXPECT_NEAR(glm::length(points[std::size_t(index)] - clicked), 0.0, 1e-5) << "the new joint is where we clicked";
  EXPECT_EQ(points.front(), before.as<PointsPart>().points.front());
  EXPECT_EQ(points.back(), before.as<PointsPart>().points.back());
}

TEST(InsertAt, ADoubleClickOnABSplineMakesItPassThroughTheClickedPlace) {
  Fixture f;
  const ScreenMapping mapping = test::ortho_mapping();
  const glm::dvec3 clicked = curve_position(f.object(kArc), 1.6);
  const auto parameter = parameter_at(f.object(kArc), f.samples(kArc), mapping, *to_screen(mapping, clicked), 7.0);
  ASSERT_TRUE(parameter);
  const int index = inserted_point_index(f.object(kArc), *parameter);
  insert_point_at(f.doc, kArc, *parameter);
  EXPECT_EQ(f.object(kArc).as<PointsPart>().points.size(), 7u);
  EXPECT_NEAR(glm::length(curve_position(f.object(kArc), double(index - 1)) - clicked), 0.0, 1e-6);
}

}  // namespace
}  // namespace sweep::editor
