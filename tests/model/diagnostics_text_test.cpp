// What Sweep says about a document in words: sweep diagnostics, fold ranges and warnings, and
// the `sweep info` summary, line by line.
#include "model/diagnostics_text.hpp"

#include "io/swp/read.hpp"

#include <gtest/gtest.h>

#include <numbers>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace sweep::editor {
namespace {

constexpr double kRadiansPerDegree = std::numbers::pi / 180.0;

const std::vector<FoldRange> kFolds = {{3, 5, 1.2, 1.45}, {12, 13, 3.0, 3.1}};

SweepDiagnostics diagnostics(bool closed, double seam_degrees, double twist_degrees,
                             std::vector<FoldRange> folds = {}) {
  SweepDiagnostics d;
  d.closed = closed;
  d.seam_angle = seam_degrees * kRadiansPerDegree;
  d.total_twist = twist_degrees * kRadiansPerDegree;
  d.folds = std::move(folds);
  return d;
}

std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

TEST(DiagnosticsText, FoldRanges) {
  EXPECT_EQ(fold_ranges({}), "");
  EXPECT_EQ(fold_ranges({kFolds[0]}), "t = 1.20 to 1.45");
  EXPECT_EQ(fold_ranges(kFolds), "t = 1.20 to 1.45, t = 3.00 to 3.10");
}

TEST(DiagnosticsText, SweepDiagnostics) {
  EXPECT_EQ(sweep_diagnostics_text(diagnostics(true, 12.0, 30.0)),
            "closed sweep, seam angle 12.00 deg, total twist 30.00 deg, no folds");
  EXPECT_EQ(sweep_diagnostics_text(diagnostics(false, 0.0, 7.5)),
            "open sweep, seam angle 0.00 deg, total twist 7.50 deg, no folds");
  EXPECT_EQ(sweep_diagnostics_text(diagnostics(false, 0.0, 7.5, kFolds)),
            "open sweep, seam angle 0.00 deg, total twist 7.50 deg, folds at t = 1.20 to 1.45, t = 3.00 to 3.10");
  EXPECT_EQ(sweep_diagnostics_text(diagnostics(true, -45.5, 180.0, {kFolds[1]})),
            "closed sweep, seam angle -45.50 deg, total twist 180.00 deg, folds at t = 3.00 to 3.10");
}

TEST(DiagnosticsText, FoldWarning) {
  EXPECT_EQ(fold_warning("tube", diagnostics(true, 0.0, 0.0, kFolds)),
            "warning: surface 'tube' folds over itself where the profile reaches beyond the sweep's radius of "
            "curvature (t = 1.20 to 1.45, t = 3.00 to 3.10)");
}

// 0 arc (line 1), 1 ring (8), 2 path (9), 3 vase (10), 4 tube (11), 5 an anonymous circle (12).
constexpr const char* kText =
    "bsp2 arc 4 6\n[-1 1]\n[-1.2 0.5]\n[-0.8 0]\n[-1 -0.5]\n[-1 -1]\n[-0.5 -1.2]\n"
    "circ ring 16 0.3\n"
    "circ path 32 2\n"
    "srev vase 8 arc\n"
    "gcyl tube ring path\n"
    "circ . 8 1\n";

std::string counts(const Mesh& mesh) {
  return ": " + std::to_string(mesh.vertex_count()) + " vertices, " + std::to_string(mesh.triangle_count()) +
         " triangles";
}

TEST(DiagnosticsText, DocumentSummaryHasALinePerCurveAndTwoPerGeneralizedCylinder) {
  const Document doc = io::parse_swp(kText);
  const Scene scene = evaluate_document(doc);
  const std::string summary = document_summary(doc, scene, "shapes.swp");
  ASSERT_FALSE(summary.empty());
  EXPECT_EQ(summary.back(), '\n');
  const std::vector<std::string> expected = {
      "shapes.swp: 6 objects",
      "  bsp2 arc              line 1    steps 4      6 control points, 13 samples",
      "  circ ring             line 8    steps 16     radius 0.3, 17 samples, closed",
      "  circ path             line 9    steps 32     radius 2, 33 samples, closed",
      "  srev vase             line 10   steps 8      profile arc" + counts(scene.objects[3].mesh),
      "  gcyl tube             line 11   profile ring, sweep path" + counts(scene.objects[4].mesh),
      "       closed sweep, seam angle 0.00 deg, total twist 0.00 deg, no folds",
      "  circ circ#5           line 12   steps 8      radius 1, 9 samples, closed",
  };
  EXPECT_EQ(lines_of(summary), expected);
  EXPECT_EQ(lines_of(summary)[6], "       " + sweep_diagnostics_text(scene.objects[4].diagnostics));
}

TEST(DiagnosticsText, DocumentSummaryKeepsItsLinesWithTheLongestNames) {
  const std::string profile(200, 'p');
  const std::string path(200, 's');
  const std::string tube(200, 't');
  const Document doc = io::parse_swp("circ " + profile + " 8 0.3\ncirc " + path + " 16 2\ngcyl " + tube + " " +
                                     profile + " " + path + "\n");
  const Scene scene = evaluate_document(doc);
  const std::vector<std::string> lines = lines_of(document_summary(doc, scene, "long.swp"));
  ASSERT_EQ(lines.size(), 5u) << ::testing::PrintToString(lines);
  EXPECT_EQ(lines[0], "long.swp: 3 objects");
  EXPECT_EQ(lines[1].rfind("  circ " + profile + " line 1    steps 8      radius 0.3", 0), 0u) << lines[1];
  const std::string tail = counts(scene.objects[2].mesh);
  ASSERT_GT(lines[3].size(), tail.size());
  EXPECT_EQ(lines[3].substr(lines[3].size() - tail.size()), tail);
  EXPECT_NE(lines[3].find("profile " + profile + ", sweep " + path), std::string::npos);
  EXPECT_EQ(lines[4], "       " + sweep_diagnostics_text(scene.objects[2].diagnostics));
}

// Every row's columns (name, line, the rest) start where the others' do, whatever the kinds'
// keywords: the keyword column is as wide as the document's longest keyword.
TEST(DiagnosticsText, DocumentSummaryAlignsItsColumnsForEveryKind) {
  const Document doc = io::parse_swp(
      "bsp2 section 8 4 [0 0] [1 1] [2 0] [3 1]\ncr3 port 10 2 [0 0 0] [0 0 4]\ncr3 star 10 2 [2 0 0] [2 0 4]\n"
      "birail hull section port star\nhelix coil 8 1 0.5 2\nmaterial wood color 0.5 0.4 0.3\n"
      "srev vase 8 section material wood\n");
  const Scene scene = evaluate_document(doc);
  const std::vector<std::string> lines = lines_of(document_summary(doc, scene, "kinds.swp"));
  ASSERT_EQ(lines.size(), 8u) << ::testing::PrintToString(lines);
  const std::vector<std::string> names = {"section", "port", "star", "hull", "coil", "wood", "vase"};
  for (std::size_t i = 0; i < names.size(); ++i) {
    const std::string& line = lines[i + 1];
    EXPECT_EQ(line.find(names[i]), 11u) << line;  // 2 spaces, "material" (8), a space
    EXPECT_EQ(line.find(" line "), 27u) << line;
  }
  EXPECT_EQ(lines[4].rfind("  birail   hull             line 4    profile section, rails port and star", 0), 0u)
      << lines[4];
}

TEST(DiagnosticsText, DocumentSummaryKeepsItsFirstLineWithALongFilePath) {
  const Document doc = io::parse_swp("circ ring 8 1\n");
  const Scene scene = evaluate_document(doc);
  const std::string file = "/" + std::string(300, 'd') + "/" + std::string(300, 'f') + ".swp";  // PATH_MAX is 4096
  const std::vector<std::string> lines = lines_of(document_summary(doc, scene, file));
  // A path longer than any fixed buffer keeps its whole line and newline.
  ASSERT_EQ(lines.size(), 2u) << ::testing::PrintToString(lines);
  EXPECT_EQ(lines[0], file + ": 1 objects");
  EXPECT_EQ(lines[1], "  circ ring             line 1    steps 8      radius 1, 9 samples, closed");
}

TEST(DiagnosticsText, AHelixOrKnotOffTheOriginSaysWhereItStands) {
  const Document doc = io::parse_swp("knot k 60 2 3 1 0.4 at 3 0 -1.5\nhelix h 4 1 0.5 1\n");
  const std::vector<std::string> lines = lines_of(document_summary(doc, evaluate_document(doc), "placed.swp"));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[1],
            "  knot  k                line 1    steps 60     P 2 Q 3 R 1 r 0.4 at 3 0 -1.5, 61 samples, closed");
  EXPECT_EQ(lines[2], "  helix h                line 2    steps 4      radius 1 pitch 0.5 turns 1, 5 samples");
}

}  // namespace
}  // namespace sweep::editor
