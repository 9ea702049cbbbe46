// parse -> write -> parse is the identity, and writing is a fixed point after one round.
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"

#include "support/core_test_support.hpp"
#include "support/file_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace {

TEST(SwpRoundTrip, EveryStarterFileParsesBackToTheSameDocument) {
  const auto files = sweep::test::starter_files();
  ASSERT_FALSE(files.empty());
  for (const auto& file : files) {
    const sweep::Document doc = sweep::io::load_swp_file(file);
    ASSERT_FALSE(doc.objects.empty()) << file;
    const std::string text = sweep::io::write_swp(doc);
    const sweep::Document again = sweep::io::parse_swp(text, "rewritten.swp");
    EXPECT_EQ(again, doc) << file;
    EXPECT_EQ(sweep::io::write_swp(again), text) << file;
  }
}

using sweep::test::read_file;

/// The shared copies of the starter files (../shared/swp beside the checkout), if there are any.
std::filesystem::path shared_swp_dir() {
  return std::filesystem::path(SWEEP_SWP_DIR).parent_path().parent_path() / "shared" / "swp";
}

TEST(SwpRoundTrip, OldFilesAreWrittenBackExactlyAsBefore) {
  // tests/data/swp-written/NAME.swp is what the writer gave for swp/NAME.swp before optional
  // clauses and the new curve kinds existed: files of the old kinds must be saved byte for byte
  // as before. (A deliberate change to a starter file needs its expected text updated here.)
  const std::filesystem::path expected_dir = std::filesystem::path(SWEEP_TEST_DATA_DIR) / "swp-written";
  const std::filesystem::path shared = shared_swp_dir();
  int compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(expected_dir)) {
    if (entry.path().extension() != ".swp") continue;
    const std::string expected = read_file(entry.path());
    ASSERT_FALSE(expected.empty()) << entry.path();
    const std::filesystem::path starter = std::filesystem::path(SWEEP_SWP_DIR) / entry.path().filename();
    EXPECT_EQ(sweep::io::write_swp(sweep::io::load_swp_file(starter)), expected) << starter;
    ++compared;
    if (const auto copy = shared / entry.path().filename(); std::filesystem::exists(copy)) {
      EXPECT_EQ(sweep::io::write_swp(sweep::io::load_swp_file(copy)), expected) << copy;
      ++compared;
    }
  }
  EXPECT_GE(compared, 11);
}

TEST(SwpRoundTrip, SharedFilesParseBackToTheSameDocument) {
  const std::filesystem::path shared = shared_swp_dir();
  if (!std::filesystem::is_directory(shared)) GTEST_SKIP() << "no " << shared;
  for (const auto& entry : std::filesystem::directory_iterator(shared)) {
    if (entry.path().extension() != ".swp") continue;
    const sweep::Document doc = sweep::io::load_swp_file(entry.path());
    const std::string text = sweep::io::write_swp(doc);
    EXPECT_EQ(sweep::io::parse_swp(text), doc) << entry.path();
    EXPECT_EQ(sweep::io::write_swp(sweep::io::parse_swp(text)), text) << entry.path();
  }
}

TEST(SwpRoundTrip, FirstLinesAreWhereTheRewrittenObjectsStart) {
  for (const auto& file : sweep::test::starter_files()) {
    const sweep::Document doc = sweep::io::load_swp_file(file);
    std::vector<int> first_lines;
    const std::string text = sweep::io::write_swp(doc, &first_lines);
    const sweep::Document again = sweep::io::parse_swp(text);
    ASSERT_EQ(first_lines.size(), again.objects.size()) << file;
    for (std::size_t i = 0; i < first_lines.size(); ++i) {
      EXPECT_EQ(again.objects[i].location.line, first_lines[i]) << file << " object " << i;
      EXPECT_EQ(again.objects[i].location.column, 1) << file << " object " << i;
    }
  }
}

