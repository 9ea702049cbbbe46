// OBJ import (mesh/obj_import.hpp): OBJ files written here from known cages read back as the same
// `mesh` object, whatever index form they use; the object survives SWP text; every kind of bad
// file gets its one message.
#include "io/mesh/obj_import.hpp"

#include "geometry/subdivision/subdivision.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/file_limits.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <filesystem>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace {

/// A cage as the tests write it: faces of 0-based indices, counterclockwise seen from outside.
struct TestCage {
  std::vector<glm::dvec3> points;
  std::vector<std::vector<int>> faces;
};

/// The unit cube: 8 corners, 6 quads.
TestCage cube() {
  return {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}},
          {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {0, 4, 7, 3}}};
}

/// A square pyramid: a quad base and 4 triangles, with coordinates that are not short decimals.
TestCage pyramid() {
  return {{{-0.1, -0.2, 0.3}, {1.0 / 3.0, -0.25, 0.0}, {0.7, 2.0 / 3.0, 1e-7}, {-1e-3, 0.9, -0.0}, {0.2, 0.3, 1.5e3}},
          {{0, 3, 2, 1}, {0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}}};
}

/// How faces name their corners.
enum class IndexForm {
  Plain,        // f 1 2 3
  Full,         // f 1/1/1 2/2/2 3/3/3
  NormalOnly,   // f 1//1 2//2 3//3
  TextureOnly,  // f 1/1 2/2 3/3
  Relative,     // f -8 -7 -6 (all vertices come first)
};

std::string number(double value) {
  char buffer[40];
  return {buffer, std::to_chars(buffer, buffer + sizeof buffer, value).ptr};
}

std::string vertex_line(const glm::dvec3& p) {
  return "v " + number(p.x) + " " + number(p.y) + " " + number(p.z) + "\n";
}

/// OBJ text for a cage: all vertices (with a texture coordinate and a normal each when the form
/// uses them), then the faces.
std::string obj_text(const TestCage& cage, IndexForm form = IndexForm::Plain) {
  std::string text = "# written by obj_import_test\n";
  for (const glm::dvec3& p : cage.points) text += vertex_line(p);
  for (std::size_t i = 0; i < cage.points.size(); ++i) {
    if (form == IndexForm::Full || form == IndexForm::TextureOnly) text += "vt 0.25 0.75\n";
    if (form == IndexForm::Full || form == IndexForm::NormalOnly) text += "vn 0 0 1\n";
  }
  const auto count = static_cast<int>(cage.points.size());
  for (const std::vector<int>& face : cage.faces) {
    text += "f";
    for (const int v : face) {
      // Appended piece by piece: GCC 12 warns wrongly (-Wrestrict) about " " + std::string.
      const std::string i = std::to_string(form == IndexForm::Relative ? v - count : v + 1);
      text += ' ';
      text += i;
      if (form == IndexForm::Full || form == IndexForm::TextureOnly) text.append("/").append(i);
      if (form == IndexForm::NormalOnly) text.append("//").append(i);
      if (form == IndexForm::Full) text.append("/").append(i);
    }
    text += "\n";
  }
  return text;
}

/// Expects `mesh` to be the `mesh` object of `cage`: the same points and faces, in order.
void expect_cage(const sweep::Object& mesh, const TestCage& cage) {
  EXPECT_EQ(mesh.kind(), sweep::ObjectKind::PolygonMesh);
  EXPECT_EQ(mesh.as<sweep::PointsPart>().points, cage.points);
  std::vector<int> sizes;
  std::vector<int> vertices;
  for (const std::vector<int>& face : cage.faces) {
    sizes.push_back(static_cast<int>(face.size()));
    vertices.insert(vertices.end(), face.begin(), face.end());
  }
  EXPECT_EQ(mesh.as<sweep::PolygonMeshSurface>().face_sizes, sizes);
  EXPECT_EQ(mesh.as<sweep::PolygonMeshSurface>().face_vertices, vertices);
}

sweep::Object parse(const std::string& text, const std::string& name = "cage") {
  return sweep::io::parse_obj_cage(text, "cage.obj", name);
}

/// The message parsing `text` as "bad.obj" throws; "no error" if it reads.
std::string error_of(const std::string& text) {
  try {
    (void)sweep::io::parse_obj_cage(text, "bad.obj", "cage");
  } catch (const sweep::io::ImportError& e) {
    return e.what();
  }
  return "no error";
}

using sweep::test::write_text;

TEST(ObjImport, CubeReadsAsItsPointsAndQuads) {
  const sweep::Object mesh = parse(obj_text(cube()), "box");
  EXPECT_EQ(mesh.name, "box");
  expect_cage(mesh, cube());
  EXPECT_FALSE(sweep::check_cage(sweep::cage_of(mesh)).has_value());
}

