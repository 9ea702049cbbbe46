// The printability checks (model/print/printability.hpp), each with a model made to fail it and
// its exact message, and the starter and artifact files as docs/printing.md says they come out.
#include "model/print/printability.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

namespace sweep {
namespace {

/// The findings of `text` as a file "m.swp" printed `height_mm` tall.
std::vector<PrintFinding> findings_of(const std::string& text, double height_mm = 80.0, double min_wall_mm = 0.8) {
  const Document doc = io::parse_swp(text, "m.swp");
  const Scene scene = evaluate_document(doc);
  return check_print(doc, print_model(doc, scene, height_mm), "m.swp", {min_wall_mm});
}

std::vector<std::string> messages(const std::vector<PrintFinding>& findings) {
  std::vector<std::string> out;
  for (const PrintFinding& f : findings) out.push_back(f.message);
  return out;
}

/// A closed cube as a polygon mesh, side 1 from `y` up; `faces` replaces its faces.
std::string cube(const std::string& name, double y, const std::string& faces = "") {
  std::string text =
      "mesh " + name + " 8 " + std::to_string(faces.empty() ? 6 : std::count(faces.begin(), faces.end(), '[')) + "\n";
  for (const double py : {y, y + 1.0}) {
    for (const char* xz : {"0 %s 0", "1 %s 0", "1 %s 1", "0 %s 1"}) {
      char line[64];
      std::snprintf(line, sizeof line, xz, std::to_string(py).c_str());
      text += std::string("[") + line + "]\n";
    }
  }
  return text + (faces.empty() ? "[0 1 2 3]\n[4 7 6 5]\n[0 4 5 1]\n[1 5 6 2]\n[2 6 7 3]\n[3 7 4 0]\n" : faces);
}

constexpr const char* kTube =
    "circ ring 16 0.3\n"
    "bez3 path 4 4\n[0 0 0]\n[0 1 0]\n[0 2 0]\n[0 3 0]\n"
    "gcyl tube ring path\n";

TEST(Printability, AnOpenTubeIsOpenWithItsHolesCounted) {
  const std::vector<PrintFinding> found = findings_of(kTube);
  ASSERT_EQ(found.size(), 1u) << testing::PrintToString(messages(found));
  EXPECT_EQ(found[0].check, PrintCheck::Open);
  EXPECT_EQ(found[0].message,
            "m.swp:7:1: warning: surface 'tube' is open: 2 holes (32 boundary edges); a printer needs a closed solid");
  EXPECT_TRUE(found[0].fails);
  EXPECT_TRUE(print_fails(found));
  EXPECT_TRUE(findings_of(std::string(kTube).replace(std::string(kTube).find("path\n", 60), 5, "path caps\n")).empty());
}

TEST(Printability, TwoCrossingOpenTubesCrossAndTwoCappedOnesOverlap) {
  const std::string across = "bez3 across 4 4\n[-1.5 1.5 0]\n[-0.5 1.5 0]\n[0.5 1.5 0]\n[1.5 1.5 0]\n";
  const std::string open = std::string(kTube) + across + "gcyl bar ring across\n";
  const std::vector<std::string> found = messages(findings_of(open));
  EXPECT_NE(std::find(found.begin(), found.end(),
                      "m.swp:7:1: warning: surfaces 'tube' and 'bar' (line 13) cross (188 pairs of triangles) "
                      "where one is open; a slicer cannot tell inside from outside there"),
            found.end())
      << testing::PrintToString(found);
  std::string capped = open;
  capped.replace(capped.find("ring path\n"), 10, "ring path caps\n");
  capped.replace(capped.find("ring across\n"), 12, "ring across caps\n");
  const std::vector<PrintFinding> solid = findings_of(capped);
  ASSERT_EQ(solid.size(), 1u) << testing::PrintToString(messages(solid));
  EXPECT_EQ(solid[0].check, PrintCheck::Overlap);
  EXPECT_EQ(solid[0].message,
            "m.swp:7:1: note: surfaces 'tube' and 'bar' (line 13) overlap; a slicer prints them as one solid");
  EXPECT_FALSE(print_fails(solid));
}

TEST(Printability, TheCreatePanelsCircleAlongItsTrefoilPassesThroughItself) {
  const std::vector<PrintFinding> found =
      findings_of("knot trefoil 240 2 3 1 0.4\ncirc circle 24 1\ngcyl tube circle trefoil\n");
  ASSERT_FALSE(found.empty());
  EXPECT_EQ(found[0].check, PrintCheck::SelfIntersection);
  EXPECT_EQ(found[0].message.rfind("m.swp:3:1: warning: surface 'tube' passes through itself (at least 1000 pairs", 0),
            0u)
      << found[0].message;
  const std::vector<PrintFinding> thin =
      findings_of("knot trefoil 240 2 3 1 0.4\ncirc circle 24 0.1\ngcyl tube circle trefoil\n");
  EXPECT_TRUE(std::none_of(thin.begin(), thin.end(),
                           [](const PrintFinding& f) { return f.check == PrintCheck::SelfIntersection; }));
}

TEST(Printability, AWall0Point3MillimetresThickAt80IsThin) {
  // A ring whose wall is 0.00375 of its height: 0.3 mm at 80 mm.
  const std::string ring = "poly2 wall 5\n[1 0]\n[1.00375 0]\n[1.00375 1]\n[1 1]\n[1 0]\nsrev ring 180 wall\n";
  const std::vector<PrintFinding> found = findings_of(ring);
  ASSERT_EQ(found.size(), 1u) << testing::PrintToString(messages(found));
  EXPECT_EQ(found[0].check, PrintCheck::ThinWall);
  EXPECT_EQ(found[0].message.rfind("m.swp:7:1: warning: surface 'ring' has walls thinner than 0.80 mm: ", 0), 0u);
  EXPECT_NE(found[0].message.find("triangles, the thinnest 0.30 mm at a height of 80.0 mm"), std::string::npos)
      << found[0].message;
  EXPECT_TRUE(findings_of(ring, 80.0, 0.25).empty());
  EXPECT_TRUE(findings_of(ring, 300.0).empty());  // 1.1 mm thick at 300 mm
}

TEST(Printability, AMeshInsideOutOrWithoutALidIsNamed) {
  const std::string flipped_all = "[0 3 2 1]\n[4 5 6 7]\n[0 1 5 4]\n[1 2 6 5]\n[2 3 7 6]\n[3 0 4 7]\n";
  EXPECT_EQ(
      messages(findings_of(cube("box", 0, flipped_all))),
      std::vector<std::string>{"m.swp:1:1: warning: surface 'box' is inside out: its triangles face into the solid"});
  const std::string lidless = "[0 1 2 3]\n[0 4 5 1]\n[1 5 6 2]\n[2 6 7 3]\n[3 7 4 0]\n";
  EXPECT_EQ(
      messages(findings_of(cube("box", 0, lidless))),
      std::vector<std::string>{
          "m.swp:1:1: warning: surface 'box' is open: 1 hole (4 boundary edges); a printer needs a closed solid"});
}

/// A flat bicubic patch over x in [x0, x0 + 1], z in [0, 1] at y = 0, or standing up (y for z);
/// `flipped` swaps its directions, so it faces the other way.
std::string flat_patch(double x0, bool flipped, bool standing = false) {
  std::string text;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const double u = (flipped ? j : i) / 3.0;
      const double v = (flipped ? i : j) / 3.0;
      const double x = standing ? x0 : x0 + u;
      const double w = standing ? u : v;
      char line[96];
      std::snprintf(line, sizeof line, "[%.6f %.6f %.6f]\n", x, standing ? w : 0.0, standing ? v : w);
      text += line;
    }
  }
  return text;
}

