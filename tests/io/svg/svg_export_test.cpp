// SVG export of the planar curves (svg/export.hpp, svg/writer.hpp), read back with tinyxml2 and a
// parser of the path data the writer emits (M, C, L, Z): the exact control points with y negated,
// every piece the geometry's, circles, closed paths, what is left out, the box, and nothing
// written when there is nothing to write.
#include "io/svg/export.hpp"

#include "base/number_text.hpp"
#include "geometry/curves/bezier.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>
#include <tinyxml2.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace sweep {
namespace {

using test::ScratchFolder;

// Planar curves of every kind (awkward decimals, so the numbers must round-trip), a closed
// Bezier, a closed kb2 with corners, an anonymous curve, then what SVG leaves out: a 3D curve, a
// helix and a surface.
constexpr const char* kText =
    "bez2 wave 8 7\n[0.1 0.2] [1 2.3] [3 2.5] [4.7 -1e-7] [6 0] [7 3.3333333333333335] [9 123456.789]\n"
    "bez2 loop 8 7\n[1 0] [1 1] [-1 1] [-1 0] [-1 -1] [1 -1] [1 0]\n"
    "bsp2 spline 8 6\n[-1 1] [-1.2 0.5] [-0.8 0] [-1 -0.5] [-1 -1] [-0.5 -1.2]\n"
    "cr2 through 8 5 tension 0.2\n[0 0] [1 0.7] [2.5 0.1] [3 -2] [4 -1]\n"
    "kb2 star 8 6 tension 0.1 continuity 0.5 bias -0.2\n[2 0] [0.3 0.4] [0 2] [-2 0] [0 -2] [2 0]\n"
    "poly2 zig 4\n[0 0] [1 1] [2 -0.5] [3.25 1]\n"
    "circ ring 16 1.5\n"
    "poly2 . 2\n[0.5 0.5] [-0.5 -0.5]\n"
    "bez3 lifted 8 4\n[0 0 1] [1 1 1] [2 1 1] [3 0 1]\n"
    "helix coil 16 1 0.5 2\n"
    "srev vase 8 spline\n";

/// One command of the path data: its letter and its points (y as written, down).
struct Command {
  char letter;
  std::vector<glm::dvec2> points;
};

/// The exact double a number of the SVG reads as; fails the test on anything else.
double number(const std::string& text) {
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  EXPECT_TRUE(error == std::errc() && end == text.data() + text.size()) << "not a number: " << text;
  return value;
}

/// The writer's path data: letters and numbers separated by blanks.
std::vector<Command> parse_path(const std::string& d) {
  std::istringstream in(d);
  std::vector<Command> commands;
  std::string word;
  std::vector<double> numbers;
  while (in >> word) {
    if (word == "M" || word == "C" || word == "L" || word == "Z") {
      commands.push_back({word[0], {}});
      continue;
    }
    if (commands.empty()) throw std::runtime_error("path data starts with a number");
    numbers.push_back(number(word));
    if (numbers.size() == 2) {
      commands.back().points.emplace_back(numbers[0], numbers[1]);
      numbers.clear();
    }
  }
  return commands;
}

/// SWP coordinates of a point as SVG writes it.
glm::dvec2 swp(glm::dvec2 svg) {
  return {svg.x, -svg.y};
}

struct Exported {
  ScratchFolder folder{"sweep-svg"};
  Document doc = io::parse_swp(kText, "curves.swp");
  io::SvgExport written = io::export_curves_svg(doc, "curves.swp", (folder.path() / "out").string());
  tinyxml2::XMLDocument xml;
  Exported() { EXPECT_EQ(xml.LoadFile(written.path.c_str()), tinyxml2::XML_SUCCESS); }

