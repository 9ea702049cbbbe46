// SVG import (svg/import.hpp) of what browsers draw and the import once got silently wrong:
// percentages of the viewport, transform-origin, the CSS transform in `style`, visibility,
// <switch>, an ellipse's or rounded rect's one radius, SVG elements under any prefix, a DOCTYPE's
// internal subset, shapes of no length; each working or refused with its line.
#include "io/svg/import.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

namespace sweep {
namespace {

Document drawing(const std::string& body, const std::string& root_attributes = "") {
  return io::parse_svg_drawing(
      "<svg xmlns=\"http://www.w3.org/2000/svg\" " + root_attributes + ">\n" + body + "\n</svg>\n", "t.svg", "shape",
      1.0);
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

std::vector<std::string> names(const Document& doc) {
  std::vector<std::string> out;
  for (const Object& o : doc.objects) out.push_back(o.name);
  return out;
}

const std::vector<glm::dvec3>& points(const Document& doc, std::size_t index) {
  return doc.objects.at(index).as<PointsPart>().points;
}

/// The on-curve points (every third control point) of curve `index` are `expected`.
void expect_corners(const Document& doc, std::size_t index, const std::vector<glm::dvec2>& expected,
                    double tolerance = 1e-12) {
  const std::vector<glm::dvec3>& got = points(doc, index);
  ASSERT_EQ(got.size(), 3 * expected.size() - 2) << doc.objects.at(index).name;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_NEAR(got[3 * i].x, expected[i].x, tolerance) << doc.objects.at(index).name << " corner " << i;
    EXPECT_NEAR(got[3 * i].y, expected[i].y, tolerance) << doc.objects.at(index).name << " corner " << i;
  }
}

/// Every control point of curve `index` of a circle or ellipse at `centre` is within the arc
/// tolerance of radius (rx, ry) there (on-curve ones exactly).
void expect_ellipse(const Document& doc, std::size_t index, glm::dvec2 centre, double rx, double ry) {
  const std::vector<glm::dvec3>& got = points(doc, index);
  ASSERT_EQ(got.size(), 13u) << doc.objects.at(index).name;
  for (std::size_t i = 0; i < got.size(); i += 3) {
    const glm::dvec2 d = (glm::dvec2(got[i]) - centre) / glm::dvec2(rx, ry);
    EXPECT_NEAR(std::hypot(d.x, d.y), 1.0, 1e-12) << doc.objects.at(index).name << " point " << i;
  }
}

TEST(SvgStyle, PercentagesAreOfTheViewport) {
  const Document doc = drawing(
      "<rect id=\"background\" width=\"100%\" height=\"100%\"/>\n"
      "<rect id=\"inset\" x=\"10%\" y=\"10%\" width=\"50%\" height=\"50%\" rx=\"5%\"/>\n"
      "<circle id=\"dot\" cx=\"50%\" cy=\"25%\" r=\"10%\"/><line id=\"l\" x2=\"25%\" y2=\"100%\"/>",
      "viewBox=\"0 0 200 100\"");
  expect_corners(doc, 0, {{0, 0}, {200, 0}, {200, -100}, {0, -100}, {0, 0}});
  // rx 5% of 200 is 10, and ry takes it: the rounded rect starts 10 in from its corner.
  EXPECT_NEAR(points(doc, 1)[0].x, 30.0, 1e-12);
  EXPECT_NEAR(points(doc, 1)[0].y, -10.0, 1e-12);
  EXPECT_NEAR(points(doc, 1)[3].x, 110.0, 1e-12);
  // r: 10% of sqrt((200^2 + 100^2) / 2).
  const double r = 0.1 * std::sqrt((200.0 * 200.0 + 100.0 * 100.0) / 2.0);
  expect_ellipse(doc, 2, {100, -25}, r, r);
  expect_corners(doc, 3, {{0, 0}, {50, -100}});
}

TEST(SvgStyle, PercentagesWithoutViewBoxAreOfTheRootsSizeOrRefused) {
  const Document doc = drawing("<rect width=\"100%\" height=\"50%\"/>", "width=\"288px\" height=\"100\"");
  expect_corners(doc, 0, {{0, 0}, {288, 0}, {288, -50}, {0, -50}, {0, 0}});
  EXPECT_EQ(problem_in("<rect width=\"50%\" height=\"1\"/>"),
            "t.svg:2: expected a viewBox or the root's width and height to resolve width=\"50%\", found neither");
  EXPECT_EQ(problem_in("<circle r=\"5%\"/>", "width=\"100\""),
            "t.svg:2: expected a viewBox or the root's width and height to resolve r=\"5%\", found neither");
  EXPECT_EQ(problem_in("<rect width=\"5em\" height=\"1\"/>", "viewBox=\"0 0 1 1\""),
            "t.svg:2: expected a length (a number with px, mm, cm, in, pt, pc, q or no unit) as width, found '5em'");
}

TEST(SvgStyle, TransformOriginTurnsAShapeAboutIt) {
  // A 20 x 20 square at (10, 10) turned 90 degrees about its centre (20, 20) stays where it is,
  // its corner (10, 10) going to (30, 10).
  const std::vector<glm::dvec2> turned = {{30, -10}, {30, -30}, {10, -30}, {10, -10}, {30, -10}};
  const std::string square = "<rect x=\"10\" y=\"10\" width=\"20\" height=\"20\" ";
  const Document doc = drawing(square + "transform=\"rotate(90)\" transform-origin=\"20 20\"/>\n" + square +
                                   "transform=\"rotate(90)\" style=\"transform-origin: 50% 50%\"/>\n" + square +
                                   "style=\"transform: rotate(90deg); transform-origin: center\"/>\n" + square +
                                   "transform=\"rotate(90)\" transform-origin=\"right bottom\"/>\n" + square +
                                   "transform=\"rotate(90)\" transform-origin=\"top 20px\"/>",
                               "viewBox=\"0 0 40 40\"");
  for (std::size_t i = 0; i < 3; ++i) expect_corners(doc, i, turned);
  // About (40, 40): (10, 10) is (-30, -30) from it, turned (30, -30), so (70, 10).
  EXPECT_NEAR(points(doc, 3)[0].x, 70.0, 1e-12);
  EXPECT_NEAR(points(doc, 3)[0].y, -10.0, 1e-12);
  // "top 20px": x 20, y 0: (10, 10) is (-10, 10) from it, turned (-10, -10), so (10, -10).
  EXPECT_NEAR(points(doc, 4)[0].x, 10.0, 1e-12);
  EXPECT_NEAR(points(doc, 4)[0].y, 10.0, 1e-12);
}

TEST(SvgStyle, TheStylesTransformWinsOverTheAttribute) {
  const Document doc = drawing(
      "<path transform=\"scale(100)\" style=\"fill:none; transform: translate(10px, 5px) scale(2)\" d=\"M1 1 H2\"/>\n"
      "<path style=\"transform:translateX(1in) rotate(0.25turn)\" d=\"M1 0 H2\"/>\n"
      "<path style=\"transform: skewX(45deg) ! important\" d=\"M0 1 H1\"/>\n"
      "<path style=\"transform: matrix(1, 2, 3, 4, 5, 6)\" d=\"M1 1 H2\"/><path style=\"transform: none\" d=\"M1 1 "
      "H2\"/>");
  expect_corners(doc, 0, {{12, -7}, {14, -7}});
  expect_corners(doc, 1, {{96, -1}, {96, -2}});
  expect_corners(doc, 2, {{1, -1}, {2, -1}});
  expect_corners(doc, 3, {{9, -12}, {10, -14}});
  expect_corners(doc, 4, {{1, -1}, {2, -1}});
}

TEST(SvgStyle, BadStyleTransformsAndOriginsAreRefusedWithTheirLine) {
  EXPECT_EQ(problem_in("<path style=\"transform: rotate(45)\" d=\"M0 0 H1\"/>"),
            "t.svg:2: expected an angle (deg, rad, grad or turn) in rotate(...) of the style's transform, found '45'");
  EXPECT_EQ(problem_in("<path style=\"transform: translate(10%)\" d=\"M0 0 H1\"/>"),
            "t.svg:2: expected a length (px, mm, cm, in, pt, pc or q) in translate(...) of the style's transform, "
            "found '10%'");
  EXPECT_EQ(problem_in("<path style=\"transform: rotate3d(1, 0, 0, 1deg)\" d=\"M0 0 H1\"/>"),
            "t.svg:2: expected matrix, translate, scale, rotate or skew (2D) in the style's transform, found "
            "'rotate3d'");
  EXPECT_EQ(problem_in("<path style=\"transform: scale(1, 2, 3)\" d=\"M0 0 H1\"/>"),
            "t.svg:2: expected 1 or 2 arguments in scale(...) of the style's transform, found 3");
  EXPECT_EQ(problem_in("<path style=\"transform: rotate\" d=\"M0 0 H1\"/>"),
            "t.svg:2: expected a function such as rotate(45deg) in the style's transform, found 'rotate'");
  EXPECT_EQ(problem_in("<path transform=\"rotate(9)\" transform-origin=\"middle\" d=\"M0 0 H1\"/>"),
            "t.svg:2: expected 1 to 3 keywords (left, center, right, top, bottom) or lengths in transform-origin, "
            "found 'middle'");
  EXPECT_EQ(problem_in("<path transform=\"rotate(9)\" transform-origin=\"50%\" d=\"M0 0 H1\"/>"),
            "t.svg:2: expected a viewBox or the root's width and height to resolve transform-origin '50%', found "
            "neither");
  EXPECT_EQ(problem_in("<path style=\"transform: rotate(9deg); transform-box: fill-box\" d=\"M0 0 H1\"/>"),
            "t.svg:2: expected transform-box view-box (the viewport), found 'fill-box' (the element's own box is not "
            "supported)");
}

TEST(SvgStyle, HiddenShapesAreSkippedAndAVisibleChildOfAHiddenGroupIsNot) {
  const Document doc = drawing(
      "<path visibility=\"hidden\" d=\"M0 0 H1\"/><path style=\"visibility:collapse\" d=\"M0 0 H1\"/>\n"
      "<g visibility=\"hidden\"><path d=\"M0 0 H1\"/><path id=\"shown\" visibility=\"visible\" d=\"M0 0 H1\"/></g>\n"
      "<g style=\"visibility: hidden\"><g visibility=\"inherit\"><path d=\"M0 0 H1\"/></g></g>\n"
      "<path id=\"kept\" visibility=\"hidden\" style=\"visibility: visible\" d=\"M0 0 H1\"/>");
  EXPECT_EQ(names(doc), (std::vector<std::string>{"shown", "kept"}));
}

TEST(SvgStyle, ASwitchDrawsItsFirstChildWhoseConditionsHold) {
  const Document doc = drawing(
      "<switch><title>t</title><path id=\"fr\" systemLanguage=\"fr\" d=\"M0 0 H1\"/>\n"
      "<path id=\"en\" systemLanguage=\"de, en-GB\" d=\"M0 0 H1\"/><path id=\"any\" d=\"M0 0 H1\"/></switch>\n"
      "<switch><foreignObject requiredExtensions=\"http://ns.adobe.com/AdobeIllustrator/10.0/\"/>\n"
      "<g><path id=\"drawing\" d=\"M0 0 H1\"/></g><path id=\"fallback\" d=\"M0 0 H1\"/></switch>\n"
      "<switch><text>only text</text><path id=\"after_text\" d=\"M0 0 H1\"/></switch>\n"
      "<path id=\"no_extension\" requiredExtensions=\"\" d=\"M0 0 H1\"/>");
  EXPECT_EQ(names(doc), (std::vector<std::string>{"en", "drawing"}));
}

TEST(SvgStyle, AnEllipseOrRoundedRectWithOneRadiusUsesItForBoth) {
  const Document doc = drawing(
      "<ellipse cx=\"1\" cy=\"2\" rx=\"3\"/><ellipse ry=\"2\" rx=\"auto\"/>\n"
      "<rect width=\"10\" height=\"4\" ry=\"1\"/><rect width=\"10\" height=\"4\" rx=\"auto\" ry=\"1\"/>");
  expect_ellipse(doc, 0, {1, -2}, 3, 3);
  expect_ellipse(doc, 1, {0, 0}, 2, 2);
  for (std::size_t i = 2; i < 4; ++i) {
    ASSERT_EQ(points(doc, i).size(), 25u);  // 4 sides and 4 corners of radius 1
    EXPECT_EQ(points(doc, i)[0], glm::dvec3(1, 0, 0));
    EXPECT_NEAR(points(doc, i)[6].x, 10.0, 1e-12);
    EXPECT_NEAR(points(doc, i)[6].y, -1.0, 1e-12);
  }
  EXPECT_EQ(problem_in("<ellipse rx=\"around\"/>"),
            "t.svg:2: expected a length (a number with px, mm, cm, in, pt, pc, q or no unit) as rx, found 'around'");
}

TEST(SvgStyle, SvgElementsAreKnownByTheirNamespaceUnderAnyPrefix) {
  const Document prefixed = io::parse_svg_drawing(
      "<s:svg xmlns:s=\"http://www.w3.org/2000/svg\" xmlns:o=\"http://example.com/other\">\n"
      "<s:g><s:rect id=\"r\" width=\"1\" height=\"1\"/></s:g><o:rect id=\"other\" width=\"1\" height=\"1\"/>\n"
      "<g xmlns=\"http://example.com/other\"><rect id=\"foreign\" width=\"1\" height=\"1\"/></g></s:svg>",
      "t.svg", "shape", 1.0);
  EXPECT_EQ(names(prefixed), (std::vector<std::string>{"r"}));
  const Document mixed = drawing("<x:path xmlns:x=\"http://www.w3.org/2000/svg\" id=\"p\" d=\"M0 0 H1\"/>");
  EXPECT_EQ(names(mixed), (std::vector<std::string>{"p"}));
}

TEST(SvgStyle, ADoctypesEntitiesAreRefusedAndItsOtherDeclarationsSkipped) {
  const std::string head =
      "<?xml version=\"1.0\"?>\n<!DOCTYPE svg PUBLIC \"-//W3C//DTD SVG 1.1//EN\" "
      "\"http://www.w3.org/Graphics/SVG/1.1/DTD/svg11.dtd\" [\n";
  const std::string svg = "]>\n<svg xmlns=\"http://www.w3.org/2000/svg\">\n<path id=\"p\" d=\"M0 0 H1\"/></svg>\n";
  EXPECT_EQ(problem(head + "  <!ENTITY ns_svg \"http://www.w3.org/2000/svg\">\n" + svg),
            "t.svg:3: expected no <!ENTITY> declarations in the DOCTYPE (entities are not supported), found "
            "'<!ENTITY ns_svg \"http://www.w3.org/2000/svg\">'");
  const Document attlist =
      io::parse_svg_drawing(head + "  <!ATTLIST svg a CDATA \"]\">\n" + svg, "t.svg", "shape", 1.0);
  EXPECT_EQ(names(attlist), (std::vector<std::string>{"p"}));
  EXPECT_EQ(problem(head + "  <!ATTLIST svg a CDATA \"]\">\n" +
                    "]>\n<svg xmlns=\"http://www.w3.org/2000/svg\">\n\n"
                    "<path d=\"M0 0 L\"/></svg>"),
            "t.svg:7: expected a number after 'L' in path data, found the end of the path data");
}

TEST(SvgStyle, ShapesOfNoLengthAreNoCurves) {
  const Document doc = drawing(
      "<path d=\"M5 5 L5 5 M1 1 C1 1 1 1 1 1\"/><line x1=\"1\" y1=\"1\" x2=\"1\" y2=\"1\"/>\n"
      "<polygon points=\"2 2 2 2 2 2\"/><path transform=\"scale(0)\" d=\"M0 0 H1\"/><path id=\"kept\" d=\"M0 0 H1\"/>");
  EXPECT_EQ(names(doc), (std::vector<std::string>{"kept"}));
  EXPECT_EQ(problem_in("<path d=\"M5 5 L5 5\"/>"), "t.svg: no paths or shapes to import; nothing written");
}

}  // namespace
}  // namespace sweep