TEST(ObjImport, TrianglesAndQuadsTogether) {
  expect_cage(parse(obj_text(pyramid())), pyramid());
}

TEST(ObjImport, EveryIndexFormGivesTheSameCage) {
  for (const IndexForm form :
       {IndexForm::Plain, IndexForm::Full, IndexForm::NormalOnly, IndexForm::TextureOnly, IndexForm::Relative}) {
    SCOPED_TRACE(obj_text(cube(), form));
    expect_cage(parse(obj_text(cube(), form)), cube());
    expect_cage(parse(obj_text(pyramid(), form)), pyramid());
  }
}

TEST(ObjImport, RelativeIndicesCountBackFromTheirOwnLine) {
  // Each quad's 4 vertices just before it, each face `f -4 -3 -2 -1`: two separate squares.
  TestCage squares;
  std::string text;
  for (int square = 0; square < 2; ++square) {
    std::vector<int> face;
    for (int k = 0; k < 4; ++k) {
      const glm::dvec3 p(k == 1 || k == 2 ? 1.0 : 0.0, k >= 2 ? 1.0 : 0.0, square);
      text += vertex_line(p);
      face.push_back(static_cast<int>(squares.points.size()));
      squares.points.push_back(p);
    }
    text += "f -4 -3 -2 -1\n";
    squares.faces.push_back(face);
  }
  expect_cage(parse(text), squares);
}

TEST(ObjImport, GroupsObjectsAndMaterialsAllGoIntoTheOneMesh) {
  const TestCage c = cube();
  std::string text = "mtllib does-not-exist.mtl\n";
  for (const glm::dvec3& p : c.points) text += vertex_line(p);
  for (std::size_t f = 0; f < c.faces.size(); ++f) {
    if (f == 0) text += "o first\n";
    if (f == 2) text += "g side\nusemtl red\n";
    if (f == 3) text += "s 1\n";
    if (f == 4) text += "o second\ng other\nusemtl blue\n";
    text += "f";
    for (const int v : c.faces[f]) text.append(" ").append(std::to_string(v + 1));
    text += "\n";
  }
  expect_cage(parse(text), c);
}

TEST(ObjImport, UnusedVerticesKeepTheirPlaceAndCrlfLinesRead) {
  TestCage c = cube();
  c.points.push_back({5, 5, 5});  // used by no face
  std::string text = obj_text(c);
  std::string crlf;
  for (const char ch : text) crlf += ch == '\n' ? std::string("\r\n") : std::string(1, ch);
  expect_cage(parse(text), c);
  expect_cage(parse(crlf), c);
}

TEST(ObjImport, CoordinatesAreReadCorrectlyRounded) {
  // Shortest round-trip digits must give back the same doubles (tinyobjloader's own number
  // parser misses about half of these by an ulp).
  std::mt19937_64 random(20240607);
  std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-8, 11);
  TestCage c = cube();
  for (glm::dvec3& p : c.points) {
    for (int axis = 0; axis < 3; ++axis) p[axis] = mantissa(random) * std::pow(10.0, exponent(random));
  }
  for (int extra = 0; extra < 500; ++extra) {
    c.points.push_back({mantissa(random), mantissa(random) * 1e6, mantissa(random) * 1e-6});
  }
  expect_cage(parse(obj_text(c)), c);
}

TEST(ObjImport, ThroughSwpTextTheObjectStaysTheSame) {
  for (const TestCage& c : {cube(), pyramid()}) {
    sweep::Document doc;
    doc.objects.push_back(parse(obj_text(c, IndexForm::Full)));
    const sweep::Document back = sweep::io::parse_swp(sweep::io::write_swp(doc), "back.swp");
    ASSERT_EQ(back.objects.size(), 1u);
    EXPECT_EQ(back.objects[0], doc.objects[0]);
    expect_cage(back.objects[0], c);
  }
}

TEST(ObjImport, FileIsReadAndNamedInMessages) {
  sweep::test::ScratchFolder folder("sweep-obj-import");
  const std::filesystem::path path = folder.path() / "pyramid.obj";
  write_text(path, obj_text(pyramid(), IndexForm::NormalOnly));
  expect_cage(sweep::io::import_obj_cage(path, "p"), pyramid());

  const std::filesystem::path bad = folder.path() / "bad.obj";
  write_text(bad, "v 0 0 0\nv 1 0 0\nf 1 2\n");
  try {
    (void)sweep::io::import_obj_cage(bad, "p");
    ADD_FAILURE() << "no error";
  } catch (const sweep::io::ImportError& e) {
    EXPECT_EQ(std::string(e.what()), bad.string() + ":3: expected at least 3 vertices in face 1, found 2");
  }

  const std::filesystem::path missing = folder.path() / "missing.obj";
  try {
    (void)sweep::io::import_obj_cage(missing, "p");
    ADD_FAILURE() << "no error";
  } catch (const sweep::io::ImportError& e) {
    EXPECT_EQ(std::string(e.what()), missing.string() + ": cannot open: No such file or directory");
  }
  try {
    (void)sweep::io::import_obj_cage(folder.path(), "p");
    ADD_FAILURE() << "no error";
  } catch (const sweep::io::ImportError& e) {
    EXPECT_EQ(std::string(e.what()), folder.path().string() + ": cannot open: it is a directory");
  }
}

