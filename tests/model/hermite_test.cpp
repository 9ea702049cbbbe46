// Hermite curves (herm2, herm3): points and tangents alternating, piece k from
// p_k to p_{k+1} with derivatives t_k and t_{k+1}, so it is the Bezier p_k, p_k
// + t_k/3, p_{k+1} - t_{k+1}/3, p_{k+1}. Read, written back, evaluated,
// exported as SVG, swept and edited by their layout: a point goes and comes
// with its tangent, and a tangent is shown and dragged as a handle.
#include "geometry/mesh/mesh_topology.hpp"
#include "io/svg/export.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/edit/edit.hpp"
#include "model/edit/edit_insert.hpp"
#include "model/edit/shown_points.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/scene.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <string>
#include <vector>

namespace {

using sweep::Document;
using sweep::io::parse_swp;
using sweep::test::expect_error;
using P = glm::dvec3;

// p0 (0,0) t0 (3,0); p1 (2,1) t1 (0,3); p2 (0,2) t2 (-3,0).
const char* const kWave = "herm2 wave 8 6 [0 0] [3 0] [2 1] [0 3] [0 2] [-3 0]\n";
// A closed loop through three points: the last point and tangent repeat the
// first.
const char* const kLoop =
    "herm3 loop 10 8 [1 0 0] [0 2 0] [-1 1 1] [-1 -1 0] "
    "[-1 -1 -1] [1 -1 0] [1 0 0] [0 2 0]\n";

std::vector<P> points(const Document& doc, std::size_t i = 0) {
  return doc.objects[i].as<sweep::PointsPart>().points;
}

/// The same curve written as its Bezier form (bez2/bez3).
std::string bezier_form(const std::vector<P>& e, bool planar, int steps) {
  std::string text(planar ? "bez2" : "bez3");
  text.append(" form ").append(std::to_string(steps)).append(" ").append(std::to_string(3 * (e.size() / 2 - 1) + 1));
  const auto point = [&](const P& p) {
    text.append(" [").append(sweep::number_text(p.x)).append(" ").append(sweep::number_text(p.y));
    if (!planar) text.append(" ").append(sweep::number_text(p.z));
    text.append("]");
  };
  for (std::size_t k = 0; k + 2 < e.size(); k += 2) {
    if (k == 0) point(e[0]);
    point(e[k] + e[k + 1] / 3.0);
    point(e[k + 2] - e[k + 3] / 3.0);
    point(e[k + 2]);
  }
  text.push_back('\n');
  return text;
}

}  // namespace

TEST(Hermite, PassesThroughItsPointsWithItsTangentsAsDerivatives) {
  const Document doc = parse_swp(kWave, "wave.swp");
  const std::vector<P> e = points(doc);
  EXPECT_EQ(sweep::piece_count(sweep::ObjectKind::Hermite2, 6), 2);
  for (std::size_t k = 0; k < 3; ++k) {
    const sweep::PieceDerivatives d = sweep::curve_derivatives(doc.objects[0], double(k));
    EXPECT_LT(glm::length(d.position - e[2 * k]), 1e-12) << k;
    EXPECT_LT(glm::length(d.d1 - e[2 * k + 1]), 1e-12) << k;
  }
  const sweep::CurveSamples c = sweep::evaluate_curve(doc.objects[0]);
  ASSERT_EQ(c.frames.size(), 2u * 8u + 1u);  // STEPS per piece
  EXPECT_EQ(c.frames[8].V, e[2]);
  // C1: the piece ending at p1 arrives with the derivative the next one leaves
  // with.
  const sweep::PieceDerivatives end_of_first = sweep::curve_derivatives(doc.objects[0], 1.0 - 1e-9);
  EXPECT_LT(glm::length(end_of_first.d1 - e[3]), 1e-6);
  // 2D convention: B = +z, N = B x T.
  for (const sweep::Frame& f : c.frames) {
    EXPECT_LT(glm::length(f.B - P(0, 0, 1)), 1e-12);
    EXPECT_LT(glm::length(f.N - glm::cross(f.B, f.T)), 1e-12);
  }
}