TEST(SwpRoundTrip, AwkwardNumbersSurviveBitForBit) {
  sweep::Document doc;
  sweep::Object curve;
  curve.set_kind(sweep::ObjectKind::BSpline3);
  curve.name = "awkward";
  curve.as<sweep::StepsPart>().steps = 3;
  curve.as<sweep::PointsPart>().points = {{0.1, 1.0 / 3.0, -2.0 / 7.0},
                                          {1e-300, std::numeric_limits<double>::denorm_min(), 123456789.123456789},
                                          {-1e12, 1e12, std::nextafter(1.0, 2.0)},
                                          {std::numeric_limits<double>::epsilon(), -0.0, 6.02214076e23 / 1e12}};
  doc.objects.push_back(curve);
  sweep::Object circle;
  circle.set_kind(sweep::ObjectKind::Circle);
  circle.name = "c";
  circle.as<sweep::StepsPart>().steps = 7;
  circle.as<sweep::RadiusPart>().radius = std::sqrt(2.0);
  doc.objects.push_back(circle);
  const sweep::Document again = sweep::io::parse_swp(sweep::io::write_swp(doc));
  ASSERT_EQ(again, doc);
  for (std::size_t i = 0; i < curve.as<sweep::PointsPart>().points.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(std::signbit(again.objects[0].as<sweep::PointsPart>().points[i][k]),
                std::signbit(curve.as<sweep::PointsPart>().points[i][k]))
          << i << " " << k;
    }
  }
}

TEST(SwpRoundTrip, AnonymousObjectsAndReferencesAreKept) {
  const std::string text =
      "bez2 p 4 4 [-1 1] [-2 0] [-2 -0.5] [-1 -1]\n"
      "circ . 12 0.25\n"
      "bsp3 s 5 4 [0 0 0] [1 0 0] [1 1 0] [1 1 1]\n"
      "srev . 8 p\n"
      "gcyl tube p s\n";
  const sweep::Document doc = sweep::io::parse_swp(text);
  ASSERT_EQ(doc.objects.size(), 5u);
  EXPECT_EQ(doc.objects[1].name, "");
  EXPECT_EQ(doc.objects[3].as<sweep::ProfilePart>().profile, 0);
  EXPECT_EQ(doc.objects[4].as<sweep::ProfilePart>().profile, 0);
  EXPECT_EQ(doc.objects[4].as<sweep::CylinderSurface>().sweep, 2);
  const std::string written = sweep::io::write_swp(doc);
  EXPECT_EQ(sweep::io::parse_swp(written), doc);
  EXPECT_EQ(sweep::io::write_swp(sweep::io::parse_swp(written)), written);
}

TEST(SwpRoundTrip, LocationIsNotPartOfEquality) {
  const sweep::Document a = sweep::io::parse_swp("circ c 10 1");
  const sweep::Document b = sweep::io::parse_swp("\n\n   circ c 10 1");
  EXPECT_EQ(a, b);
  EXPECT_NE(a.objects[0].location, b.objects[0].location);
  EXPECT_NE(a, sweep::io::parse_swp("circ c 10 2"));
  EXPECT_NE(a, sweep::io::parse_swp("circ d 10 1"));
  EXPECT_NE(a, sweep::io::parse_swp("circ c 11 1"));
}

TEST(SwpRoundTrip, ValidateDocumentAcceptsParsedAndRejectsBrokenEdits) {
  for (const auto& file : sweep::test::starter_files())
    EXPECT_NO_THROW(sweep::io::validate_document(sweep::io::load_swp_file(file)));
  sweep::Document doc = sweep::io::parse_swp("circ c 10 1\n\ncirc s 20 2\ngcyl t c s\ncirc late 5 1\n", "edit.swp");
  doc.objects[2].as<sweep::ProfilePart>().profile = 3;  // an edit that makes the surface use a curve defined after it
  try {
    sweep::io::validate_document(doc, "edit.swp");
    FAIL() << "no error";
  } catch (const sweep::io::ParseError& e) {
    EXPECT_EQ(e.line(), 4);  // where the surface was read from, not a line of the rewritten text
    EXPECT_EQ(e.column(), 1);
    EXPECT_EQ(
        std::string(e.what()),
        "edit.swp:4:1: expected the name of a 2D curve (bez2, bsp2, circ, cr2, kb2, poly2, herm2) defined above as "
        "profile, found "
        "'late' "
        "(it is defined further down; references point backwards only) (in t)");
  }
}

}  // namespace
