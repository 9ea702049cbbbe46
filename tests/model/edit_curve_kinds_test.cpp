// Editing the new curve kinds: Catmull-Rom and Kochanek-Bartels points are inserted and deleted
// like B-spline points (a closed one stays closed), their clauses and the helix and knot numbers
// change with the reader's ranges and messages, and every template is a valid document.
#include "base/number_text.hpp"
#include "geometry/curves/adaptive.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/curve_parameters.hpp"
#include "model/edit/edit.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace sweep {
namespace {

using glm::dvec3;

constexpr const char* kText =
    "cr2 open 8 4\n[0 0]\n[1 1]\n[2 0]\n[3 1]\n"
    "cr2 loop 8 5\n[1 0]\n[0 1]\n[-1 0]\n[0 -1]\n[1 0]\n"
    "kb3 bent 8 3 continuity 0.5\n[0 0 0]\n[1 1 1]\n[2 0 0]\n"
    "helix coil 16 1 0.5 2\n"
    "knot trefoil 60 2 3 2 1\n";

/// The message of the EditError `edit` throws, and that the document did not change.
std::string refusal(Document& doc, const std::function<Change(Document&)>& edit) {
  const Document before = doc;
  try {
    edit(doc);
  } catch (const EditError& e) {
    EXPECT_EQ(doc, before) << "a refused edit changed the document";
    return e.what();
  }
  ADD_FAILURE() << "the edit was not refused";
  return {};
}

// Issue 59, item 6: the Edit panel lists a kind's numbers in the order its SWP syntax writes them
// (docs/swp-format.md: `knot NAME STEPS P Q R r`, `helix NAME STEPS RADIUS PITCH TURNS`, `cr2 NAME
// STEPS N [alpha A] [tension T]`, `kb2 ... [tension T] [continuity C] [bias B]`, `[at X Y Z]` of
// a knot or helix), then tolerance; and a written knot has them in that order too.
TEST(EditCurveKinds, EveryKindsParametersAreInTheFilesOrder) {
  using enum CurveParameter;
  const std::vector<std::pair<ObjectKind, std::vector<CurveParameter>>> expected = {
      {ObjectKind::TorusKnot, {KnotP, KnotQ, MajorRadius, Radius, AtX, AtY, AtZ, Tolerance}},
      {ObjectKind::Helix, {Radius, Pitch, Turns, AtX, AtY, AtZ, Tolerance}},
      {ObjectKind::CatmullRom2, {Alpha, Tension, Tolerance}},
      {ObjectKind::CatmullRom3, {Alpha, Tension, Tolerance}},
      {ObjectKind::KochanekBartels2, {Tension, Continuity, Bias, Tolerance}},
      {ObjectKind::Circle, {Radius, Tolerance}},
      {ObjectKind::Bezier2, {Tolerance}},
      {ObjectKind::BSpline3, {Tolerance}},
  };
  for (const auto& [kind, parameters] : expected) {
    EXPECT_EQ(parameters_in_file_order(kind), parameters) << keyword(kind);
  }
  const Document knot = io::parse_swp("knot k 240 2 3 1.5 0.25 at 4 -0.5 7\n");
  const std::string written = io::write_swp(knot);
  std::size_t at = 0;
  for (const CurveParameter parameter : parameters_in_file_order(ObjectKind::TorusKnot)) {
    if (parameter == Tolerance) continue;
    const std::string value = number_text(parameter_value(knot.objects[0], parameter));
    const std::size_t found = written.find(" " + value, at);
    ASSERT_NE(found, std::string::npos) << parameter_name(parameter) << " in " << written;
    at = found + 1;
  }
}

TEST(EditCurveKinds, PointsOfAnOpenCatmullRomAreInsertedAndDeletedDownToTwo) {
  Document doc = io::parse_swp(kText);
  insert_bspline_point(doc, 0, 4, {4, 0, 7});
  ASSERT_EQ(doc.objects[0].as<PointsPart>().points.size(), 5u);
  EXPECT_EQ(doc.objects[0].as<PointsPart>().points[4], dvec3(4, 0, 0)) << "a 2D point drops z";
  for (int k = 0; k < 3; ++k) delete_point(doc, 0, 0);
  EXPECT_EQ(doc.objects[0].as<PointsPart>().points.size(), 2u);
  EXPECT_EQ(refusal(doc, [](Document& d) { return delete_point(d, 0, 0); }),
            "a Catmull-Rom curve needs at least 2 points");
  io::validate_document(doc);
}

TEST(EditCurveKinds, AClosedCatmullRomStaysClosed) {
  Document doc = io::parse_swp(kText);
  const Object& loop = doc.objects[1];
  ASSERT_TRUE(is_closed_polygon(loop));
  EXPECT_EQ(seam_partners(loop, 0), (std::vector<int>{0, 4}));
  EXPECT_EQ(seam_partners(loop, 4), (std::vector<int>{4, 0}));
  move_point(doc, 1, 4, {2, 0, 0});
  EXPECT_EQ(loop.as<PointsPart>().points.front(), dvec3(2, 0, 0)) << "the seam partner moves along";
  insert_bspline_point(doc, 1, 5, {1, -1, 0});  // before the repeat: before the point it repeats
  EXPECT_TRUE(is_closed_polygon(doc.objects[1]));
  EXPECT_EQ(doc.objects[1].as<PointsPart>().points.size(), 6u);
  delete_point(doc, 1, 0);
  delete_point(doc, 1, 0);
  EXPECT_TRUE(is_closed_polygon(doc.objects[1]));
  EXPECT_EQ(doc.objects[1].as<PointsPart>().points.size(), 4u);
  EXPECT_EQ(refusal(doc, [](Document& d) { return delete_point(d, 1, 1); }),
            "a closed Catmull-Rom curve needs at least 3 distinct points (besides the first, repeated)");
  io::validate_document(doc);
}

TEST(EditCurveKinds, KochanekBartelsCurvesAreNotSplitLikeBezierCurves) {
  Document doc = io::parse_swp(kText);
  EXPECT_EQ(refusal(doc, [](Document& d) { return split_bezier_piece(d, 2, 0, 0.5); }),
            "curve 'bent' is a Kochanek-Bartels curve (kb3): only Bezier curves are split into pieces");
}

TEST(EditCurveKinds, ParametersChangeWithinTheReadersRanges) {
  Document doc = io::parse_swp(kText);
  set_curve_parameter(doc, 0, CurveParameter::Alpha, 1.0);
  set_curve_parameter(doc, 0, CurveParameter::Tension, 0.5);
  set_curve_parameter(doc, 2, CurveParameter::Bias, -1.0);
  set_curve_parameter(doc, 3, CurveParameter::Pitch, -2.0);
  set_curve_parameter(doc, 3, CurveParameter::Turns, 0.25);
  set_curve_parameter(doc, 4, CurveParameter::KnotQ, 5.0);
  EXPECT_EQ(doc.objects[0].as<AlphaPart>().alpha, 1.0);
  EXPECT_EQ(doc.objects[0].as<TensionPart>().tension, 0.5);
  EXPECT_EQ(doc.objects[2].as<ContinuityBiasPart>().bias, -1.0);
  EXPECT_EQ(doc.objects[3].as<HelixCurve>().pitch, -2.0);
  EXPECT_EQ(doc.objects[3].as<HelixCurve>().turns, 0.25);
  EXPECT_EQ(doc.objects[4].as<TorusKnotCurve>().knot_q, 5);
  io::validate_document(doc);
  EXPECT_EQ(parameter_value(doc.objects[4], CurveParameter::KnotQ), 5.0);
}

TEST(EditCurveKinds, ParametersOutOfRangeAreRefusedWithTheReadersMessage) {
  Document doc = io::parse_swp(kText);
  const auto set = [&](int object, CurveParameter parameter, double value) {
    return refusal(doc, [=](Document& d) { return set_curve_parameter(d, object, parameter, value); });
  };
  EXPECT_EQ(set(0, CurveParameter::Alpha, 1.5), check_alpha(1.5));
  EXPECT_EQ(set(0, CurveParameter::Tension, 1.0), "expected tension from 0 up to (not including) 1");
  EXPECT_EQ(set(2, CurveParameter::Tension, -1.5), "expected tension from -1 to 1");
  EXPECT_EQ(set(2, CurveParameter::Continuity, 2.0), "expected continuity from -1 to 1");
  EXPECT_EQ(set(3, CurveParameter::Turns, 0.0), "expected a positive number of turns");
  EXPECT_EQ(set(3, CurveParameter::Radius, -1.0), "expected a positive radius");
  EXPECT_EQ(set(4, CurveParameter::Radius, 2.0), "expected r less than R (the torus would cross its own axis)");
  EXPECT_EQ(set(4, CurveParameter::MajorRadius, 0.5), "expected r less than R (the torus would cross its own axis)");
  EXPECT_EQ(
      set(4, CurveParameter::KnotP, 3.0),
      "expected P and Q without a common factor (P = 3 and Q = 3 share 3: that is a link of 3 loops, not a knot)");
  EXPECT_EQ(set(4, CurveParameter::KnotP, 2.5), "expected P, a whole number from 1 to 1000");
  EXPECT_EQ(set(3, CurveParameter::Pitch, 2e12), "expected a number from -1e12 to 1e12 (pitch)");
  EXPECT_EQ(set(0, CurveParameter::Pitch, 1.0), "'open' (cr2) has no pitch");
  EXPECT_EQ(set(3, CurveParameter::Turns, 1e9),
            "curve 'coil': expected at most 10000000 samples per curve (STEPS 16 and TURNS 1e+09 give 16000000001)");
}

TEST(EditCurveKinds, EveryCurveTakesItsOwnToleranceAndItIsSavedBack) {
  Document doc = io::parse_swp(kText);
  for (int i = 0; i < static_cast<int>(doc.objects.size()); ++i) {
    const ObjectKind kind = doc.objects[static_cast<std::size_t>(i)].kind();
    ASSERT_EQ(has_parameter(kind, CurveParameter::Tolerance), is_curve(kind)) << i;
    if (!is_curve(kind)) continue;
    const double size = curve_extent(doc.objects[static_cast<std::size_t>(i)]);
    set_curve_parameter(doc, i, CurveParameter::Tolerance, 1e-3 * size);
    EXPECT_EQ(parameter_value(doc.objects[static_cast<std::size_t>(i)], CurveParameter::Tolerance), 1e-3 * size);
  }
  io::validate_document(doc);
  EXPECT_EQ(io::parse_swp(io::write_swp(doc)), doc);  // the clauses are written and read back
  const std::string text = io::write_swp(doc);
  EXPECT_NE(text.find(" tolerance "), std::string::npos);
  // 0 turns it off again (by STEPS), and no clause is written.
  for (int i = 0; i < static_cast<int>(doc.objects.size()); ++i) {
    if (is_curve(doc.objects[static_cast<std::size_t>(i)].kind()))
      set_curve_parameter(doc, i, CurveParameter::Tolerance, 0.0);
  }
  EXPECT_EQ(io::write_swp(doc), io::write_swp(io::parse_swp(kText)));
}

TEST(EditCurveKinds, AToleranceBelowTheFloorOrNegativeIsRefusedWithTheReadersMessage) {
  Document doc = io::parse_swp(kText);
  const double size = curve_extent(doc.objects[0]);
  EXPECT_EQ(refusal(doc, [](Document& d) { return set_curve_parameter(d, 0, CurveParameter::Tolerance, -1.0); }),
            "expected a tolerance > 0");
  EXPECT_EQ(
      refusal(doc, [=](Document& d) { return set_curve_parameter(d, 0, CurveParameter::Tolerance, 1e-9 * size); }),
      check_tolerance(1e-9 * size, size, "the curve"));
  EXPECT_NE(check_tolerance(1e-9 * size, size, "the curve")
                .find("expected a tolerance of at least 1e-06 of the curve's size"),
            std::string::npos);
}

TEST(EditCurveKinds, EveryTemplateIsAValidDocument) {
  Document doc;
  for (std::string_view shape : {"Catmull-Rom (2D)", "closed Catmull-Rom (2D)", "Catmull-Rom (3D)",
                                 "Kochanek-Bartels (2D)", "helix", "trefoil knot"}) {
    add_curve(doc, shape, unique_name(doc, "c"));
  }
  ASSERT_EQ(doc.objects.size(), 6u);
  io::validate_document(doc);
  EXPECT_TRUE(is_closed_polygon(doc.objects[1])) << "the closed Catmull-Rom template is closed";
  // The 2D templates may be profiles of surfaces; the 3D ones sweeps.
  add_surface(doc, ObjectKind::SurfaceOfRevolution, "vase", 0, -1, 12);
  add_surface(doc, ObjectKind::GeneralizedCylinder, "tube", 1, 5, 0);
  io::validate_document(doc);
  // The open 2D templates are profiles (issue 25): left of the y axis, top to bottom.
  for (const std::size_t i : {std::size_t{0}, std::size_t{3}}) {
    const auto& points = doc.objects[i].as<PointsPart>().points;
    for (const glm::dvec3& p : points) EXPECT_LT(p.x, 0.0) << doc.objects[i].name;
    EXPECT_GT(points.front().y, points.back().y) << doc.objects[i].name;
  }
}

}  // namespace
}  // namespace sweep
