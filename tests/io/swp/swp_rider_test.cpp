// The rider kind in SWP files: `rider NAME PATH MODEL [seconds S] [start F] [up X Y Z]`. Every bad
// input by its exact message and position; write -> parse as the identity, clauses written only
// when not default; a file's own text kept when saved unchanged or changed elsewhere.
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/evaluation/riders.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using sweep::test::expect_error;

const std::string kHead =
    "circ track 40 2\n"
    "circ body 12 0.2\n"
    "bez3 spine 1 4\n[0 0 0]\n[0 0 0.3]\n[0 0 0.6]\n[0 0 1]\n"
    "gcyl car body spine\n"
    "material red color 1 0 0\n";
const std::string kSurfaces = "(srev, gcyl, birail, bezpatch, bsppatch, mesh, subd)";

sweep::RiderObject rider_of(const sweep::Document& doc, const char* name) {
  return doc.objects.at(static_cast<std::size_t>(doc.find(name))).as<sweep::RiderObject>();
}

TEST(SwpRider, ReadsPathModelAndDefaults) {
  const sweep::Document doc = sweep::io::parse_swp(kHead + "rider r track car\n");
  const sweep::RiderObject r = rider_of(doc, "r");
  EXPECT_EQ(r.path, doc.find("track"));
  EXPECT_EQ(r.model, doc.find("car"));
  EXPECT_EQ(r.seconds, 10.0);
  EXPECT_EQ(r.start, 0.0);
  EXPECT_EQ(r.up, glm::dvec3(0.0));
}

TEST(SwpRider, ReadsClausesInAnyOrderAndCase) {
  const sweep::Document doc = sweep::io::parse_swp(kHead + "RIDER r track car UP 0 1 0 start 0.25 Seconds 4\n");
  const sweep::RiderObject r = rider_of(doc, "r");
  EXPECT_EQ(r.seconds, 4.0);
  EXPECT_EQ(r.start, 0.25);
  EXPECT_EQ(r.up, glm::dvec3(0.0, 1.0, 0.0));
}

TEST(SwpRider, WritesOnlyClausesThatAreNotDefault) {
  sweep::Document doc =
      sweep::io::parse_swp(kHead + "rider a track car\nrider b track car seconds 4 start 0.5 up 0 0 2\n");
  const std::string text = sweep::io::write_swp(doc);
  EXPECT_NE(text.find("rider a track car\n"), std::string::npos) << text;
  EXPECT_NE(text.find("rider b track car seconds 4 start 0.5 up 0 0 2\n"), std::string::npos) << text;
  EXPECT_EQ(sweep::io::parse_swp(text), doc);
}

TEST(SwpRider, SavedUnchangedIsTheFileByteForByte) {
  const std::string text = kHead + "rider  r track car   up 0 1 0 seconds 4\r\n";
  const sweep::Document doc = sweep::io::parse_swp_keeping_source(text);
  EXPECT_EQ(sweep::io::write_swp_preserving(doc), text);
}

TEST(SwpRider, AChangedRiderKeepsItsClauseOrder) {
  sweep::Document doc = sweep::io::parse_swp_keeping_source(kHead + "rider r track car up 0 1 0 seconds 4\n");
  doc.objects.back().as<sweep::RiderObject>().seconds = 6.0;
  const std::string text = sweep::io::write_swp_preserving(doc);
  EXPECT_NE(text.find("rider r track car up 0 1 0 seconds 6\n"), std::string::npos) << text;
}

TEST(SwpRiderErrors, PathMustBeACurveDefinedAbove) {
  expect_error(kHead + "rider r car car\n", 10, 9,
               "expected the name of a curve defined above as path, found 'car' (it is a surface (gcyl))");
  expect_error(kHead + "rider r later car\ncirc later 8 1\n", 10, 9,
               "expected the name of a curve defined above as path, found 'later' (it is defined further down; "
               "references point backwards only)");
  expect_error(kHead + "rider r nothing car\n", 10, 9,
               "expected the name of a curve defined above as path, found 'nothing' (no object has that name)");
}

TEST(SwpRiderErrors, ModelMustBeASurfaceDefinedAbove) {
  const std::string expected = "expected the name of a surface defined above as the model " + kSurfaces;
  expect_error(kHead + "rider r track body\n", 10, 15, expected + ", found 'body' (it is a curve (circ))");
  expect_error(kHead + "rider r track red\n", 10, 15, expected + ", found 'red' (it is a material (material))");
  expect_error(kHead + "rider r track ghost\n", 10, 15, expected + ", found 'ghost' (no object has that name)");
  expect_error(kHead + "rider r track\n", 11, 1, expected + ", found end of file");
}

TEST(SwpRiderErrors, SecondsStartAndUp) {
  expect_error(kHead + "rider r track car seconds 0\n", 10, 27,
               "expected seconds greater than 0, at most 1e9, found '0'");
  expect_error(kHead + "rider r track car seconds -2\n", 10, 27,
               "expected seconds greater than 0, at most 1e9, found '-2'");
  expect_error(kHead + "rider r track car start 1\n", 10, 25,
               "expected start from 0 up to (not including) 1, found '1'");
  expect_error(kHead + "rider r track car start -0.1\n", 10, 25,
               "expected start from 0 up to (not including) 1, found '-0.1'");
  expect_error(kHead + "rider r track car up 0 0 0\n", 10, 22, "expected an up vector other than 0 0 0, found '0'");
  expect_error(kHead + "rider r track car up 0 1\n", 11, 1, "expected a number (up z), found end of file");
  expect_error(kHead + "rider r track car up 0 1 0 up 0 1 0\n", 10, 28,
               "expected each clause at most once, found 'up' (already given at line 10, column 19)");
  expect_error(
      kHead + "rider r track car speed 3\n", 10, 19,
      "expected a clause (seconds, start, up) or a keyword (bez2, bez3, bsp2, bsp3, circ, cr2, cr3, kb2, "
      "kb3, helix, knot, poly2, poly3, herm2, herm3, srev, gcyl, birail, bezpatch, bsppatch, mesh, subd, material, "
      "rider), found 'speed'");
}

TEST(SwpRider, ModelsAreMarkedCarried) {
  const sweep::Document doc = sweep::io::parse_swp(kHead + "rider r track car\n");
  const std::vector<bool> carried = sweep::carried_models(doc);
  ASSERT_EQ(carried.size(), doc.objects.size());
  for (std::size_t i = 0; i < carried.size(); ++i) {
    EXPECT_EQ(carried[i], static_cast<int>(i) == doc.find("car")) << i;
  }
  EXPECT_EQ(sweep::riders_of(doc), std::vector<int>{doc.find("r")});
  EXPECT_EQ(sweep::longest_loop(doc), 10.0);
}

TEST(SwpRider, TheCurvesOfACarriedModelRideWithItAndAreNotDrawnAtTheOrigin) {
  const sweep::Document doc = sweep::io::parse_swp(kHead + "rider r track car\n");
  const std::vector<std::vector<int>> curves = sweep::carried_curves(doc);
  ASSERT_EQ(curves.size(), doc.objects.size());
  const int car = doc.find("car");
  // The car's own curves; not the track, which the rider rides (it is drawn where it is).
  for (std::size_t i = 0; i < curves.size(); ++i) {
    if (static_cast<int>(i) != car) {
      EXPECT_TRUE(curves[i].empty()) << i;
    }
  }
  EXPECT_EQ(curves[std::size_t(car)], (std::vector<int>{doc.find("body"), doc.find("spine")}));
}

}  // namespace
