// SWP for patches, meshes and subdivision surfaces (bezpatch, bsppatch, mesh, subd): the exact
// messages for bad input, at the token they are about, and round trips through write_swp.
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"

#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

namespace {

using sweep::test::expect_error;

const std::string kKeywords =
    "expected a keyword (bez2, bez3, bsp2, bsp3, circ, cr2, cr3, kb2, kb3, helix, knot, poly2, poly3, herm2, herm3, "
    "srev, gcyl, "
    "birail, "
    "bezpatch, bsppatch, mesh, subd, material, rider)";
const std::string kCageExpected =
    "expected the name of a surface defined above as the cage (srev, gcyl, birail, bezpatch, bsppatch, mesh, subd)";

/// `count` 3D points "[k 0.5 -k]" separated by spaces, each 1 + ... characters; see point_column.
std::string points(int count) {
  std::string out;
  for (int k = 0; k < count; ++k) {
    if (k > 0) out += ' ';
    // Appending piece by piece: "[" + s + "..." trips GCC 12's false -Wrestrict at -O3.
    out += '[';
    out += std::to_string(k % 10);
    out += " 0 1]";
  }
  return out;
}
/// The column of point k (0-based) in points(): each is "[d 0 1]" (7 characters) plus a space.
int point_column(int k) {
  return 1 + 8 * k;
}

// The cube as a mesh: lines 1 to 3.
const std::string kBox =
    "mesh box 8 6\n[-1 -1 -1] [1 -1 -1] [1 1 -1] [-1 1 -1] [-1 -1 1] [1 -1 1] [1 1 1] [-1 1 1]\n"
    "[0 3 2 1] [4 5 6 7] [0 1 5 4] [3 7 6 2] [0 4 7 3] [1 2 6 5]\n";
// A tetrahedron of triangles: lines 1 to 3.
const std::string kTet = "mesh tet 4 4\n[1 1 1] [1 -1 -1] [-1 1 -1] [-1 -1 1]\n[0 1 2] [0 3 1] [0 2 3] [1 3 2]\n";

TEST(SwpPatchErrors, BezierPatchWithTooFewPoints) {
  // K = 2 asks for 32 points; after 20 the next token is reported.
  expect_error("bezpatch p 4 2\n" + points(20) + "\ncirc c 8 1\n", 3, 1,
               "expected '[' to start point 21 of 32, found 'circ'");
  expect_error("bezpatch p 4 2\n" + points(20) + "\n", 3, 1, "expected '[' to start point 21 of 32, found end of file");
  // A point with two coordinates.
  expect_error("bezpatch p 4 1\n[0 0]", 2, 5, "expected a number (z of point 1 of 16), found ']'");
}

TEST(SwpPatchErrors, PatchWithTooManyPoints) {
  expect_error("bezpatch p 4 1\n" + points(17) + "\n", 2, point_column(16),
               kKeywords + ", found '[' (the bezpatch above already has its 16 points)");
  expect_error("bsppatch p 4 4 5\n" + points(21) + "\n", 2, point_column(20),
               kKeywords + ", found '[' (the bsppatch above already has its 20 points)");
}

TEST(SwpPatchErrors, PatchCounts) {
  expect_error("bezpatch p 4 0", 1, 14, "expected a patch count K, a whole number from 1 to 625000, found '0'");
  expect_error("bezpatch p 4 -2", 1, 14, "expected a patch count K, a whole number from 1 to 625000, found '-2'");
  expect_error("bezpatch p 0 1", 1, 12, "expected STEPS, a whole number from 1 to 100000, found '0'");
  expect_error("bsppatch p 4 3 4", 1, 14, "expected a row count M, a whole number from 4 to 2500000, found '3'");
  expect_error("bsppatch p 4 0 4", 1, 14, "expected a row count M, a whole number from 4 to 2500000, found '0'");
  expect_error("bsppatch p 4 4 3", 1, 16, "expected a column count N, a whole number from 4 to 2500000, found '3'");
  expect_error("bsppatch p 4 4000 4000", 1, 19,
               "expected at most 10000000 control points, found '4000' (M x N is 16000000)");
  expect_error("bsppatch p 4 4 4\n" + points(15), 1 + 1, point_column(14) + 7,
               "expected '[' to start point 16 of 16, found end of file");
}

TEST(SwpPatchErrors, MeshCounts) {
  expect_error("mesh m 2 1", 1, 8, "expected a vertex count NV, a whole number from 3 to 10000000, found '2'");
  expect_error("mesh m 3 0", 1, 10, "expected a face count NF, a whole number from 1 to 10000000, found '0'");
  // Fewer points than NV: the first face is read as a point, then a face is missing.
  expect_error("mesh m 4 1\n[0 0 0] [1 0 0] [0 1 0]\n[0 1 2]\n", 4, 1,
               "expected '[' to start face 1 of 1, found end of file");
}

TEST(SwpPatchErrors, MeshFaceIndexOutOfRange) {
  const std::string head = "mesh m 4 2\n[0 0 0] [1 0 0] [1 1 0] [0 1 0]\n";
  expect_error(head + "[0 1 2] [0 2 4]\n", 3, 14,
               "expected a vertex index of face 2 of 2, a whole number from 0 to 3, found '4'");
  expect_error(head + "[0 1 -1] [0 2 3]\n", 3, 6,
               "expected a vertex index of face 1 of 2, a whole number from 0 to 3, found '-1'");
  expect_error(head + "[0 1 2.5] [0 2 3]\n", 3, 6,
               "expected a vertex index of face 1 of 2, a whole number from 0 to 3, found '2.5'");
}

TEST(SwpPatchErrors, MeshFaceShapes) {
  const std::string head = "mesh m 4 2\n[0 0 0] [1 0 0] [1 1 0] [0 1 0]\n";
  expect_error(head + "[0 1 2] [0 2]\n", 3, 13,
               "expected a vertex index of face 2 of 2, found ']' (a face has at least 3 vertices, this one 2)");
  expect_error(head + "[] [0 1 2]\n", 3, 2,
               "expected a vertex index of face 1 of 2, found ']' (a face has at least 3 vertices, this one 0)");
  expect_error(head + "0 1 2\n", 3, 1, "expected '[' to start face 1 of 2, found '0'");
  // More corners than vertices: the face must end there.
  expect_error(head + "[0 1 2 3 0]\n", 3, 10,
               "expected ']' to end face 1 of 2, found '0' (a face has at most NV vertices)");
  expect_error(head + "[0 1 2", 3, 7,
               "expected a vertex index of face 1 of 2, a whole number from 0 to 3, found end of file");
  expect_error(head + "[0 1 1] [0 2 3]\n", 3, 1, "expected distinct vertices in face 1, found vertex 1 twice");
}

TEST(SwpPatchErrors, NonManifoldCageNamesTheEdgeAndTheFaces) {
  const std::string head = "mesh m 5 3\n[0 0 0] [1 0 0] [1 1 0] [0 1 0] [2 0 0]\n";
  // Edge 0-2 is in faces 1 and 2 (each way), then in face 3: reported at face 3's '['.
  expect_error(head + "[0 1 2]\n[0 2 3]\n[2 0 4]\n", 5, 1,
               "expected a manifold cage, found edge 2-0 in a third face, 3 (after faces 1 and 2)");
  // Face 2 turns the other way round: edge 2-0 runs the same way in faces 1 and 2.
  expect_error("mesh m 4 2\n[0 0 0] [1 0 0] [1 1 0] [0 1 0]\n[0 1 2]\n   [0 3 2]\n", 4, 4,
               "expected a manifold cage, found edge 2-0 running the same way in faces 1 and 2 (neighbouring "
               "faces must turn the same way)");
}

TEST(SwpPatchErrors, MeshWithAnExtraFace) {
  // The faces are counted: one more '[' is where the next object's keyword should be.
  expect_error(kBox + "[0 1 2]\n", 4, 1, kKeywords + ", found '['");
  // Nor does a mesh take clauses.
  expect_error(kBox + "caps\n", 4, 1, kKeywords + ", found 'caps'");
}

TEST(SwpPatchErrors, LevelsOutOfRange) {
  expect_error(kBox + "subd s 7 box\n", 4, 8, "expected LEVELS, a whole number from 0 to 6, found '7'");
  expect_error(kBox + "subd s -1 box\n", 4, 8, "expected LEVELS, a whole number from 0 to 6, found '-1'");
  expect_error(kBox + "subd s two box\n", 4, 8, "expected LEVELS, a whole number from 0 to 6, found 'two'");
}

TEST(SwpPatchErrors, LoopNeedsTriangles) {
  expect_error(kBox + "subd s 1 box loop\n", 4, 14,
               "expected a triangle cage for loop, found 'loop' (face 1 of box has 4 vertices; Catmull-Clark, the "
               "default, takes any polygons)");
  // The first face that is not a triangle is named, and the clause wherever it is.
  expect_error(
      "mesh pyr 5 5\n[-1 -1 0] [1 -1 0] [1 1 0] [-1 1 0] [0 0 1]\n[0 1 4] [0 3 2 1] [1 2 4] [2 3 4] [3 0 4]\n"
      "subd s 1 pyr smooth-boundary LOOP\n",
      4, 30,
      "expected a triangle cage for loop, found 'LOOP' (face 2 of pyr has 4 vertices; Catmull-Clark, the default, "
      "takes any polygons)");
  expect_error("bsp2 p 4 4 [1 0] [2 1] [2 2] [1 3]\nsrev s 8 p\nsubd d 1 s loop\n", 3, 12,
               "expected a triangle cage for loop, found 'loop' (s is a grid of quads (srev); Catmull-Clark, the "
               "default, takes them)");
  expect_error("bsppatch b 2 4 4\n" + points(16) + "\nsubd d 1 b loop\n", 3, 12,
               "expected a triangle cage for loop, found 'loop' (b is a grid of quads (bsppatch); Catmull-Clark, the "
               "default, takes them)");
  // Triangles, or a subd's triangles, are fine.
  EXPECT_EQ(sweep::test::error_of(kTet + "subd s 1 tet loop\nsubd t 1 s loop\n"), "no error");
}

TEST(SwpPatchErrors, SubdClauses) {
  expect_error(kTet + "subd s 1 tet loop loop\n", 4, 19,
               "expected each clause at most once, found 'loop' (already given at line 4, column 14)");
  expect_error(kTet + "subd s 1 tet smooth\n", 4, 14,
               "expected a clause (loop, smooth-boundary, material) or " + kKeywords.substr(9) + ", found 'smooth'");
  // A keyword ends the clauses.
  EXPECT_EQ(sweep::test::error_of(kTet + "subd s 1 tet loop\nsubd t 0 tet\n"), "no error");
}

TEST(SwpPatchErrors, SubdSourceMustBeASurfaceDefinedAbove) {
  expect_error("circ c 8 1\nsubd s 1 c\n", 2, 10, kCageExpected + ", found 'c' (it is a curve (circ))");
  expect_error("bez3 c 8 4 [0 0 0] [1 0 0] [1 1 0] [1 1 1]\nsubd s 1 c\n", 2, 10,
               kCageExpected + ", found 'c' (it is a curve (bez3))");
  expect_error(kBox + "subd s 1 nope\n", 4, 10, kCageExpected + ", found 'nope' (no object has that name)");
  expect_error("subd s 1 box\n" + kBox, 1, 10,
               kCageExpected + ", found 'box' (it is defined further down; references point backwards only)");
  expect_error(kBox + "subd s 1\n", 5, 1, kCageExpected + ", found end of file");
  expect_error(kBox + "subd s 1 [", 4, 10, kCageExpected + ", found '['");
  // A subd cannot be its own cage.
  expect_error(kBox + "subd s 1 s\n", 4, 10, kCageExpected + ", found 's' (no object has that name)");
}

TEST(SwpPatchErrors, SubdSourceDotIsNoName) {
  // As for curves (read_reference): '.' names nothing, even when an anonymous object follows; it
  // is not "defined further down".
  expect_error("subd s 1 .\nmesh . 3 1 [0 0 0] [1 0 0] [0 1 0] [0 1 2]\n", 1, 10,
               kCageExpected + ", found '.' ('.' means no name; only named objects can be referenced)");
}

TEST(SwpPatchErrors, RefinedSubdMustFitTheVertexCap) {
  // A strip of n quads refined 6 times is a (64 n + 1) x 65 grid: n = 12100 gives 50336065
  // vertices, over the cap of 5e7; n = 12000 gives 49920065, under it.
  const auto strip = [](int n) {
    std::string text = "mesh strip ";
    const auto add = [&text](int a, const char* after) {
      text += std::to_string(a);
      text += after;
    };
    add(2 * (n + 1), " ");
    add(n, "\n");
    for (int k = 0; k <= n; ++k) {
      text += '[';
      add(k, " 0 0] [");
      add(k, " 1 0]\n");
    }
    for (int k = 0; k < n; ++k) {
      text += '[';
      add(2 * k, " ");
      add(2 * k + 2, " ");
      add(2 * k + 3, " ");
      add(2 * k + 1, "]\n");
    }
    return text;
  };
  const std::string big = strip(12100);
  expect_error(big + "subd s 6 strip\n", 1 + 12101 + 12100 + 1, 8,
               "expected a surface of at most 50000000 vertices, found '6' (this one would have 50336065)");
  EXPECT_EQ(sweep::test::error_of(big + "subd s 5 strip\n"), "no error");
  EXPECT_EQ(sweep::test::error_of(strip(12000) + "subd s 6 strip\n"), "no error");
}

/// parse(write(doc)) == doc, and writing again gives the same text.
void expect_round_trip(const std::string& text) {
  const sweep::Document doc = sweep::io::parse_swp(text);
  const std::string written = sweep::io::write_swp(doc);
  const sweep::Document again = sweep::io::parse_swp(written);
  EXPECT_EQ(again, doc) << text;
  EXPECT_EQ(sweep::io::write_swp(again), written) << text;
  // Every object starts on the line write_swp says, with its keyword.
  std::vector<int> first_lines;
  (void)sweep::io::write_swp(doc, &first_lines);
  ASSERT_EQ(first_lines.size(), doc.objects.size());
  std::vector<std::string> lines;
  std::istringstream in(written);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  for (std::size_t k = 0; k < doc.objects.size(); ++k) {
    const auto line = static_cast<std::size_t>(first_lines[k]);
    ASSERT_LE(line, lines.size());
    EXPECT_EQ(lines[line - 1].rfind(std::string(sweep::keyword(doc.objects[k].kind())) + " ", 0), 0u)
        << "object " << k << " at line " << line << ": " << lines[line - 1];
    EXPECT_EQ(again.objects[k].location.line, first_lines[k]);
  }
}

TEST(SwpPatchRoundTrip, EveryNewKindRoundTrips) {
  expect_round_trip("bezpatch p 3 1\n" + points(16) + "\n");
  expect_round_trip("bezpatch p 7 2 " + points(32) + " bezpatch . 1 1 " + points(16));
  expect_round_trip("bezpatch q 2 1 [0.1 -2.5e-3 1e12] [1 2 3] [-0 0 0] [0.3333333333333333 0.1 0.2] " + points(12) +
                    "\n");
  expect_round_trip("bsppatch b 5 4 5\n" + points(20) + "\n");
  expect_round_trip(kBox);
  expect_round_trip(
      "mesh pyr 5 5\n[-1 -1 0] [1 -1 0] [1 1 0] [-1 1 0] [0 0 1]\n[0 1 4] [0 3 2 1] [1 2 4] [2 3 4] [3 0 4]\n");
  expect_round_trip(kBox + "subd s 2 box\n");
  expect_round_trip(kBox + "subd s 0 box smooth-boundary\n");
  expect_round_trip(kTet + "subd s 1 tet loop\nsubd t 3 s\n");
  expect_round_trip(kTet + "subd s 6 tet LOOP Smooth-Boundary\nsubd . 1 s smooth-boundary loop\n");
  expect_round_trip("bsp2 p 4 4 [1 0] [2 1] [2 2] [1 3]\nsrev s 8 p\nsubd d 1 s\nsubd e 2 d smooth-boundary\n");
  expect_round_trip("bsppatch b 2 4 4\n" + points(16) + "\nsubd d 1 b\n");
}

TEST(SwpPatchRoundTrip, WrittenFormOfTheNewKinds) {
  const sweep::Document doc =
      sweep::io::parse_swp(kTet + "subd s 2 tet SMOOTH-BOUNDARY Loop\nbsppatch b 2 4 4 " + points(16) + "\n");
  ASSERT_EQ(doc.objects.size(), 3u);
  const sweep::Object& mesh = doc.objects[0];
  EXPECT_EQ(mesh.kind(), sweep::ObjectKind::PolygonMesh);
  EXPECT_EQ(mesh.as<sweep::PointsPart>().points.size(), 4u);
  EXPECT_EQ(mesh.as<sweep::PolygonMeshSurface>().face_sizes, (std::vector<int>{3, 3, 3, 3}));
  EXPECT_EQ(mesh.as<sweep::PolygonMeshSurface>().face_vertices, (std::vector<int>{0, 1, 2, 0, 3, 1, 0, 2, 3, 1, 3, 2}));
  const sweep::Object& subd = doc.objects[1];
  EXPECT_EQ(subd.kind(), sweep::ObjectKind::Subdivision);
  EXPECT_EQ(subd.as<sweep::SubdivisionSurface>().levels, 2);
  EXPECT_EQ(subd.as<sweep::SubdivisionSurface>().source, 0);
  EXPECT_TRUE(subd.as<sweep::SubdivisionSurface>().loop);
  EXPECT_TRUE(subd.as<sweep::SubdivisionSurface>().smooth_boundary);
  const sweep::Object& patch = doc.objects[2];
  EXPECT_EQ(patch.as<sweep::BSplinePatchSurface>().rows, 4);
  EXPECT_EQ(patch.as<sweep::BSplinePatchSurface>().columns, 4);
  EXPECT_EQ(patch.as<sweep::StepsPart>().steps, 2);
  const std::string text = sweep::io::write_swp(doc);
  // Header lines with the counts, clauses in the table's order and lower case, one point or
  // face a line.
  EXPECT_NE(text.find("mesh tet 4 4\n[1 1 1]\n[1 -1 -1]\n[-1 1 -1]\n[-1 -1 1]\n[0 1 2]\n[0 3 1]\n[0 2 3]\n[1 3 2]\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("subd s 2 tet loop smooth-boundary\n"), std::string::npos) << text;
  EXPECT_NE(text.find("bsppatch b 2 4 4\n[0 0 1]\n[1 0 1]\n"), std::string::npos) << text;
  // Default clauses are not written.
  EXPECT_NE(sweep::io::write_swp(sweep::io::parse_swp(kBox + "subd s 2 box\n")).find("subd s 2 box\n"),
            std::string::npos);
  EXPECT_EQ(sweep::io::write_swp(sweep::io::parse_swp("bezpatch p 4 2 " + points(32))).substr(0, 15),
            "bezpatch p 4 2\n");
}

}  // namespace
