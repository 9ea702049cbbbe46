// Each kind's point layout (model/kinds/point_layout.hpp) against the reader's count rule and its own
// templates: the editor's rules and the reader's cannot disagree, and no edit commits a count
// the reader refuses.
#include "model/edit/edit.hpp"
#include "model/edit/edit_support.hpp"
#include "model/edit/shown_points.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using sweep::Document;
using sweep::EditUnit;
using sweep::KindInfo;
using sweep::Object;
using sweep::PointLayout;

}  // namespace

TEST(PointLayout, TheLeastCountsTheEditorKeepsAreTheReadersLeast) {
  for (const KindInfo& kind : sweep::kinds()) {
    const PointLayout& layout = kind.points;
    if (layout.unit != EditUnit::Point && layout.unit != EditUnit::PointAndTangent) continue;
    Object curve(kind.kind);
    const auto count_problem = [&](std::size_t count) {
      curve.as<sweep::PointsPart>().points.assign(count, glm::dvec3(0.0));
      return sweep::count_problem(curve);
    };
    EXPECT_EQ(count_problem(layout.least_open * layout.stride), "") << kind.keyword;
    EXPECT_NE(count_problem((layout.least_open - 1) * layout.stride), "") << kind.keyword;
    EXPECT_EQ(layout.seam_repeats % layout.stride, 0) << kind.keyword << ": a seam repeats whole groups";
  }
}

TEST(PointLayout, EveryTemplateHasACountItsReaderTakesAndShowsEveryEntry) {
  ASSERT_GE(sweep::curve_templates().size(), 13u);
  for (const sweep::CurveTemplateInfo& row : sweep::curve_templates()) {
    const Object curve = row.make();
    EXPECT_EQ(curve.kind(), row.kind) << row.label;
    EXPECT_EQ(sweep::count_problem(curve), "") << row.label;
    EXPECT_EQ(sweep::shown_points(curve).size(), sweep::points_of(curve).size()) << row.label;
  }
}

TEST(PointLayout, NoEditCommitsACountTheReaderRefuses) {
  Document doc = sweep::io::parse_swp("bez2 c 4 4 [0 0] [1 0] [1 1] [0 1]\n", "c.swp");
  Object five = doc.objects[0];
  five.as<sweep::PointsPart>().points.push_back(glm::dvec3(2, 2, 0));
  EXPECT_EQ(sweep::test::edit_error(doc, [&] { sweep::edit_support::commit(doc, 0, std::move(five)); }),
            "curve 'c': expected a Bezier control point count of the form 3n+1 (4, 7, 10, ...)");
  EXPECT_EQ(doc.objects[0].as<sweep::PointsPart>().points.size(), 4u);
}