TEST(ObjImport, FacesOfTooFewOrTooManyVertices) {
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  EXPECT_EQ(error_of(square + "f 1 2 3\nf 1 3\n"), "bad.obj:6: expected at least 3 vertices in face 2, found 2");
  EXPECT_EQ(error_of(square + "f 1 2 3\nf \n"), "bad.obj:6: expected at least 3 vertices in face 2, found 0");

  // A polygon of kMaxObjFaceVertices corners reads; one more does not.
  for (const int n : {sweep::io::kMaxObjFaceVertices, sweep::io::kMaxObjFaceVertices + 1}) {
    TestCage disk;
    disk.faces.emplace_back();
    for (int k = 0; k < n; ++k) {
      const double angle = 2.0 * std::numbers::pi * k / n;
      disk.points.push_back({std::cos(angle), std::sin(angle), 0.0});
      disk.faces[0].push_back(k);
    }
    if (n <= sweep::io::kMaxObjFaceVertices) {
      expect_cage(parse(obj_text(disk)), disk);
    } else {
      EXPECT_EQ(error_of(obj_text(disk)), "bad.obj:" + std::to_string(n + 2) + ": expected at most " +
                                              std::to_string(sweep::io::kMaxObjFaceVertices) +
                                              " vertices in face 1 (tinyobjloader's limit), found " +
                                              std::to_string(n));
    }
  }
}

TEST(ObjImport, IndicesThatNameNoVertex) {
  const std::string square = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
  EXPECT_EQ(error_of(square + "f 1 2 3\nf 1 3 5\n"),
            "bad.obj:6: expected a vertex index from 1 to 4 in face 2, found '5'");
  EXPECT_EQ(error_of(square + "f 1/1/1 2/1/1 9/1/1\n"),
            "bad.obj:5: expected a vertex index from 1 to 4 in face 1, found '9'");
  EXPECT_EQ(error_of(square + "f -1 -2 -5\n"),
            "bad.obj:5: expected a relative vertex index from -1 to -4 in face 1, found '-5'");
  // Relative to the vertices before the line, not to all of them.
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 1 1 0\n"),
            "bad.obj:3: expected a relative vertex index from -1 to -2 in face 1, found '-3'");
  EXPECT_EQ(error_of("f -1 -2 -3\nv 0 0 0\nv 1 0 0\nv 1 1 0\n"),
            "bad.obj:1: expected a vertex ('v' line) before the relative vertex index in face 1, found '-1'");
  EXPECT_EQ(error_of(square + "f 1 2 99999999999\n"),
            "bad.obj:5: expected a vertex index in face 1, found '99999999999'");
  // Index 0 is tinyobjloader's error, passed on.
  EXPECT_EQ(error_of(square + "f 1 2 3\nf 0 1 2\n"),
            "bad.obj: Failed parse `f' line(e.g. zero value for face index. line 6.)");
}

TEST(ObjImport, CagesThatAreNotManifold) {
  // check_cage's messages, with the face's line in front and vertices numbered as in the file.
  const std::string five = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n";
  // Three faces on edge 1-2: faces 1 and 2 use it both ways, face 3 once more.
  EXPECT_EQ(error_of(five + "f 1 2 3\nf 2 1 4\nf 1 2 5\n"),
            "bad.obj:8: expected a manifold cage, found edge 1-2 in a third face, 3 (after faces 1 and 2)");
  EXPECT_EQ(error_of(five + "f 1 2 3\nf 1 2 4\n"),
            "bad.obj:7: expected a manifold cage, found edge 1-2 running the same way in faces 1 and 2 (neighbouring "
            "faces must turn the same way)");
  EXPECT_EQ(error_of(five + "f 1 2 3\nf 4 2 1 2\n"),
            "bad.obj:7: expected distinct vertices in face 2, found vertex 2 twice");
  // Relative indices are named by the vertices they resolve to.
  EXPECT_EQ(error_of(five + "f -5 -4 -3\nf -5 -4 -2\n"),
            "bad.obj:7: expected a manifold cage, found edge 1-2 running the same way in faces 1 and 2 (neighbouring "
            "faces must turn the same way)");
}