TEST(Hermite, SamplesAsItsBezierFormDoes) {
  for (const char* text : {kWave, kLoop}) {
    const Document doc = parse_swp(text, "h.swp");
    const bool planar = sweep::is_planar_curve(doc.objects[0].kind());
    const Document form =
        parse_swp(bezier_form(points(doc), planar, doc.objects[0].as<sweep::StepsPart>().steps), "form.swp");
    const sweep::CurveSamples a = sweep::evaluate_curve(doc.objects[0]);
    const sweep::CurveSamples b = sweep::evaluate_curve(form.objects[0]);
    ASSERT_EQ(a.frames.size(), b.frames.size()) << text;
    for (std::size_t i = 0; i < a.frames.size(); ++i) {
      EXPECT_LT(glm::length(a.frames[i].V - b.frames[i].V), 1e-12) << text << i;
      EXPECT_LT(glm::length(a.frames[i].T - b.frames[i].T), 1e-9) << text << i;
    }
    EXPECT_EQ(a.closed, b.closed) << text;
  }
  EXPECT_TRUE(sweep::evaluate_curve(parse_swp(kLoop, "loop.swp").objects[0]).closed);
  EXPECT_FALSE(sweep::evaluate_curve(parse_swp(kWave, "wave.swp").objects[0]).closed);
}

TEST(Hermite, WritesBackAsItWasReadAndExportsAsSvgPieces) {
  const std::string text = "herm2 wave 8 6\n[0 0]\n[3 0]\n[2 1]\n[0 3]\n[0 2]\n[-3 0]\n\n";
  EXPECT_EQ(sweep::io::write_swp(parse_swp(text, "h.swp")), text);
  const Document loop = parse_swp(kLoop, "loop.swp");
  EXPECT_EQ(parse_swp(sweep::io::write_swp(loop), "again.swp"), loop);
  const std::vector<sweep::io::SvgOutline> outlines = sweep::io::planar_outlines(parse_swp(kWave, "wave.swp"));
  ASSERT_EQ(outlines.size(), 1u);
  const auto& path = std::get<sweep::io::SvgPath>(outlines[0].shape);
  ASSERT_EQ(path.pieces.size(), 2u);
  EXPECT_EQ(path.pieces[0][1], P(1, 0, 0));  // p0 + t0 / 3
  EXPECT_EQ(path.pieces[1][2], P(1, 2, 0));  // p2 - t2 / 3
}

TEST(Hermite, BadCountsAreLocatedInTheReadersWords) {
  const std::string rule =
      "expected an even count of at least 4 Hermite entries (points and "
      "tangents alternating: p0 t0 p1 t1 ...)";
  expect_error("herm2 h 8 5 [0 0] [1 0] [1 1] [0 1] [2 2]\n", 1, 11, rule + ", found '5'");
  expect_error("herm3 h 8 2 [0 0 0] [1 0 0]\n", 1, 11, rule + ", found '2'");
  expect_error("herm2 h 8 4 [0 0] [1 0] [1 1]\n", 2, 1, "expected '[' to start point 4 of 4, found end of file");
}

TEST(Hermite, APointIsDeletedAndInsertedWithItsTangent) {
  Document doc = parse_swp(kWave, "wave.swp");
  sweep::delete_point(doc, 0, 3);  // the tangent of p1: p1 goes with it
  EXPECT_EQ(points(doc), (std::vector<P>{P(0, 0, 0), P(3, 0, 0), P(0, 2, 0), P(-3, 0, 0)}));
  EXPECT_EQ(sweep::test::edit_error(doc, [&] { sweep::delete_point(doc, 0, 0); }),
            "a Hermite curve needs at least 2 points");
  // Inserted at a click: the curve's point there, with half its derivative (the
  // two new pieces each take part of the old one).
  const sweep::PieceDerivatives at = sweep::curve_derivatives(doc.objects[0], 0.25);
  EXPECT_EQ(sweep::inserted_point_index(doc.objects[0], 0.25), 2);
  sweep::insert_point_at(doc, 0, 0.25);
  ASSERT_EQ(points(doc).size(), 6u);
  EXPECT_LT(glm::length(points(doc)[2] - at.position), 1e-12);
  EXPECT_LT(glm::length(points(doc)[3] - at.d1 / 2.0), 1e-12);
  // Inserted by index (the Point table's "Insert after"): a tangent from its
  // neighbours.
  sweep::insert_bspline_point(doc, 0, 3, P(1, 1, 0));  // inside p1's group: before it
  ASSERT_EQ(points(doc).size(), 8u);
  EXPECT_EQ(points(doc)[2], P(1, 1, 0));
  EXPECT_EQ(points(doc)[3], (points(doc)[4] - points(doc)[0]) / 2.0);
  EXPECT_EQ(parse_swp(sweep::io::write_swp(doc), "again.swp"), doc);
}

