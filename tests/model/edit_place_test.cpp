// Where the Create panel puts what it makes (issue 59, item 3): a new curve sized to the scene and
// beside it on the ground grid, a 2D profile only sized (its coordinates are its place in every
// surface made from it), and a tube's profile made small enough that the tube never passes
// through itself, judged by the printability check.
#include "io/swp/read.hpp"
#include "model/edit/edit.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/scene.hpp"
#include "model/print/printability.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace sweep {
namespace {

struct Box {
  glm::dvec3 lo{0.0};
  glm::dvec3 hi{0.0};
};

Box samples_box(const Object& curve) {
  const CurveSamples samples = evaluate_curve(curve);
  Box box{samples.frames.front().V, samples.frames.front().V};
  for (const Frame& f : samples.frames) {
    box.lo = glm::min(box.lo, f.V);
    box.hi = glm::max(box.hi, f.V);
  }
  return box;
}

double largest_side(const Box& b) {
  return std::max({b.hi.x - b.lo.x, b.hi.y - b.lo.y, b.hi.z - b.lo.z});
}

/// The wineglass's box, as the viewer measures it, standing on a ground at y = -2 with lines 0.5 apart.
const SceneBox kGlass{{-2.0, -2.0, -2.0}, {2.0, 4.0, 2.0}, -2.0, 0.5};

bool on_grid(double value, double step) {
  return std::abs(value / step - std::round(value / step)) < 1e-9;
}

TEST(EditPlace, ANew3DCurveStandsBesideTheSceneOnItsGroundSizedToIt) {
  for (const char* label : {"trefoil knot", "helix", "open B-spline (3D)", "Bezier (3D)", "Hermite (3D)"}) {
    Document doc;
    std::string how;
    const int index = add_curve(doc, label, "new", kGlass, how);
    const Object& curve = doc.objects[std::size_t(index)];
    const Box box = samples_box(curve);
    EXPECT_GT(box.lo.x, kGlass.hi.x) << label << ": beside the scene, not in it";
    EXPECT_NEAR(box.lo.y, kGlass.ground, 1e-9) << label << ": on the ground";
    const double size = largest_side(box);
    EXPECT_GE(size, 0.25 * 6.0) << label;  // near half the scene's largest side (6), by a nice factor
    EXPECT_LE(size, 1.0 * 6.0) << label;
    EXPECT_NEAR(0.5 * (box.lo.z + box.hi.z), 0.0, 0.5 * kGlass.step + 1e-9) << label << ": in line with the scene";
    EXPECT_NE(how.find("beside the scene"), std::string::npos) << how;
  }
}

TEST(EditPlace, ANewKnotsPlaceIsItsAtClauseOnGridLines) {
  // A scene 18 high: the template (2.8 across) grows by a nice 2, near half of it.
  const SceneBox scene{{-6.0, -6.0, -5.0}, {6.0, 12.0, 6.0}, -6.0, 1.0};
  Document doc;
  std::string how;
  const int index = add_curve(doc, "trefoil knot", "knot", scene, how);
  const auto& knot = doc.objects[std::size_t(index)].as<TorusKnotCurve>();
  EXPECT_EQ(how, " (scaled by 2, beside the scene)");
  EXPECT_EQ(knot.major_radius, 2.0);
  EXPECT_EQ(knot.radius, 0.8);
  EXPECT_TRUE(on_grid(knot.at.x, scene.step)) << knot.at.x;
  EXPECT_TRUE(on_grid(knot.at.z, scene.step)) << knot.at.z;
  EXPECT_EQ(knot.at.z, 1.0) << "the scene's middle in z, 0.5, on the nearest grid line";
}

TEST(EditPlace, ANew2DCurveIsOnlyScaledAboutItsOrigin) {
  for (const char* label : {"circle", "closed B-spline (2D)", "Hermite (2D)"}) {
    Document plain;
    add_curve(plain, label, "c");
    Document doc;
    std::string how;
    const int index = add_curve(doc, label, "c", kGlass, how);
    const Box before = samples_box(plain.objects[0]);
    const Box after = samples_box(doc.objects[std::size_t(index)]);
    const double factor = largest_side(after) / largest_side(before);
    EXPECT_GT(factor, 1.0) << label;
    EXPECT_NEAR(glm::length(after.lo - factor * before.lo), 0.0, 1e-9) << label << ": about the origin";
    EXPECT_EQ(how.find("beside"), std::string::npos) << how;
  }
}

TEST(EditPlace, AnEmptyOrOutlandishSceneLeavesTheTemplateAsItIs) {
  Document plain;
  add_curve(plain, "trefoil knot", "k");
  const SceneBox huge{{-1e11, 0.0, 0.0}, {1e11, 1.0, 1.0}, 0.0, 1e10};  // a place beside would pass 1e12
  for (const SceneBox& scene : {SceneBox{}, huge}) {
    Document placed;
    std::string how;
    add_curve(placed, "trefoil knot", "k", scene, how);
    EXPECT_EQ(how, "");
    EXPECT_EQ(placed.objects[0], plain.objects[0]);
  }
}

/// The self-intersection findings of `doc` printed 80 mm tall.
std::size_t self_intersections(const Document& doc) {
  const PrintModel model = print_model(doc, evaluate_document(doc), 80.0);
  const std::vector<PrintFinding> found = check_print(doc, model, "m.swp");
  return std::size_t(std::count_if(found.begin(), found.end(),
                                   [](const PrintFinding& f) { return f.check == PrintCheck::SelfIntersection; }));
}

TEST(EditPlace, ATubesProfileShrinksUntilTheTubeNeverPassesThroughItself) {
  Document doc;
  add_curve(doc, "trefoil knot", "trefoil");
  add_curve(doc, "circle", "circle");
  EXPECT_FALSE(is_referenced(doc, 1));
  const double fit = profile_fit_factor(doc, 1, 0);
  EXPECT_LT(fit, 1.0);
  Document as_is = doc;
  add_surface(as_is, ObjectKind::GeneralizedCylinder, "tube", 1, 0, 1);
  EXPECT_TRUE(is_referenced(as_is, 1));
  EXPECT_GT(self_intersections(as_is), 0u) << "the default circle along the default knot folds";
  scale_curve(doc.objects[1], fit);
  add_surface(doc, ObjectKind::GeneralizedCylinder, "tube", 1, 0, 1);
  EXPECT_EQ(self_intersections(doc), 0u) << "scaled by " << fit;
  EXPECT_EQ(profile_fit_factor(doc, 1, 0), 1.0) << "once fitted, it fits";
}

TEST(EditPlace, AStraightSweepTakesAnyProfile) {
  const Document doc = io::parse_swp("circ c 24 5\nbez3 line 1 4\n[0 0 0]\n[0 0 1]\n[0 0 2]\n[0 0 3]\n");
  EXPECT_EQ(profile_fit_factor(doc, 0, 1), 1.0);
}

}  // namespace
}  // namespace sweep
