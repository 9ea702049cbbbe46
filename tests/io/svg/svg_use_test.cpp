// SVG <use> clones and <symbol>s (svg/import.hpp): a clone of a shape, a group, a clone and a
// symbol drawn where a browser draws it (x and y after the clone's transform, the symbol's
// viewBox fitted into the clone's size), hidden and cloned visibility, and the clones refused
// with their line: a reference cycle, a reference outside the file, a chain too deep or too big.
#include "io/svg/import.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace sweep {
namespace {

constexpr const char* kRoot = "<svg xmlns=\"http://www.w3.org/2000/svg\" xmlns:xlink=\"http://www.w3.org/1999/xlink\" ";

Document drawing(const std::string& body, const std::string& root_attributes = "") {
  return io::parse_svg_drawing(kRoot + root_attributes + ">\n" + body + "\n</svg>\n", "t.svg", "shape", 1.0);
}

std::string problem_in(const std::string& body, const std::string& root_attributes = "") {
  try {
    drawing(body, root_attributes);
  } catch (const io::ImportError& e) {
    return e.what();
  }
  return "no error";
}

std::vector<std::string> names(const Document& doc) {
  std::vector<std::string> out;
  for (const Object& o : doc.objects) out.push_back(o.name);
  return out;
}

/// The on-curve points (every third control point) of curve `index`.
std::vector<glm::dvec2> corners(const Document& doc, std::size_t index) {
  const std::vector<glm::dvec3>& points = doc.objects.at(index).as<PointsPart>().points;
  std::vector<glm::dvec2> out;
  for (std::size_t i = 0; i < points.size(); i += 3) out.emplace_back(points[i]);
  return out;
}

void expect_corners(const Document& doc, std::size_t index, const std::vector<glm::dvec2>& expected) {
  const std::vector<glm::dvec2> got = corners(doc, index);
  ASSERT_EQ(got.size(), expected.size()) << doc.objects.at(index).name;
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_NEAR(got[i].x, expected[i].x, 1e-12) << doc.objects.at(index).name << " corner " << i;
    EXPECT_NEAR(got[i].y, expected[i].y, 1e-12) << doc.objects.at(index).name << " corner " << i;
  }
}

TEST(SvgUse, AShapeIsClonedAtItsXAndYAfterTheClonesTransform) {
  const Document doc = drawing(
      "<defs><rect id=\"tile\" width=\"2\" height=\"1\"/></defs>\n"
      "<use href=\"#tile\" x=\"10\" y=\"5\"/>\n"
      "<use xlink:href=\"#tile\" x=\"1\" transform=\"scale(3)\"/>");
  ASSERT_EQ(names(doc), (std::vector<std::string>{"tile", "tile_2"}));
  expect_corners(doc, 0, {{10, -5}, {12, -5}, {12, -6}, {10, -6}, {10, -5}});
  // scale(3) after translate(1, 0): the tile from (3, 0) to (9, -3).
  expect_corners(doc, 1, {{3, 0}, {9, 0}, {9, -3}, {3, -3}, {3, 0}});
}

TEST(SvgUse, AGroupAndAClonesCloneAreDrawnWithTheirOwnTransforms) {
  const Document doc = drawing(
      "<g id=\"pair\" transform=\"translate(1 0)\"><path id=\"a\" d=\"M0 0 H1\"/><path id=\"b\" d=\"M0 1 H1\"/></g>\n"
      "<use id=\"copy\" href=\"#pair\" y=\"10\"/>\n"
      "<use href=\"#copy\" x=\"100\"/>");
  ASSERT_EQ(names(doc), (std::vector<std::string>{"a", "b", "a_2", "b_2", "a_3", "b_3"}));
  expect_corners(doc, 0, {{1, 0}, {2, 0}});
  expect_corners(doc, 2, {{1, -10}, {2, -10}});
  expect_corners(doc, 3, {{1, -11}, {2, -11}});
  expect_corners(doc, 5, {{101, -11}, {102, -11}});
}

TEST(SvgUse, ASymbolsViewBoxIsFittedIntoTheClonesSize) {
  // viewBox 10 x 10 into 40 x 20: meet scales by 2 and centres in x (10 to spare on each side).
  const std::string symbol =
      "<symbol id=\"s\" viewBox=\"0 0 10 10\"%><path id=\"tri\" d=\"M5 0 L10 10 L0 10 Z\"/></symbol>\n";
  const auto with = [&](const std::string& aspect) {
    std::string body = symbol;
    const std::size_t mark = body.find('%');
    body = body.substr(0, mark) + aspect + body.substr(mark + 1);
    return drawing(body + "<use href=\"#s\" x=\"150\" y=\"10\" width=\"40\" height=\"20\"/>");
  };
  expect_corners(with(""), 0, {{170, -10}, {180, -30}, {160, -30}, {170, -10}});
  expect_corners(with(" preserveAspectRatio=\"xMinYMin meet\""), 0, {{160, -10}, {170, -30}, {150, -30}, {160, -10}});
  expect_corners(with(" preserveAspectRatio=\"none\""), 0, {{170, -10}, {190, -30}, {150, -30}, {170, -10}});
  // slice scales by 4 and centres in y: 40 x 40, 10 above and below cut off (not clipped here).
  expect_corners(with(" preserveAspectRatio=\"xMidYMid slice\""), 0, {{170, 0}, {190, -40}, {150, -40}, {170, 0}});
}

