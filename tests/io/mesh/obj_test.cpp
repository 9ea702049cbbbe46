// OBJ output read back by a small independent OBJ reader: counts, 1-based indices in range,
// values equal to the mesh after a float round trip; every starter surface saved to a file.
// (Texture coordinates, materials and tinyobjloader: mtl_export_test.cpp.)
#include "io/mesh/obj_writer.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"

#include "support/core_test_support.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <sstream>

namespace {

/// One corner of a face: 1-based indices as written, 0 where absent.
struct Corner {
  long v = 0;
  long vt = 0;
  long vn = 0;
};

/// What a minimal OBJ reader makes of a file: the statements sweep writes without a material
/// (v, vt, vn, f, #) and an error for anything it cannot read.
struct ObjData {
  std::vector<glm::vec3> v;
  std::vector<glm::vec2> vt;
  std::vector<glm::vec3> vn;
  std::vector<std::vector<Corner>> faces;
  std::vector<std::string> comments;
  std::string error;  // empty if the text was read completely
};

bool read_float(const std::string& word, float& out) {
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), out);
  return ec == std::errc() && end == word.data() + word.size();
}

bool read_index(const std::string& word, long& out) {
  if (word.empty()) return false;
  const auto [end, ec] = std::from_chars(word.data(), word.data() + word.size(), out);
  return ec == std::errc() && end == word.data() + word.size() && out != 0;
}

ObjData read_obj(const std::string& text) {
  ObjData obj;
  std::istringstream lines(text);
  std::string line;
  int number = 0;
  while (std::getline(lines, line)) {
    ++number;
    const std::string where = "line " + std::to_string(number) + ": ";
    if (line.empty()) continue;
    if (line[0] == '#') {
      obj.comments.push_back(line.substr(line.size() > 1 && line[1] == ' ' ? 2 : 1));
      continue;
    }
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    std::vector<std::string> args;
    for (std::string w; words >> w;) args.push_back(w);
    if (tag == "v" || tag == "vn") {
      glm::vec3 value;
      if (args.size() != 3 || !read_float(args[0], value.x) || !read_float(args[1], value.y) ||
          !read_float(args[2], value.z)) {
        obj.error = where + "bad " + tag;
        return obj;
      }
      (tag == "v" ? obj.v : obj.vn).push_back(value);
    } else if (tag == "vt") {
      glm::vec2 value;
      if (args.size() != 2 || !read_float(args[0], value.x) || !read_float(args[1], value.y)) {
        obj.error = where + "bad vt";
        return obj;
      }
      obj.vt.push_back(value);
    } else if (tag == "f") {
      if (args.size() < 3) {
        obj.error = where + "face with fewer than 3 corners";
        return obj;
      }
      std::vector<Corner> face;
      for (const std::string& a : args) {
        Corner c;
        const std::size_t s1 = a.find('/');
        const std::size_t s2 = s1 == std::string::npos ? std::string::npos : a.find('/', s1 + 1);
        bool ok = read_index(a.substr(0, s1), c.v);
        if (ok && s1 != std::string::npos) {
          const std::string vt = a.substr(s1 + 1, s2 == std::string::npos ? std::string::npos : s2 - s1 - 1);
          if (!vt.empty()) ok = read_index(vt, c.vt);
          if (ok && s2 != std::string::npos) ok = read_index(a.substr(s2 + 1), c.vn);
        }
        if (!ok) {
          obj.error = where + "bad corner '" + a + "'";
          return obj;
        }
        face.push_back(c);
      }
      obj.faces.push_back(face);
    } else {
      obj.error = where + "unknown statement '" + tag + "'";
      return obj;
    }
  }
  return obj;
}