TEST(Hermite, AClosedOneStaysClosedThroughEdits) {
  Document doc = parse_swp(kLoop, "loop.swp");
  ASSERT_TRUE(sweep::is_closed_polygon(doc.objects[0]));
  EXPECT_EQ(sweep::seam_partners(doc.objects[0], 1), (std::vector<int>{1, 7}));
  sweep::move_point(doc, 0, 1, P(0, 3, 0));
  EXPECT_EQ(points(doc)[7], P(0, 3, 0));  // the repeated tangent moves with the first
  sweep::insert_point_at(doc, 0, 2.5);
  EXPECT_EQ(points(doc).size(), 10u);
  EXPECT_TRUE(sweep::is_closed_polygon(doc.objects[0]));
  sweep::delete_point(doc, 0, 8);  // a trailing repeat: the first group goes, the seam follows
  EXPECT_EQ(points(doc).size(), 8u);
  EXPECT_TRUE(sweep::is_closed_polygon(doc.objects[0]));
  sweep::delete_point(doc, 0, 2);
  EXPECT_EQ(sweep::test::edit_error(doc, [&] { sweep::delete_point(doc, 0, 2); }),
            "a closed Hermite curve needs at least 2 distinct points (besides the "
            "first, repeated)");
}

TEST(Hermite, ATangentIsShownAndDraggedAsAHandle) {
  Document doc = parse_swp(kWave, "wave.swp");
  const std::vector<P> shown = sweep::shown_points(doc.objects[0]);
  EXPECT_EQ(shown[0], P(0, 0, 0));
  EXPECT_EQ(shown[1], P(1, 0, 0));  // p0 + t0 / 3
  EXPECT_EQ(shown[3], P(2, 2, 0));  // p1 + t1 / 3
  // The drawn polygon runs through the points, out to each handle and back: its corners are all
  // places one can drag.
  EXPECT_EQ(sweep::control_polygon(doc.objects[0]),
            (std::vector<P>{shown[0], shown[1], shown[0], shown[2], shown[3], shown[2], shown[4], shown[5], shown[4]}));
  // Dragging the handle to (1, 1) makes t0 = 3 ((1, 1) - p0); dragging p1
  // carries its handle.
  const sweep::PointMove handle{1, P(1, 1, 0)};
  sweep::move_shown_points(doc, 0, std::span(&handle, 1));
  EXPECT_EQ(points(doc)[1], P(3, 3, 0));
  const sweep::PointMove point{2, P(3, 1, 0)};
  sweep::move_shown_points(doc, 0, std::span(&point, 1));
  EXPECT_EQ(points(doc)[3], P(0, 3, 0));
  EXPECT_EQ(sweep::shown_points(doc.objects[0])[3], P(3, 2, 0));
  // Both moved at once: the tangent is taken from the point's new place,
  // whatever the order.
  const std::vector<sweep::PointMove> both{{5, P(1, 3, 0)}, {4, P(0, 3, 0)}};
  sweep::move_shown_points(doc, 0, both);
  EXPECT_EQ(points(doc)[5], P(3, 0, 0));
}

TEST(Hermite, TheCreatePanelsTemplatesAreValidProfilesAndPaths) {
  Document doc;
  sweep::add_curve(doc, "Hermite (2D)", "profile");
  sweep::add_curve(doc, "Hermite (3D)", "path");
  sweep::add_curve(doc, "circle", "ring");
  EXPECT_EQ(doc.objects[0].kind(), sweep::ObjectKind::Hermite2);
  EXPECT_EQ(doc.objects[1].kind(), sweep::ObjectKind::Hermite3);
  sweep::add_surface(doc, sweep::ObjectKind::SurfaceOfRevolution, "vase", 0, -1, 16);
  sweep::add_surface(doc, sweep::ObjectKind::GeneralizedCylinder, "tube", 2, 1, 0);
  sweep::io::validate_document(doc);
  const sweep::Scene scene = sweep::evaluate_document(doc);
  for (const std::size_t surface : {3u, 4u}) {
    EXPECT_GT(scene.objects[surface].mesh.indices.size(), 0u);
    EXPECT_EQ(sweep::mesh_topology(scene.objects[surface].mesh).non_manifold_edges, 0u);
  }
  EXPECT_EQ(parse_swp(sweep::io::write_swp(doc), "made.swp"), doc);
}