TEST(SvgUse, ASymbolWithoutSizeTakesTheWholeViewportAndWithoutViewBoxIsMoved) {
  const Document doc = drawing(
      "<symbol id=\"s\" viewBox=\"0 0 1 1\"><path d=\"M0 0 H1\"/></symbol><use href=\"#s\"/>\n"
      "<symbol id=\"plain\"><path id=\"p\" d=\"M0 0 H1\"/></symbol><use href=\"#plain\" x=\"5\" y=\"6\"/>",
      "viewBox=\"0 0 50 20\"");
  // 1 x 1 into 50 x 20: scale 20, centred in x (15 to spare on each side).
  expect_corners(doc, 0, {{15, 0}, {35, 0}});
  expect_corners(doc, 1, {{5, -6}, {6, -6}});
}

TEST(SvgUse, VisibilityAndDisplayOfClonesAndOfWhatTheyReference) {
  const Document doc = drawing(
      "<defs><path id=\"p\" d=\"M0 0 H1\"/><path id=\"gone\" display=\"none\" d=\"M0 0 H1\"/></defs>\n"
      "<use href=\"#p\" visibility=\"hidden\"/><use href=\"#gone\"/><use href=\"#p\" display=\"none\"/>\n"
      "<g visibility=\"hidden\"><use href=\"#p\" style=\"visibility: visible\" x=\"7\"/></g>");
  ASSERT_EQ(names(doc), (std::vector<std::string>{"p"}));
  expect_corners(doc, 0, {{7, 0}, {8, 0}});
}

TEST(SvgUse, ReferencesOutsideTheFileAndCyclesAreRefusedWithTheirLine) {
  const std::string expected = "expected a reference to an element of this file ('#id') as <use>'s href, found ";
  EXPECT_EQ(problem_in("<path d=\"M0 0 H1\"/>\n<use href=\"other.svg#a\"/>"), "t.svg:3: " + expected + "'other.svg#a'");
  EXPECT_EQ(problem_in("<use xlink:href=\"#nothing\"/>"),
            "t.svg:2: " + expected + "'#nothing' (no element has that id)");
  EXPECT_EQ(problem_in("<use x=\"1\"/>"), "t.svg:2: " + expected + "none");
  EXPECT_EQ(problem_in("<g id=\"a\">\n<use href=\"#a\"/></g>"),
            "t.svg:3: expected a <use> outside what it references, found '#a' (a reference cycle)");
  EXPECT_EQ(problem_in("<use id=\"u\" href=\"#u\"/>"),
            "t.svg:2: expected a <use> outside what it references, found '#u' (a reference cycle)");
  EXPECT_EQ(problem_in("<use id=\"a\" href=\"#b\"/>\n<use id=\"b\" href=\"#a\"/>"),
            "t.svg:2: expected a <use> outside what it references, found '#b' (a reference cycle)");
}

TEST(SvgUse, ClonesOfClonesTooDeepOrTooManyAreRefused) {
  std::string chain = "<path id=\"u0\" d=\"M0 0 H1\"/>";
  for (int i = 1; i <= 70; ++i) {
    chain += "<use id=\"u" + std::to_string(i) + "\" href=\"#u" + std::to_string(i - 1) + "\"/>";
  }
  EXPECT_EQ(problem_in(chain), "t.svg:2: expected clones of clones at most 64 deep, found deeper");
  // Ten clones of ten clones of ... of an empty group: 10^7 elements from a few hundred bytes.
  std::string defs = "<defs><g id=\"l0\"/>";
  for (int level = 1; level <= 7; ++level) {
    defs += "<g id=\"l" + std::to_string(level) + "\">";
    for (int i = 0; i < 10; ++i) defs += "<use href=\"#l" + std::to_string(level - 1) + "\"/>";
    defs += "</g>";
  }
  EXPECT_EQ(problem_in(defs + "</defs>\n<use href=\"#l7\"/>"),
            "t.svg:2: expected at most 1000000 elements drawn through <use> clones, found more");
}

}  // namespace
}  // namespace sweep