/// The first way in which a face is not a triangle whose corners reference an existing v and vn
/// (1-based, no negative indices) with the same index for both, as sweep writes them, and the
/// same vt when the file has texture coordinates (none otherwise); empty if there is none.
/// "" if every face is a triangle (or, with `polygons`, has at least 3 corners) of valid v//vn
/// pairs or v/vt/vn triples.
std::string reference_problem(const ObjData& obj, bool polygons = false) {
  if (!obj.error.empty()) return obj.error;
  const auto nv = static_cast<long>(obj.v.size());
  const auto nn = static_cast<long>(obj.vn.size());
  for (std::size_t f = 0; f < obj.faces.size(); ++f) {
    if (polygons ? obj.faces[f].size() < 3 : obj.faces[f].size() != 3) {
      return "face " + std::to_string(f) + " is not a " + (polygons ? "polygon" : "triangle");
    }
    for (const Corner& c : obj.faces[f]) {
      const bool vt_ok = obj.vt.empty() ? c.vt == 0 : c.vt == c.v;
      if (c.v < 1 || c.v > nv || c.vn < 1 || c.vn > nn || !vt_ok || c.v != c.vn) {
        return "face " + std::to_string(f) + " corner " + std::to_string(c.v) + "//" + std::to_string(c.vn);
      }
    }
  }
  return "";
}

sweep::Mesh small_mesh() {
  // A tetrahedron with awkward floats: every value must survive text and back exactly.
  sweep::Mesh mesh;
  mesh.positions = {{0.1f, 1.0f / 3.0f, -0.0f},
                    {1e-8f, -2.5f, 7.0f},
                    {std::numeric_limits<float>::max(), std::numeric_limits<float>::denorm_min(), 123456.789f},
                    {-1.0f, 2.0f / 3.0f, std::nextafter(1.0f, 2.0f)}};
  mesh.normals = {glm::normalize(glm::vec3(1, 1, 1)), glm::normalize(glm::vec3(-1, 0.3f, 0)), glm::vec3(0, 0, 1),
                  glm::normalize(glm::vec3(0.2f, -0.7f, 0.1f))};
  mesh.indices = {0, 1, 2, 0, 3, 1, 1, 3, 2, 2, 3, 0};
  return mesh;
}

TEST(Obj, TextReadsBackToTheSameMesh) {
  const sweep::Mesh mesh = small_mesh();
  const ObjData obj = read_obj(sweep::io::obj_text(mesh));
  ASSERT_EQ(obj.error, "");
  ASSERT_EQ(obj.v.size(), mesh.positions.size());
  ASSERT_EQ(obj.vn.size(), mesh.normals.size());
  ASSERT_EQ(obj.faces.size(), mesh.triangle_count());
  EXPECT_EQ(reference_problem(obj), "");
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    for (int k = 0; k < 3; ++k) {
      EXPECT_EQ(obj.v[i][k], mesh.positions[i][k]) << "v " << i << " " << k;
      EXPECT_EQ(std::signbit(obj.v[i][k]), std::signbit(mesh.positions[i][k])) << "v " << i << " " << k;
      EXPECT_EQ(obj.vn[i][k], mesh.normals[i][k]) << "vn " << i << " " << k;
    }
  }
  for (std::size_t t = 0; t < obj.faces.size(); ++t) {
    for (std::size_t k = 0; k < 3; ++k) EXPECT_EQ(obj.faces[t][k].v, static_cast<long>(mesh.indices[3 * t + k]) + 1);
  }
  EXPECT_TRUE(obj.comments.empty());
}

TEST(Obj, CommentComesFirst) {
  const std::string text = sweep::io::obj_text(small_mesh(), "made by a test");
  EXPECT_EQ(text.rfind("# made by a test\n", 0), 0u);
  const ObjData obj = read_obj(text);
  ASSERT_EQ(obj.comments.size(), 1u);
  EXPECT_EQ(obj.comments[0], "made by a test");
  EXPECT_EQ(obj.v.size(), 4u);
}

TEST(Obj, EmptyMeshIsEmptyText) {
  EXPECT_EQ(sweep::io::obj_text(sweep::Mesh{}), "");
  const ObjData obj = read_obj(sweep::io::obj_text(sweep::Mesh{}, "nothing"));
  EXPECT_EQ(obj.error, "");
  EXPECT_TRUE(obj.v.empty() && obj.vn.empty() && obj.faces.empty());
}