TEST(ObjImport, FilesWithoutVerticesOrFaces) {
  EXPECT_EQ(error_of(""), "bad.obj: expected at least one vertex ('v' line)");
  EXPECT_EQ(error_of("# nothing\nf 1 2 3\n"), "bad.obj: expected at least one vertex ('v' line)");
  EXPECT_EQ(error_of("v 0 0 0\nv 1 0 0\nv 0 1 0\nl 1 2 3\n"), "bad.obj: expected at least one face ('f' line)");
}

TEST(ObjImport, CoordinatesThatAreNotNumbersOrTooLarge) {
  EXPECT_EQ(error_of("v 0 0 0\nv nan 0 0\n"),
            "bad.obj:2: expected a number from -1e12 to 1e12 as x of vertex 2, found 'nan'");
  EXPECT_EQ(error_of("v 0 inf 0\n"), "bad.obj:1: expected a number from -1e12 to 1e12 as y of vertex 1, found 'inf'");
  EXPECT_EQ(error_of("v 0 0 1e400\n"),
            "bad.obj:1: expected a number from -1e12 to 1e12 as z of vertex 1, found '1e400'");
  EXPECT_EQ(error_of("v 0 -1.5e12 0\n"),
            "bad.obj:1: expected a number from -1e12 to 1e12 as y of vertex 1, found '-1.5e12'");
  EXPECT_EQ(error_of("v 0 abc 0\n"), "bad.obj:1: expected a number from -1e12 to 1e12 as y of vertex 1, found 'abc'");
  EXPECT_EQ(error_of("v 1 2\n"), "bad.obj:1: expected 3 coordinates (x y z) of vertex 1, found 2");
  // Line numbers count "\r\n" and "\r" line ends as tinyobjloader does.
  EXPECT_EQ(error_of("v 0 0 0\r\nv 1 0 0\rv 1 1 0\r\nv 0 x 0\n"),
            "bad.obj:4: expected a number from -1e12 to 1e12 as y of vertex 4, found 'x'");
  // At the cap itself a coordinate reads; a leading '+' and a 4th value (w) are allowed.
  const sweep::Object mesh = parse("v 1e12 -1e12 +0.5 1\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(mesh.as<sweep::PointsPart>().points[0], glm::dvec3(1e12, -1e12, 0.5));
}

TEST(ObjImport, VerticesAndCornersTogetherAtMostTheSwpCap) {
  // 3 vertices, then faces of kMaxObjFaceVertices corners (repeated vertices are only checked
  // after the caps) until the total passes kMaxControlPoints.
  const std::int64_t per_face = sweep::io::kMaxObjFaceVertices;
  const std::int64_t faces = (sweep::limits::kMaxControlPoints - 3) / per_face + 1;
  std::string face = "f";
  for (std::int64_t k = 0; k < per_face; ++k) face += " 1";
  face += "\n";
  std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  text.reserve(text.size() + static_cast<std::size_t>(faces) * face.size());
  for (std::int64_t f = 0; f < faces; ++f) text += face;
  EXPECT_EQ(error_of(text), "bad.obj:" + std::to_string(3 + faces) + ": expected at most " +
                                std::to_string(sweep::limits::kMaxControlPoints) +
                                " vertices and face corners in all, found " + std::to_string(3 + faces * per_face) +
                                " by this line");
}

TEST(ObjImport, InvalidNameIsRefused) {
  EXPECT_THROW((void)parse(obj_text(cube()), "1cube"), std::invalid_argument);
  EXPECT_THROW((void)parse(obj_text(cube()), ""), std::invalid_argument);
}

TEST(ObjImport, ObjectNameFromTheFileName) {
  EXPECT_EQ(sweep::io::object_name_from_path("cages/cube.obj"), "cube");
  EXPECT_EQ(sweep::io::object_name_from_path("my-cage.v2.obj"), "my-cage.v2");
  EXPECT_EQ(sweep::io::object_name_from_path("2 cubes.obj"), "_2_cubes");
  EXPECT_EQ(sweep::io::object_name_from_path("_x.OBJ"), "_x");
  EXPECT_EQ(sweep::io::object_name_from_path("w\xc3\xbcrfel.obj"), "w__rfel");
  EXPECT_EQ(sweep::io::object_name_from_path(".obj"), "_.obj");
  EXPECT_EQ(sweep::io::object_name_from_path(std::string(300, 'a') + ".obj"),
            std::string(sweep::limits::kMaxNameLength, 'a'));
  for (const char* path : {"", "/", "-.obj", "a b/c d", "...", "\x01\x7f.obj", "9.obj"}) {
    EXPECT_TRUE(sweep::is_valid_object_name(sweep::io::object_name_from_path(path))) << path;
  }
}

}  // namespace