  const tinyxml2::XMLElement* element(const std::string& id) const {
    for (const auto* e = xml.RootElement()->FirstChildElement(); e; e = e->NextSiblingElement()) {
      if (e->Attribute("id") && e->Attribute("id") == id) return e;
    }
    return nullptr;
  }
  std::vector<Command> path(const std::string& id) const {
    const auto* e = element(id);
    if (!e || !e->Attribute("d")) throw std::runtime_error("no path " + id);
    return parse_path(e->Attribute("d"));
  }
  const Object& object(const std::string& name) const { return doc.objects[static_cast<std::size_t>(doc.find(name))]; }
};

/// The pieces a path of cubics draws: each starts where the one before ends (SWP coordinates).
std::vector<std::array<glm::dvec2, 4>> written_pieces(const std::vector<Command>& path) {
  std::vector<std::array<glm::dvec2, 4>> pieces;
  glm::dvec2 at = swp(path.front().points.front());
  for (const Command& c : path) {
    if (c.letter != 'C') continue;
    pieces.push_back({at, swp(c.points[0]), swp(c.points[1]), swp(c.points[2])});
    at = pieces.back()[3];
  }
  return pieces;
}

TEST(SvgExport, WritesOnePrefixSvgWithThePlanarCurvesInDocumentOrder) {
  Exported e;
  EXPECT_EQ(e.written.path, (e.folder.path() / "out.svg").string());
  EXPECT_EQ(e.written.curves, 8u);
  EXPECT_EQ(io::written_line(e.written), "wrote " + e.written.path + " (8 curves)");
  EXPECT_EQ(e.folder.entries(), std::vector<std::string>{"out.svg"});  // no temporary left
  const tinyxml2::XMLElement* svg = e.xml.RootElement();
  EXPECT_STREQ(svg->Name(), "svg");
  EXPECT_STREQ(svg->Attribute("xmlns"), "http://www.w3.org/2000/svg");
  EXPECT_STREQ(svg->FirstChildElement("title")->GetText(), "sweep: planar curves of curves.swp");
  std::vector<std::string> shapes;
  for (const auto* c = svg->FirstChildElement(); c; c = c->NextSiblingElement()) {
    if (std::string(c->Name()) == "title") continue;
    shapes.push_back(std::string(c->Name()) + " " + (c->Attribute("id") ? c->Attribute("id") : "(no id)"));
    EXPECT_STREQ(c->Attribute("fill"), "none");
    EXPECT_STREQ(c->Attribute("stroke"), "black");
    EXPECT_EQ(c->Attribute("transform"), nullptr);
  }
  EXPECT_EQ(shapes, (std::vector<std::string>{"path wave", "path loop", "path spline", "path through", "path star",
                                              "path zig", "circle ring", "path (no id)"}));
}

TEST(SvgExport, ABezierCurvesControlPointsAreWrittenExactlyWithYNegated) {
  Exported e;
  const std::vector<Command> path = e.path("wave");
  std::vector<glm::dvec2> points;
  std::string letters;
  for (const Command& c : path) {
    letters += c.letter;
    for (const glm::dvec2 p : c.points) points.push_back(swp(p));
  }
  EXPECT_EQ(letters, "MCC");  // open: no Z
  const auto swp_points = points_of(e.object("wave"));
  ASSERT_EQ(points.size(), swp_points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(points[i].x, swp_points[i].x) << i;  // bit for bit: the numbers round-trip
    EXPECT_EQ(points[i].y, swp_points[i].y) << i;
  }
}

TEST(SvgExport, EveryPieceIsTheGeometrysAndTheCurvePassesThroughItsSamples) {
  Exported e;
  for (const std::string name : {"spline", "through", "star", "loop"}) {
    SCOPED_TRACE(name);
    const Object& curve = e.object(name);
    const std::vector<BezierPiece> expected = bezier_pieces(describe_curve(curve));
    const auto pieces = written_pieces(e.path(name));
    ASSERT_EQ(pieces.size(), expected.size());
    const double tolerance = 1e-12 * curve_extent(curve);
    for (std::size_t k = 0; k < pieces.size(); ++k) {
      for (std::size_t j = 0; j < 4; ++j) {
        EXPECT_LE(glm::distance(pieces[k][j], glm::dvec2(expected[k][j])), tolerance) << "piece " << k << " " << j;
      }
    }
    const CurveSamples samples = evaluate_curve(curve);
    for (std::size_t i = 0; i < samples.frames.size(); ++i) {
      const double u = samples.parameters[i];
      const std::size_t k = std::min(static_cast<std::size_t>(u), pieces.size() - 1);
      BezierPiece cubic;
      for (std::size_t j = 0; j < 4; ++j) cubic[j] = glm::dvec3(pieces[k][j], 0.0);
      const glm::dvec3 point = evaluate_bezier_piece(cubic, u - static_cast<double>(k)).position;
      EXPECT_LE(glm::distance(point, samples.frames[i].V), 1e-9) << "at " << u;
    }
  }
}

TEST(SvgExport, ClosedCurvesEndWithZAndOpenOnesDoNot) {
  Exported e;
  for (const std::string name : {"loop", "star"}) EXPECT_EQ(e.path(name).back().letter, 'Z') << name;
  for (const std::string name : {"wave", "spline", "through", "zig"})
    EXPECT_NE(e.path(name).back().letter, 'Z') << name;
}

TEST(SvgExport, APolylineIsLinesThroughItsPoints) {
  Exported e;
  const std::vector<Command> path = e.path("zig");
  const auto points = points_of(e.object("zig"));
  ASSERT_EQ(path.size(), points.size());
  for (std::size_t i = 0; i < path.size(); ++i) {
    EXPECT_EQ(path[i].letter, i == 0 ? 'M' : 'L');
    ASSERT_EQ(path[i].points.size(), 1u);
    EXPECT_EQ(swp(path[i].points[0]), glm::dvec2(points[i]));
  }
}

TEST(SvgExport, ACircleIsACircleAboutTheOrigin) {
  Exported e;
  const tinyxml2::XMLElement* ring = e.element("ring");
  ASSERT_NE(ring, nullptr);
  EXPECT_STREQ(ring->Name(), "circle");
  EXPECT_STREQ(ring->Attribute("cx"), "0");
  EXPECT_STREQ(ring->Attribute("cy"), "0");
  EXPECT_STREQ(ring->Attribute("r"), "1.5");
}

TEST(SvgExport, ThreeDimensionalCurvesAndSurfacesAreLeftOut) {
  Exported e;
  for (const std::string name : {"lifted", "coil", "vase"}) EXPECT_EQ(e.element(name), nullptr) << name;
  EXPECT_EQ(io::planar_outlines(io::parse_swp("bez3 a 8 4\n[0 0 1] [1 1 1] [2 1 1] [3 0 1]\ncirc b 8 1\n")).size(), 1u);
}

/// The viewBox's four numbers.
std::vector<double> view_box(const tinyxml2::XMLDocument& xml) {
  std::istringstream in(xml.RootElement()->Attribute("viewBox"));
  std::vector<double> box;
  for (std::string word; in >> word;) box.push_back(number(word));
  return box;
}

TEST(SvgExport, TheViewBoxIsTheExactBoxWithYNegatedPlusAMarginAndOneUnitIsOneMillimetre) {
  ScratchFolder folder("sweep-svg");
  const std::string prefix = (folder.path() / "c").string();
  // A circle of radius 2 beside a Bezier arch whose top (y = 3, at t = 1/2) is below its
  // control points (y = 4): the box is the curves', not the control points'.
  const Document doc = io::parse_swp("circ c 8 2\nbez2 arch 8 4\n[1 0] [1 4] [5 4] [5 0]\n", "c.swp");
  io::export_curves_svg(doc, "c.swp", prefix);
  tinyxml2::XMLDocument xml;
  ASSERT_EQ(xml.LoadFile((prefix + ".svg").c_str()), tinyxml2::XML_SUCCESS);
  const std::vector<double> box = view_box(xml);  // x -2..5, y -2..3: 7 x 5, margin 0.35
  ASSERT_EQ(box.size(), 4u);
  EXPECT_NEAR(box[0], -2.35, 1e-12);
  EXPECT_NEAR(box[1], -3.35, 1e-12);  // -(max y) - margin
  EXPECT_NEAR(box[2], 7.7, 1e-12);
  EXPECT_NEAR(box[3], 5.7, 1e-12);
  EXPECT_EQ(xml.RootElement()->Attribute("width"), number_text(box[2]) + "mm");
  EXPECT_EQ(xml.RootElement()->Attribute("height"), number_text(box[3]) + "mm");
  EXPECT_NEAR(xml.RootElement()->FirstChildElement("circle")->DoubleAttribute("stroke-width"), 7.7 / 500, 1e-12);
}

TEST(SvgExport, ADocumentWithoutPlanarCurvesWritesNothing) {
  ScratchFolder folder("sweep-svg");
  const Document doc = io::parse_swp("bez3 a 8 4\n[0 0 1] [1 1 1] [2 1 1] [3 0 1]\nhelix h 16 1 0.5 2\n", "3d.swp");
  const io::SvgExport written = io::export_curves_svg(doc, "3d.swp", (folder.path() / "out").string());
  EXPECT_EQ(written.curves, 0u);
  EXPECT_TRUE(folder.entries().empty());
  EXPECT_EQ(io::no_planar_curves_message("3d.swp"), "3d.swp has no planar curves; nothing written");
}

TEST(SvgExport, AFailedWriteNamesThePathAndLeavesNoFile) {
  ScratchFolder folder("sweep-svg");
  const std::string prefix = (folder.path() / "missing" / "out").string();
  try {
    io::export_curves_svg(io::parse_swp("circ c 8 1\n"), "c.swp", prefix);
    FAIL() << "no error";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find(prefix + ".svg"), std::string::npos) << error.what();
  }
  EXPECT_TRUE(folder.entries().empty());
}

}  // namespace
}  // namespace sweep
