// Resource caps (core/limits.hpp) and numerical limits: every cap is reached without error and
// passing it gives a file:line:column error before anything large is allocated; values at the
// coordinate cap and the radius bounds give finite meshes.
#include "io/mesh/obj_writer.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/evaluation/scene.hpp"
#include "model/file_limits.hpp"

#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <string>

namespace {

using sweep::io::ParseError;

/// The full message of the ParseError that parsing `text` as "caps.swp" throws, or "no error".
std::string parse_error(const std::string& text) {
  try {
    (void)sweep::io::parse_swp(text, "caps.swp");
  } catch (const ParseError& e) {
    return e.what();
  }
  return "no error";
}

/// A bsp2 named `name` whose `count` control points cycle through a small grid.
std::string bspline_text(const std::string& name, int steps, int count) {
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) about "literal" + std::string.
  std::string text = "bsp2 ";
  text.append(name).append(" ").append(std::to_string(steps)).append(" ").append(std::to_string(count)).append("\n");
  for (int i = 0; i < count; ++i) {
    text.append("[").append(std::to_string(i % 7)).append(" ").append(std::to_string(i % 5)).append("]\n");
  }
  return text;
}

TEST(Limits, AMillionControlPointsLoadAndEvaluate) {
  const int count = 1'000'000;
  const std::string text = bspline_text("big", 1, count);
  const sweep::Document doc = sweep::io::parse_swp(text, "big.swp");
  ASSERT_EQ(doc.objects.size(), 1u);
  ASSERT_EQ(doc.objects[0].as<sweep::PointsPart>().points.size(), static_cast<std::size_t>(count));
  EXPECT_EQ(doc.objects[0].as<sweep::PointsPart>().points[999'999], glm::dvec3(999'999 % 7, 999'999 % 5, 0.0));
  const sweep::Scene scene = sweep::evaluate_document(doc);
  // STEPS is per piece: (count - 3) pieces of one segment each.
  EXPECT_EQ(scene.objects[0].curve.frames.size(), static_cast<std::size_t>(count - 3 + 1));
}

TEST(Limits, StepsCap) {
  EXPECT_EQ(parse_error("circ c 100000 1"), "no error");
  EXPECT_EQ(parse_error("circ c 100001 1"),
            "caps.swp:1:8: expected STEPS, a whole number from 1 to 100000, found '100001'");
}

TEST(Limits, ControlPointCountCapIsCheckedBeforeReadingPoints) {
  EXPECT_EQ(parse_error("bsp3 c 1 10000001 [0 0 0]"),
            "caps.swp:1:10: expected a control point count, a whole number from 0 to 10000000, found '10000001'");
  // A count within the cap in a short file fails at the missing point, not on allocation.
  EXPECT_EQ(parse_error("bsp3 c 1 10000000 [0 0 0]"),
            "caps.swp:1:26: expected '[' to start point 2 of 10000000, found end of file");
}

TEST(Limits, SamplesPerCurveCap) {
  // (pieces) * STEPS + 1 samples: 99 pieces * 100000 + 1 is under 10 million, 100 pieces is over.
  EXPECT_EQ(parse_error(bspline_text("ok", 100000, 102)), "no error");
  EXPECT_EQ(parse_error(bspline_text("over", 100000, 103)),
            "caps.swp:1:11: expected at most 10000000 samples per curve, found '100000' "
            "(STEPS 100000 gives 10000001)");
}

TEST(Limits, SamplesPerDocumentCap) {
  // Three curves of 9.7 million samples each pass 20 million at the third one's STEPS (line 203).
  const std::string text =
      bspline_text("a", 100000, 100) + bspline_text("b", 100000, 100) + bspline_text("c", 100000, 100);
  EXPECT_EQ(parse_error(text),
            "caps.swp:203:8: expected at most 20000000 curve samples in the whole document, found '100000' "
            "(this curve brings the total to 29100003)");
}

TEST(Limits, MeshVertexCaps) {
  // A profile of 300 samples turned 100000 times gives 30 million vertices: one is fine, two
  // pass the document's 50 million.
  EXPECT_EQ(parse_error("circ c 299 1\nsrev a 100000 c"), "no error");
  EXPECT_EQ(parse_error("circ c 299 1\nsrev a 100000 c\nsrev b 100000 c"),
            "caps.swp:3:8: expected at most 50000000 surface vertices in the whole document, found '100000' "
            "(this surface brings the total to 60000000)");
  EXPECT_EQ(parse_error("circ c 1000 1\nsrev a 100000 c"),
            "caps.swp:2:8: expected a surface of at most 50000000 vertices, found '100000' "
            "(this one would have 100100000)");
  EXPECT_EQ(parse_error("circ p 9999 1\ncirc s 9999 1\ngcyl g p s"),
            "caps.swp:3:1: expected a surface of at most 50000000 vertices, found 'gcyl' "
            "(this one would have 100000000)");
}

TEST(Limits, NameLengthCap) {
  const std::string longest(sweep::limits::kMaxNameLength, 'n');
  EXPECT_EQ(parse_error("circ " + longest + " 4 1"), "no error");
  EXPECT_EQ(parse_error("circ " + longest + "n 4 1"),
            "caps.swp:1:6: expected a name (a letter or '_', then letters, digits, '_', '-' or '.') or '.' for none, "
            "found '" +
                std::string(32, 'n') + "...'");
}

TEST(Limits, FileSizeCapIsCheckedBeforeReading) {
  // A sparse file one byte over the cap: no disk space is used, and the loader must refuse it
  // from its size alone.
  const sweep::test::ScratchFolder folder("sweep-limits");
  const auto path = folder.path() / "huge.swp";
  sweep::test::write_text(path, " ");
  std::filesystem::resize_file(path, sweep::limits::kMaxFileBytes + 1);
  try {
    (void)sweep::io::load_swp_file(path);
    ADD_FAILURE() << "a file over the cap loaded";
  } catch (const ParseError& e) {
    EXPECT_EQ(e.detail(), "expected an SWP file of at most 512 MiB (536870912 bytes), found 536870913 bytes");
  }
}

TEST(Limits, CoordinateCap) {
  EXPECT_EQ(parse_error("bez3 c 4 4 [1e12 -1e12 1e12] [0 0 0] [1 1 1] [-1e12 1e12 -1e12]"), "no error");
  EXPECT_EQ(parse_error("bez3 c 4 4 [1e12 -1e12 1e12] [0 0 1.0000001e12]"),
            "caps.swp:1:35: expected a number from -1e12 to 1e12 (z of point 2 of 4), found '1.0000001e12'");
  EXPECT_EQ(parse_error("circ c 4 1e400"), "caps.swp:1:10: expected a number (radius), found '1e400' (out of range)");
  EXPECT_EQ(parse_error("circ c 4 inf"), "caps.swp:1:10: expected a finite number (radius), found 'inf'");
  EXPECT_EQ(parse_error("circ c 4 nan"), "caps.swp:1:10: expected a finite number (radius), found 'nan'");
}

TEST(Limits, RadiusBounds) {
  EXPECT_EQ(parse_error("circ c 4 1e-12"), "no error");
  EXPECT_EQ(parse_error("circ c 4 1e-300"),
            "caps.swp:1:10: expected a radius of 0 or of at least 1e-12, found '1e-300'");
  EXPECT_EQ(parse_error("circ c 4 0"), "no error") << "a point whose frames turn (issue 26)";
  EXPECT_EQ(parse_error("circ c 4 -1"), "caps.swp:1:10: expected a radius of 0 or more, found '-1'");
  EXPECT_EQ(parse_error("helix h 4 0 1 2"), "caps.swp:1:11: expected a positive radius, found '0'");
}

/// Every surface of the document as OBJ text, after checking the meshes are finite.
void expect_finite_export(const std::string& text) {
  const sweep::Document doc = sweep::io::parse_swp(text, "extreme.swp");
  const sweep::Scene scene = sweep::evaluate_document(doc);
  int surfaces = 0;
  for (const auto& object : scene.objects) {
    if (object.mesh.vertex_count() == 0) continue;
    ++surfaces;
    EXPECT_TRUE(sweep::io::mesh_is_finite(object.mesh)) << text;
    const std::string obj = sweep::io::obj_text(object.mesh);
    EXPECT_EQ(obj.find("nan"), std::string::npos) << text;
    EXPECT_EQ(obj.find("inf"), std::string::npos) << text;
  }
  EXPECT_GT(surfaces, 0) << text;
}

TEST(Limits, ExtremeButValidInputsGiveFiniteMeshes) {
  // Largest radius swept along a curve at the coordinate cap: positions reach 3e12, still finite
  // in float (whose limit is 3.4e38).
  expect_finite_export(
      "circ p 16 1e12\nbez3 s 8 4 [1e12 1e12 1e12] [-1e12 1e12 -1e12] [1e12 -1e12 1e12] [-1e12 -1e12 -1e12]\n"
      "gcyl g p s\nsrev r 16 p");
  // Smallest radius, on a tiny and a huge sweep.
  expect_finite_export(
      "circ p 16 1e-12\nbsp3 s 4 4 [0 0 0] [1e-300 0 0] [1e-300 1e-300 0] [0 1e-300 1e-300]\ngcyl g p s");
  expect_finite_export("circ p 16 1e-12\nbsp3 s 4 4 [0 0 0] [1e12 0 0] [1e12 1e12 0] [0 1e12 1e12]\ngcyl g p s");
  // A profile of denormal coordinates and one that is a single repeated point.
  expect_finite_export("bez2 p 4 4 [4.9e-324 0] [0 4.9e-324] [-4.9e-324 0] [0 -4.9e-324]\nsrev r 8 p");
  expect_finite_export(
      "bsp2 p 4 4 [1 1] [1 1] [1 1] [1 1]\nsrev r 8 p\nbez3 s 4 4 [1 2 3] [1 2 3] [1 2 3] [1 2 3]\ngcyl g p s");
}

TEST(Limits, ExporterRefusesANonFiniteMeshAndWritesNothing) {
  sweep::Mesh mesh;
  mesh.positions = {{0, 0, 0}, {1, 0, 0}, {0, std::nanf(""), 0}};
  mesh.normals = {{0, 0, 1}, {0, 0, 1}, {0, 0, 1}};
  mesh.indices = {0, 1, 2};
  const sweep::test::ScratchFolder folder("sweep-limits");
  const auto path = folder.path() / "nan.obj";
  try {
    sweep::io::save_obj_file(path, mesh);
    ADD_FAILURE() << "a mesh with a NaN was written";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + path.string() + ": the mesh has a NaN or infinite coordinate");
  }
  EXPECT_FALSE(std::filesystem::exists(path));
  mesh.positions[2].y = 0.0f;
  mesh.normals[1].x = INFINITY;
  EXPECT_FALSE(sweep::io::mesh_is_finite(mesh));
  EXPECT_THROW(sweep::io::save_obj_file(path, mesh), std::runtime_error);
  EXPECT_FALSE(std::filesystem::exists(path));
}

}  // namespace
