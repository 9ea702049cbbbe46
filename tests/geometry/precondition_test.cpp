// Checked preconditions (base/precondition.hpp): with SWEEP_CHECK_PRECONDITIONS a public
// function called outside its stated preconditions aborts with "sweep: precondition failed: TEXT
// (CONDITION) in FUNCTION at FILE:LINE" instead of reading out of bounds or dividing by zero;
// without it the checks compile to nothing and never evaluate their condition.
#include "base/precondition.hpp"

#include "geometry/curves/adaptive.hpp"
#include "geometry/curves/curve.hpp"
#include "geometry/curves/helix.hpp"
#include "geometry/curves/torus_knot.hpp"
#include "geometry/mesh/weld.hpp"
#include "geometry/subdivision/subdivision.hpp"
#include "geometry/surfaces/end_caps.hpp"
#include "geometry/surfaces/patch.hpp"
#include "geometry/surfaces/surface.hpp"
#include "geometry/unit_vector.hpp"

#include <gtest/gtest.h>

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace {

using sweep::CurveSamples;

#if SWEEP_CHECK_PRECONDITIONS
constexpr bool kChecked = true;
#else
constexpr bool kChecked = false;
#endif

/// Death tests fork; "threadsafe" re-executes the test binary instead, which also works under
/// AddressSanitizer and with the threads GoogleTest or OpenSubdiv may have started.
class PreconditionDeathTest : public ::testing::Test {
 protected:
  void SetUp() override {
#if SWEEP_CHECK_PRECONDITIONS
    GTEST_FLAG_SET(death_test_style, "threadsafe");
#else
    GTEST_SKIP() << "built without SWEEP_CHECK_PRECONDITIONS (CMake option SWEEP_PRECONDITIONS=OFF)";
#endif
  }
};

std::vector<glm::dvec3> points(std::size_t count) {
  std::vector<glm::dvec3> out;
  for (std::size_t i = 0; i < count; ++i) out.emplace_back(static_cast<double>(i), static_cast<double>(i % 2), 0.0);
  return out;
}

/// A cube cage, faces counterclockwise seen from outside.
sweep::Cage cube() {
  sweep::Cage c;
  c.points = {{-1, -1, -1}, {1, -1, -1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, 1}, {-1, 1, 1}};
  c.face_sizes = {4, 4, 4, 4, 4, 4};
  c.face_vertices = {0, 3, 2, 1, 4, 5, 6, 7, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
  return c;
}

void needs_positive(int x) {
  SWEEP_EXPECTS(x > 0, "x > 0");
}

TEST(Precondition, EvaluatesItsConditionOnlyWhenChecked) {
  int evaluated = 0;
  SWEEP_EXPECTS(++evaluated > 0, "counts");
  EXPECT_EQ(evaluated, kChecked ? 1 : 0);
  needs_positive(1);  // a check that holds does nothing
}

TEST(Precondition, ValidInputPasses) {
  EXPECT_EQ(sweep::evaluate_bezier(points(7), 4, true).frames.size(), 9u);
  EXPECT_EQ(sweep::evaluate_bspline(points(4), 4, true).frames.size(), 5u);
  EXPECT_EQ(sweep::evaluate_circle(1.0, 8).frames.size(), 9u);
  EXPECT_EQ(sweep::subdivide(cube(), {1, sweep::SubdivisionScheme::CatmullClark, false}).counts.faces, 24);
}

TEST_F(PreconditionDeathTest, MessageNamesTextConditionFunctionAndPlace) {
  EXPECT_DEATH(needs_positive(0),
               "^sweep: precondition failed: x > 0 \\(x > 0\\) in needs_positive at .*precondition_test\\.cpp:[0-9]+");
}

TEST_F(PreconditionDeathTest, BezierNeeds3nPlus1Points) {
  EXPECT_DEATH(sweep::evaluate_bezier({}, 4, true), "points\\.size\\(\\) = 3n\\+1 with n >= 1 .* in evaluate_bezier");
  EXPECT_DEATH(sweep::evaluate_bezier(points(5), 4, true), "points\\.size\\(\\) = 3n\\+1 .* in evaluate_bezier");
  EXPECT_DEATH(sweep::evaluate_bezier(points(4), 0, true), "precondition failed: steps >= 1 .* in evaluate_bezier");
}

TEST_F(PreconditionDeathTest, BSplineNeedsFourPoints) {
  EXPECT_DEATH(sweep::evaluate_bspline(points(3), 4, false), "points\\.size\\(\\) >= 4 .* in evaluate_bspline");
}

TEST_F(PreconditionDeathTest, InterpolatingSplinesCheckTheirShape) {
  EXPECT_DEATH(sweep::evaluate_catmull_rom(points(1), 4, 0.5, 0.0, true), "points\\.size\\(\\) >= 2");
  EXPECT_DEATH(sweep::evaluate_catmull_rom(points(3), 4, 0.5, 1.0, true), "tension in \\[0, 1\\)");
  EXPECT_DEATH(sweep::evaluate_kochanek_bartels(points(3), 4, {0.0, 2.0, 0.0}, true),
               "tension, continuity and bias in \\[-1, 1\\] .* in evaluate_kochanek_bartels");
}

TEST_F(PreconditionDeathTest, AnalyticCurvesCheckTheirParameters) {
  EXPECT_DEATH(sweep::evaluate_circle(1.0, 0), "precondition failed: steps >= 1 .* in evaluate_circle");
  EXPECT_DEATH(sweep::evaluate_circle(-1.0, 8), "precondition failed: radius >= 0 .* in evaluate_circle");
  EXPECT_DEATH(sweep::evaluate_helix(1.0, 1.0, 0.0, 8), "precondition failed: turns > 0 .* in evaluate_helix");
  EXPECT_DEATH(sweep::evaluate_torus_knot({2, 3, 1.0, 1.0}, 64), "0 < r < R <= limits::kMaxCoordinate");
}

TEST_F(PreconditionDeathTest, SurfaceOfRevolutionNeedsTwoProfileSamples) {
  CurveSamples profile;
  profile.planar = true;
  profile.frames.resize(1);
  EXPECT_DEATH(sweep::build_surface_of_revolution(profile, 8), "profile has >= 2 samples");
  EXPECT_DEATH(sweep::build_surface_of_revolution(sweep::evaluate_circle(1.0, 8), 0),
               "precondition failed: steps >= 1 .* in build_surface_of_revolution");
}

TEST_F(PreconditionDeathTest, PatchesCheckTheirNet) {
  EXPECT_DEATH(sweep::build_bezier_patches(points(15), 4), "size a multiple of 16 .* in build_bezier_patches");
  EXPECT_DEATH(sweep::build_bspline_patch(points(12), 3, 4, 4), "rows, columns >= 4 .* in build_bspline_patch");
  EXPECT_DEATH(sweep::build_bspline_patch(points(15), 4, 4, 4), "rows x columns points .* in build_bspline_patch");
}

TEST_F(PreconditionDeathTest, SubdivisionChecksLevelsSchemeAndIndices) {
  EXPECT_DEATH(
      sweep::subdivide(cube(), {sweep::kMaxSubdivisionLevel + 1, sweep::SubdivisionScheme::CatmullClark, false}),
      "levels in \\[0, kMaxSubdivisionLevel\\] .* in subdivide");
  EXPECT_DEATH(sweep::subdivide(cube(), {1, sweep::SubdivisionScheme::Loop, false}),
               "Loop needs triangles only .* in subdivide");
  sweep::Cage broken = cube();
  broken.face_vertices[5] = 8;
  EXPECT_DEATH(sweep::subdivide(broken, {1, sweep::SubdivisionScheme::CatmullClark, false}),
               "check_cage passes: indices in range");
}

TEST_F(PreconditionDeathTest, MeshHelpersCheckTheirInput) {
  const std::vector<glm::dvec3> p = points(4);
  EXPECT_DEATH(sweep::weld_points(p, 0.0), "precondition failed: tolerance > 0 .* in weld_points");
  sweep::Mesh tube;
  tube.positions.resize(4);
  const std::vector<glm::dvec2> segment = {{0, 0}, {1, 0}};
  EXPECT_DEATH(sweep::add_tube_caps(tube, segment, 2, {0, 0, -1}, {0, 0, 1}),
               "ring\\.size\\(\\) >= 3 .* in add_tube_caps");
  EXPECT_DEATH(sweep::bezier_part({}, 0.5, 0.5), "0 <= a < b <= 1 .* in bezier_part");
  EXPECT_DEATH(sweep::unit_vector(glm::dvec3(0.0)), "v is finite and not zero .* in unit_vector");
}

}  // namespace
