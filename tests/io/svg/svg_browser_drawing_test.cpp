// A drawing with clones, percent sizes and shapes rotated about their centres
// (tests/data/svg/browser-drawing.svg) imports as a browser draws it: every sample of every
// imported curve lies on the outline computed here by hand, and the outline's corners are where
// the browser puts them (looked at: headless Chromium's picture of the file and rsvg-convert's
// of its import exported back as SVG show the same six outlines; rsvg-convert 2.54 itself
// ignores transform-origin and CSS transforms, so it is no reference for this file).
#include "io/svg/import.hpp"

#include "model/evaluation/curve_evaluation.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <string>
#include <vector>

namespace sweep {
namespace {

const std::filesystem::path kDrawing = std::filesystem::path(SWEEP_TEST_DATA_DIR) / "svg" / "browser-drawing.svg";

/// A point of the page (y down) in SWP (y up): the drawing has a viewBox of its size in px.
glm::dvec2 swp(glm::dvec2 page) {
  return {page.x, -page.y};
}

/// `p` turned by `degrees` about `centre` on the page (SVG's rotate: clockwise on the screen).
glm::dvec2 turned(glm::dvec2 p, glm::dvec2 centre, double degrees) {
  const double a = degrees * std::numbers::pi / 180.0;
  const glm::dvec2 d = p - centre;
  return centre + glm::dvec2(d.x * std::cos(a) - d.y * std::sin(a), d.x * std::sin(a) + d.y * std::cos(a));
}

double distance_to_segment(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const double t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
  return glm::distance(p, a + t * (b - a));
}

class BrowserDrawing : public ::testing::Test {
 protected:
  const Document doc = io::import_svg_drawing(kDrawing, "drawing", 1.0);

  const Object& curve(const std::string& name) const {
    const auto found = std::ranges::find(doc.objects, name, &Object::name);
    EXPECT_NE(found, doc.objects.end()) << name;
    return *found;
  }

  /// The curve is the closed polygon through `page_corners` (page coordinates): its on-curve
  /// points are the corners in order, and each of its samples lies on the polygon.
  void expect_polygon(const std::string& name, const std::vector<glm::dvec2>& page_corners) const {
    const Object& c = curve(name);
    const std::vector<glm::dvec3>& points = c.as<PointsPart>().points;
    ASSERT_EQ(points.size(), 3 * page_corners.size() + 1) << name;
    for (std::size_t i = 0; i <= page_corners.size(); ++i) {
      const glm::dvec2 expected = swp(page_corners[i % page_corners.size()]);
      EXPECT_NEAR(points[3 * i].x, expected.x, 1e-9) << name << " corner " << i;
      EXPECT_NEAR(points[3 * i].y, expected.y, 1e-9) << name << " corner " << i;
    }
    const CurveSamples samples = evaluate_curve(c);
    ASSERT_GT(samples.frames.size(), 4 * page_corners.size()) << name;
    for (const Frame& f : samples.frames) {
      double nearest = INFINITY;
      for (std::size_t i = 0; i < page_corners.size(); ++i) {
        const glm::dvec2 a = swp(page_corners[i]);
        const glm::dvec2 b = swp(page_corners[(i + 1) % page_corners.size()]);
        nearest = std::min(nearest, distance_to_segment(glm::dvec2(f.V), a, b));
      }
      EXPECT_LE(nearest, 1e-9) << name << " sample at " << f.V.x << ", " << f.V.y;
    }
  }
};

TEST_F(BrowserDrawing, EveryShapeAndCloneIsImportedOnce) {
  std::vector<std::string> names;
  for (const Object& o : doc.objects) names.push_back(o.name);
  // The tile and the arrow are only drawn through their clones; the clone of the tile is named
  // after the tile, the arrow after the path in its symbol.
  EXPECT_EQ(names, (std::vector<std::string>{"background", "turned", "tile", "head", "dot", "spun"}));
}

TEST_F(BrowserDrawing, ThePercentBackgroundFillsTheViewBox) {
  expect_polygon("background", {{0, 0}, {200, 0}, {200, 100}, {0, 100}});
}

TEST_F(BrowserDrawing, ShapesTurnAboutTheirCentres) {
  // transform="rotate(30)" with transform-origin="100 40", the centre of the 40 x 20 rectangle.
  const glm::dvec2 centre{100, 40};
  std::vector<glm::dvec2> corners;
  for (const glm::dvec2 p : {glm::dvec2(80, 30), glm::dvec2(120, 30), glm::dvec2(120, 50), glm::dvec2(80, 50)}) {
    corners.push_back(turned(p, centre, 30.0));
  }
  expect_polygon("turned", corners);
  // By hand: the top-left corner (-20, -10) from the centre turns to
  // (-20 cos 30 + 10 sin 30, -20 sin 30 - 10 cos 30) = (-12.3205, -18.6603).
  EXPECT_NEAR(corners[0].x, 100 - 12.320508075688772, 1e-12);
  EXPECT_NEAR(corners[0].y, 40 - 18.660254037844386, 1e-12);
  // The CSS transform in style: rotate(-45deg) about 155px 70px, the 30 x 20 rectangle's centre.
  const glm::dvec2 spun_centre{155, 70};
  std::vector<glm::dvec2> spun;
  for (const glm::dvec2 p : {glm::dvec2(140, 60), glm::dvec2(170, 60), glm::dvec2(170, 80), glm::dvec2(140, 80)}) {
    spun.push_back(turned(p, spun_centre, -45.0));
  }
  expect_polygon("spun", spun);
  // Turned about its centre, a shape keeps its centre.
  const std::vector<glm::dvec3>& points = curve("spun").as<PointsPart>().points;
  const glm::dvec3 middle = (points[0] + points[3] + points[6] + points[9]) / 4.0;
  EXPECT_NEAR(middle.x, 155.0, 1e-9);
  EXPECT_NEAR(middle.y, -70.0, 1e-9);
}

TEST_F(BrowserDrawing, ClonesAreWhereTheirXYTransformAndSymbolViewBoxPutThem) {
  // scale(2) after translate(10, 10): the 10 x 10 tile from (20, 20) to (40, 40).
  expect_polygon("tile", {{20, 20}, {40, 20}, {40, 40}, {20, 40}});
  // The symbol's 10 x 10 viewBox in the clone's 40 x 20 at (150, 10): scale 2, centred in x.
  expect_polygon("head", {{170, 10}, {180, 30}, {160, 30}});
}

TEST_F(BrowserDrawing, APercentCircleIsOfTheViewportsSize) {
  // cx 25% of 200, cy 75% of 100, r 5% of sqrt((200^2 + 100^2) / 2) = 7.9057.
  const glm::dvec2 centre = swp({50, 75});
  const double r = 0.05 * std::sqrt((200.0 * 200.0 + 100.0 * 100.0) / 2.0);
  EXPECT_NEAR(r, 7.905694150420948, 1e-12);
  const CurveSamples samples = evaluate_curve(curve("dot"));
  ASSERT_GE(samples.frames.size(), 64u);
  for (const Frame& f : samples.frames) EXPECT_NEAR(glm::distance(glm::dvec2(f.V), centre), r, 2.8e-4 * r);
}

}  // namespace
}  // namespace sweep