TEST(Printability, PatchesFacingOppositeWaysOrThreeAtAnEdgeAreNamed) {
  const std::vector<std::string> opposite =
      messages(findings_of("bezpatch sheet 4 2\n" + flat_patch(0, false) + flat_patch(1, true)));
  EXPECT_NE(std::find(opposite.begin(), opposite.end(),
                      "m.swp:1:1: warning: surface 'sheet' is not consistently oriented: 4 edges join triangles that "
                      "face opposite ways"),
            opposite.end())
      << testing::PrintToString(opposite);
  const std::vector<std::string> fin = messages(
      findings_of("bezpatch fin 4 3\n" + flat_patch(0, false) + flat_patch(1, false) + flat_patch(1, false, true)));
  EXPECT_NE(std::find(fin.begin(), fin.end(),
                      "m.swp:1:1: warning: surface 'fin' has 4 non-manifold edges (each of more than two triangles)"),
            fin.end())
      << testing::PrintToString(fin);
}

TEST(Printability, APartAboveTheRestTouchingNothingFloats) {
  const std::vector<PrintFinding> found = findings_of(cube("base", 0) + cube("top", 1.5));
  ASSERT_EQ(found.size(), 1u) << testing::PrintToString(messages(found));
  EXPECT_EQ(found[0].check, PrintCheck::Floating);
  EXPECT_EQ(found[0].message,
            "m.swp:16:1: warning: surface 'top' floats: it touches nothing below it; its lowest point is 48.0 mm above "
            "the plate");
  EXPECT_NEAR(found[0].where.y, 1.5, 1e-9);  // model coordinates: where the viewer marks it
  EXPECT_TRUE(findings_of(cube("base", 0) + cube("top", 0.5)).size() == 1u);  // overlapping: a note
}

TEST(Printability, TheQueenAndTheBraidPrintAsDocsPrintingSays) {
  for (const auto& [file, height] : {std::pair("chess-queen.swp", 80.0), std::pair("trefoil-braid.swp", 60.0)}) {
    const Document doc = io::load_swp_file(std::filesystem::path(SWEEP_SWP_DIR) / "artifacts" / file);
    const PrintModel model = print_model(doc, evaluate_document(doc), height);
    const std::vector<PrintFinding> found = check_print(doc, model, file);
    std::vector<std::string> failing;
    for (const PrintFinding& f : found) {
      if (f.fails) failing.push_back(f.message);
    }
    if (std::string(file) == "trefoil-braid.swp") {
      EXPECT_TRUE(found.empty()) << testing::PrintToString(messages(found));
      continue;
    }
    ASSERT_EQ(failing.size(), 1u) << testing::PrintToString(failing);  // the crown's star points
    EXPECT_EQ(failing[0].rfind("chess-queen.swp:63:1: warning: surface 'crown' has walls thinner than 0.80 mm", 0), 0u);
    for (const PrintPart& part : model.parts) EXPECT_EQ(zero_area_triangles(part.shell), 0u) << part.name;
  }
}

TEST(Printability, TheWineglassIsOneClosedShellWithNoTriangleOfZeroArea) {
  const Document doc = test::load_starter("wineglass.swp");
  const PrintModel model = print_model(doc, evaluate_document(doc), 80.0);
  ASSERT_EQ(model.parts.size(), 1u);
  const std::vector<PrintFinding> found = check_print(doc, model, "wineglass.swp");
  EXPECT_TRUE(std::none_of(found.begin(), found.end(), [](const PrintFinding& f) {
    return f.check == PrintCheck::Open;
  })) << testing::PrintToString(messages(found));
  EXPECT_EQ(zero_area_triangles(model.parts[0].shell), 0u);
}

}  // namespace
}  // namespace sweep