TEST(Obj, ReaderRejectsWhatItShould) {
  // The reader itself must be able to fail, or the tests above prove nothing.
  EXPECT_NE(read_obj("v 1 2\n").error, "");
  EXPECT_NE(read_obj("f 1//1 2//x 3//3\n").error, "");
  EXPECT_NE(read_obj("vt 0\n").error, "");
  EXPECT_NE(read_obj("vp 0 0\n").error, "");
  EXPECT_EQ(reference_problem(read_obj("v 0 0 0\nvt 0 0\nvn 0 0 1\nf 1//1 1//1 1//1\n")), "face 0 corner 1//1");
  EXPECT_EQ(reference_problem(read_obj("v 0 0 0\nvt 0 0\nvn 0 0 1\nf 1/1/1 1/1/1 1/1/1\n")), "");
  EXPECT_EQ(reference_problem(read_obj("v 0 0 0\nvn 0 0 1\nf 1//1 2//1 1//1\n")), "face 0 corner 2//1");
  EXPECT_EQ(reference_problem(read_obj("v 0 0 0\nvn 0 0 1\nf 1//1 1//1 1//2\n")), "face 0 corner 1//2");
  EXPECT_EQ(reference_problem(read_obj("v 0 0 0\nvn 0 0 1\nf 1//1 1//1 1//1 1//1\n")), "face 0 is not a triangle");
  EXPECT_EQ(reference_problem(read_obj("v 0 0 0\nvn 0 0 1\nf 1//1 1//1 1//1\n")), "");
}

using sweep::test::read_file;
using sweep::test::ScratchFolder;

TEST(ObjFile, EveryStarterSurfaceSavesToAValidFile) {
  const ScratchFolder folder("sweep-obj");
  int surfaces = 0;
  for (const auto& file : sweep::test::starter_files()) {
    const sweep::Document doc = sweep::io::load_swp_file(file);
    const sweep::Scene scene = sweep::evaluate_document(doc);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      if (!sweep::is_surface(doc.objects[i].kind())) continue;
      ++surfaces;
      const std::string what = file.filename().string() + " " + sweep::display_name(doc, static_cast<int>(i));
      const sweep::Mesh& mesh = scene.objects[i].mesh;
      const std::filesystem::path path = folder.path() / (file.stem().string() + "_" + std::to_string(i) + ".obj");
      sweep::io::save_obj_file(path, mesh, what);
      const std::string text = read_file(path);
      ASSERT_FALSE(text.empty()) << what;
      EXPECT_EQ(text.back(), '\n') << what;
      EXPECT_EQ(text, sweep::io::obj_text(mesh, what)) << what;
      const ObjData obj = read_obj(text);
      EXPECT_EQ(obj.v.size(), mesh.vertex_count()) << what;
      EXPECT_EQ(obj.vn.size(), mesh.vertex_count()) << what;
      EXPECT_EQ(obj.vt.size(), mesh.uvs.size()) << what;
      // A cage (mesh) keeps its polygons; every other surface is triangles.
      const bool polygons = !mesh.polygon_sizes.empty();
      EXPECT_EQ(obj.faces.size(), polygons ? mesh.polygon_sizes.size() : mesh.triangle_count()) << what;
      EXPECT_EQ(reference_problem(obj, polygons), "") << what;
      for (std::size_t k = 0; k < obj.vn.size(); ++k) {
        ASSERT_NEAR(glm::length(obj.vn[k]), 1.0f, 1e-5f) << what << " vn " << k;
      }
    }
  }
  EXPECT_GT(surfaces, 0);
}

TEST(ObjFile, NonFiniteMeshIsRefusedAndTheOldFileKept) {
  const ScratchFolder folder("sweep-obj");
  const std::filesystem::path path = folder.path() / "kept.obj";
  sweep::io::save_obj_file(path, small_mesh());
  const std::string before = read_file(path);
  sweep::Mesh broken = small_mesh();
  broken.positions[2].y = std::numeric_limits<float>::quiet_NaN();
  EXPECT_FALSE(sweep::io::mesh_is_finite(broken));
  try {
    sweep::io::save_obj_file(path, broken);
    FAIL() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + path.string() + ": the mesh has a NaN or infinite coordinate");
  }
  EXPECT_EQ(read_file(path), before);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"kept.obj"});
}

}  // namespace
