// SVG import (svg/import.hpp): the hand-written drawings of tests/data/svg read as the curves
// computed by hand (an Inkscape file in mm, composed transforms, every shape), units and viewBox
// scales, ids as names, and every problem's one message.
#include "io/svg/import.hpp"

#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

namespace sweep {
namespace {

const std::filesystem::path kData = std::filesystem::path(SWEEP_TEST_DATA_DIR) / "svg";

Document drawing(const std::string& body, const std::string& root_attributes = "", double scale = 1.0) {
  return io::parse_svg_drawing(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" " + root_attributes + ">\n" + body + "\n</svg>\n", "t.svg", "shape",
      scale);
}

std::string problem(const std::string& text) {
  try {
    io::parse_svg_drawing(text, "t.svg", "shape", 1.0);
  } catch (const io::ImportError& e) {
    return e.what();
  }
  return "no error";
}

std::string problem_in(const std::string& body, const std::string& root_attributes = "") {
  return problem("<svg xmlns=\"http://www.w3.org/2000/svg\" " + root_attributes + ">\n" + body + "\n</svg>\n");
}

std::vector<glm::dvec3> points(const Document& doc, std::size_t index) {
  return doc.objects.at(index).as<PointsPart>().points;
}

std::vector<std::string> names(const Document& doc) {
  std::vector<std::string> out;
  for (const Object& o : doc.objects) out.push_back(o.name);
  return out;
}

void expect_near(const glm::dvec3& got, glm::dvec2 expected, double tolerance = 1e-12) {
  EXPECT_NEAR(got.x, expected.x, tolerance);
  EXPECT_NEAR(got.y, expected.y, tolerance);
  EXPECT_EQ(got.z, 0.0);
}

TEST(SvgImport, AnInkscapeDrawingInMillimetresReadsInMillimetres) {
  const Document doc = io::import_svg_drawing(kData / "inkscape.svg", "vase", 1.0);
  // defs, metadata, sodipodi:namedview and text give nothing.
  EXPECT_EQ(names(doc), (std::vector<std::string>{"vase", "path_12_", "rect1"}));
  for (const Object& o : doc.objects) {
    EXPECT_EQ(o.kind(), ObjectKind::Bezier2);
    EXPECT_EQ(o.as<StepsPart>().steps, 16);
  }
  // The layer's translate(-10,-20), then y negated: m 30,40 is (20, -20).
  const std::vector<glm::dvec3> vase = points(doc, 0);
  ASSERT_EQ(vase.size(), 13u);
  const glm::dvec2 corners[] = {{20, -20}, {30, -20}, {30, -40}, {30, -45}, {20, -45}, {20, -40}};
  const std::size_t at[] = {0, 3, 6, 7, 8, 9};
  for (int i = 0; i < 6; ++i) expect_near(vase[at[i]], corners[i]);
  EXPECT_EQ(vase.back(), vase.front());
  // A 10 mm line in the drawing is 10 units long.
  const std::vector<glm::dvec3> line = points(doc, 1);
  ASSERT_EQ(line.size(), 4u);
  EXPECT_NEAR(glm::length(line[3] - line[0]), 10.0, 1e-12);
  expect_near(line[0], {50, -20});
  EXPECT_EQ(points(doc, 2).size(), 25u);  // 4 sides and 4 rounded corners
  // The document reads back from its SWP text.
  EXPECT_EQ(io::parse_swp(io::write_swp(doc)).objects, doc.objects);
}

TEST(SvgImport, TransformsComposeGroupThenElement) {
  const Document doc = io::import_svg_drawing(kData / "transforms.svg", "t", 1.0);
  ASSERT_EQ(names(doc), (std::vector<std::string>{"turned", "centred", "skewed", "matrix", "listed"}));
  // (1, 0) turned by 90 degrees is (0, 1), scaled (0, 2), moved (10, 2), flipped (10, -2).
  expect_near(points(doc, 0)[0], {10, -2});
  expect_near(points(doc, 0)[3], {10, -4});
  // rotate(90, 5, 5) takes (6, 5) to (5, 6); then scale 2 and translate: (20, 12).
  expect_near(points(doc, 1)[0], {20, -12});
  expect_near(points(doc, 1)[3], {20, -10});
  expect_near(points(doc, 2)[0], {1, -1});   // skewX(45): x += y
  expect_near(points(doc, 3)[0], {9, -12});  // matrix(1 2 3 4 5 6) (1, 1)
  expect_near(points(doc, 3)[3], {5, -6});
  expect_near(points(doc, 4)[0], {4, -5});  // translate(1,2) after scale(3)
}

TEST(SvgImport, ShapesBecomePaths) {
  const Document doc = io::import_svg_drawing(kData / "shapes.svg", "s", 1.0);
  ASSERT_EQ(names(doc), (std::vector<std::string>{"box", "rounded", "round", "oval", "stroke", "zigzag", "triangle"}));
  const std::vector<glm::dvec3> box = points(doc, 0);
  ASSERT_EQ(box.size(), 13u);
  const glm::dvec2 box_corners[] = {{1, -2}, {5, -2}, {5, -5}, {1, -5}, {1, -2}};
  for (std::size_t i = 0; i < 5; ++i) expect_near(box[3 * i], box_corners[i]);
  // rx 3 alone rounds by 3 in x and 3 in y, clamped to half the height: 2; the 4 wide side
  // leaves no straight side at the ends (no zero-length pieces): 2 sides and 4 corners.
  const std::vector<glm::dvec3> rounded = points(doc, 1);
  ASSERT_EQ(rounded.size(), 19u);
  expect_near(rounded[0], {3, 0});
  expect_near(rounded[3], {7, 0});
  expect_near(rounded[6], {10, -2});
  // The circle: 4 quarters, every joint at radius 2 from (5, -5), every sample within the arc
  // tolerance of it.
  const std::vector<glm::dvec3> round = points(doc, 2);
  ASSERT_EQ(round.size(), 13u);
  for (std::size_t i = 0; i < round.size(); i += 3) {
    EXPECT_NEAR(glm::length(glm::dvec2(round[i]) - glm::dvec2(5, -5)), 2.0, 1e-12);
  }
  EXPECT_EQ(round.back(), round.front());
  const std::vector<glm::dvec3> oval = points(doc, 3);
  expect_near(oval[0], {3, 0});
  expect_near(oval[3], {0, -1});
  const std::vector<glm::dvec3> stroke = points(doc, 4);
  ASSERT_EQ(stroke.size(), 4u);
  expect_near(stroke[1], {1, -2});
  EXPECT_EQ(points(doc, 5).size(), 7u);  // polyline: open
  EXPECT_NE(points(doc, 5).back(), points(doc, 5).front());
  EXPECT_EQ(points(doc, 6).size(), 10u);  // polygon: closed
  EXPECT_EQ(points(doc, 6).back(), points(doc, 6).front());
}

TEST(SvgImport, APlainPathKeepsItsNumbersExactly) {
  const Document doc = drawing("<path d=\"M 0.1 0.2 C 1.3 -2.7 1e-7 3.3333333333333335 1234.5678 9\"/>");
  const std::vector<glm::dvec3> expected = {
      {0.1, -0.2, 0}, {1.3, 2.7, 0}, {1e-7, -3.3333333333333335, 0}, {1234.5678, -9, 0}};
  EXPECT_EQ(points(doc, 0), expected);
}

/// The length of the line from (0, 0) to (10, 0) in user units, in a root with these attributes.
double ten_units(const std::string& root_attributes, double scale = 1.0) {
  const Document doc = drawing("<path d=\"M0 0 H10\"/>", root_attributes, scale);
  return glm::length(points(doc, 0).back() - points(doc, 0).front());
}

TEST(SvgImport, UnitsAndViewBoxSetTheScale) {
  EXPECT_EQ(ten_units(""), 10.0);                                        // no units: 1 per user unit
  EXPECT_EQ(ten_units("width=\"300\" height=\"200\""), 10.0);            // px, no viewBox
  EXPECT_EQ(ten_units("width=\"200px\" viewBox=\"0 0 100 50\""), 20.0);  // 2 px per user unit
  EXPECT_EQ(ten_units("viewBox=\"-5 -5 100 50\""), 10.0);                // no size: as the viewBox
  EXPECT_EQ(ten_units("width=\"100mm\" height=\"50mm\" viewBox=\"0 0 100 50\""), 10.0);
  EXPECT_EQ(ten_units("width=\"10cm\" viewBox=\"0 0 50 50\""), 20.0);  // 2 mm per user unit
  EXPECT_NEAR(ten_units("width=\"4in\" viewBox=\"0 0 96 96\""), 10.0 * 25.4 * 4.0 / 96.0, 1e-12);
  EXPECT_NEAR(ten_units("width=\"100pt\""), 10.0 * 25.4 / 96.0, 1e-12);  // mm, a user unit is 1 px
  // Different scales in x and y: the smaller (meet) unless preserveAspectRatio="none".
  EXPECT_EQ(ten_units("width=\"100mm\" height=\"100mm\" viewBox=\"0 0 50 100\""), 10.0);
  EXPECT_EQ(ten_units("width=\"100mm\" height=\"100mm\" viewBox=\"0 0 50 100\" preserveAspectRatio=\"none\""), 20.0);
  EXPECT_EQ(ten_units("width=\"100mm\" height=\"50mm\" viewBox=\"0 0 100 50\"", 2.5), 25.0);
}

TEST(SvgImport, ShapeLengthsMayCarryUnits) {
  // In a document in mm without a viewBox a user unit is 1 px: 10mm is 10 units long.
  const Document doc = drawing("<line x2=\"10mm\"/><line x2=\"1in\"/><line x2=\"72pt\"/>", "width=\"100mm\"");
  ASSERT_EQ(doc.objects.size(), 3u);
  EXPECT_NEAR(points(doc, 0)[3].x, 10.0, 1e-12);
  EXPECT_NEAR(points(doc, 1)[3].x, 25.4, 1e-12);
  EXPECT_NEAR(points(doc, 2)[3].x, 25.4, 1e-12);
}

TEST(SvgImport, IdsBecomeValidUniqueNames) {
  const Document doc = drawing(
      "<path id=\"vase\" d=\"M0 0 H1 M5 5 H6\"/><path id=\"vase\" d=\"M0 0 H1\"/><path id=\"2 cups!\" d=\"M0 0 H1\"/>"
      "<path d=\"M0 0 H1\"/><path id=\"\" d=\"M0 0 H1\"/><path id=\"shape_2\" d=\"M0 0 H1\"/>");
  EXPECT_EQ(names(doc),
            (std::vector<std::string>{"vase", "vase_2", "vase_3", "_2_cups_", "shape", "shape_2", "shape_2_2"}));
  const std::string long_id(300, 'a');
  const Document long_names = drawing("<path id=\"" + long_id + "\" d=\"M0 0 H1 M2 2 H3\"/>");
  EXPECT_EQ(long_names.objects[0].name, std::string(200, 'a'));
  EXPECT_EQ(long_names.objects[1].name, std::string(198, 'a') + "_2");
  for (const Object& o : long_names.objects) EXPECT_TRUE(is_valid_object_name(o.name));
}

TEST(SvgImport, HiddenAndUndrawnElementsAreSkipped) {
  const Document doc = drawing(
      "<defs><path d=\"M0 0 H1\"/></defs><clipPath><rect width=\"1\" height=\"1\"/></clipPath>"
      "<mask><circle r=\"1\"/></mask><symbol><path d=\"M0 0 H1\"/></symbol><path display=\"none\" d=\"M0 0 H1\"/>"
      "<g style=\"display: none\"><path d=\"M0 0 H1\"/></g><image href=\"x.png\"/><text>x</text>"
      "<path id=\"kept\" d=\"M0 0 H1\"/>");
  EXPECT_EQ(names(doc), (std::vector<std::string>{"kept"}));
}

TEST(SvgImport, EveryProblemHasItsLineAndMessage) {
  EXPECT_EQ(problem_in("<path\n d=\"M 0 0 C 1 2 x\"/>"),
            "t.svg:2: expected a number after 'C' in path data, found 'x'");
  EXPECT_EQ(problem_in("<g transform=\"rotate(x)\"/>"),
            "t.svg:2: transform: expected a number in rotate(...), found 'x'");
  EXPECT_EQ(problem_in("<path transform=\"turn(3)\" d=\"M0 0 H1\"/>"),
            "t.svg:2: expected matrix, translate, scale, rotate, skewX or skewY in transform, found 'turn'");
  EXPECT_EQ(problem_in("<path transform=\"rotate(1 2)\" d=\"M0 0 H1\"/>"),
            "t.svg:2: expected 1 or 3 numbers in rotate(...), found 2");
  EXPECT_EQ(problem_in("<path d=\"M0 0 H1\"/>\n<use href=\"#a\"/>"),
            "t.svg:3: expected a reference to an element of this file ('#id') as <use>'s href, found '#a' (no element "
            "has that id)");
  EXPECT_EQ(problem_in("<svg/>"), "t.svg:2: expected paths or shapes, found a nested <svg>");
  EXPECT_EQ(problem_in(""), "t.svg: no paths or shapes to import; nothing written");
  EXPECT_EQ(problem_in("<path d=\"M0 0\"/>"), "t.svg: no paths or shapes to import; nothing written");
  EXPECT_EQ(problem("<html/>"), "t.svg:1: expected an <svg> root element, found <html>");
  EXPECT_EQ(problem_in("", "viewBox=\"0 0 0 10\""),
            "t.svg:1: expected a viewBox of 4 numbers (x y width height, both sizes > 0), found '0 0 0 10'");
  EXPECT_EQ(problem_in("", "width=\"10em\""),
            "t.svg:1: expected a length (a number with px, mm, cm, in, pt, pc, q or no unit) > 0 or a percentage as "
            "the root's width, found '10em'");
  EXPECT_EQ(problem_in("<rect width=\"50vw\" height=\"1\"/>"),
            "t.svg:2: expected a length (a number with px, mm, cm, in, pt, pc, q or no unit) as width, found '50vw'");
  EXPECT_EQ(problem_in("<polygon points=\"0 0 1\"/>"),
            "t.svg:2: expected an even number of coordinates in points, found 3");
  EXPECT_EQ(problem_in("<circle r=\"-1\"/>"), "t.svg:2: expected radii >= 0, found a negative one");
  EXPECT_EQ(problem_in("<path d=\"M0 0 H1\" transform=\"scale(1e300)\"/>"),
            "t.svg:2: expected coordinates of at most 1e12 after the transforms and units, found "
            "(3.3333333333333335e+299, 0)");
  const std::string malformed = problem("<svg>\n<path d=\"M0 0 H1\">\n</svg>\n");
  EXPECT_EQ(malformed, "t.svg:2: expected well-formed XML, found XML_ERROR_MISMATCHED_ELEMENT (XMLElement name=path)");
  EXPECT_EQ(problem("<svg"),
            "t.svg:1: expected well-formed XML, found XML_ERROR_PARSING_ELEMENT (XMLElement name=svg)");
}

TEST(SvgImport, APathTooLongForOneCurveNamesTheCap) {
  std::string d = "M0 0";
  for (int i = 0; i < 625000; ++i) d += "h1";
  EXPECT_EQ(problem_in("<path d=\"" + d + "\"/>"),
            "t.svg:2: expected at most 10000000 samples per curve (16 steps per piece give 10000001)");
}

TEST(SvgImport, MissingFilesAndTheirMessages) {
  test::ScratchFolder folder;
  EXPECT_THROW(io::import_svg_drawing(folder.path() / "missing.svg", "a", 1.0), io::ImportError);
  try {
    io::import_svg_drawing(folder.path(), "a", 1.0);
  } catch (const io::ImportError& e) {
    EXPECT_EQ(std::string(e.what()), folder.path().string() + ": cannot open: it is a directory");
  }
}

}  // namespace
}  // namespace sweep
