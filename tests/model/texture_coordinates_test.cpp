// Texture coordinates through the pipeline (parse_swp + evaluate_document): one finite uv per
// vertex on every surface kind; on swept grids u runs along the profile's arc length from 0 to 1,
// v along the sweep in the same units (square cells; a whole number of repeats around a closed
// sweep); a textured material splits closed seams so no triangle runs the texture backwards; caps
// and box-projected surfaces (patches, cages, subds) get finite uvs in sensible ranges.
#include "geometry/surfaces/texture_coordinates.hpp"
#include "geometry/surfaces/surface.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"

#include "support/core_test_support.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

namespace {

using sweep::Document;
using sweep::Mesh;
using sweep::Scene;

/// Every surface's texture coordinates, as an export asks for them.
Scene evaluate(const Document& doc, double tolerance = 0.0) {
  sweep::EvaluationOptions options;
  options.tolerance = tolerance;
  options.texture_coordinates = sweep::TextureCoordinates::Everywhere;
  return sweep::evaluate_document(doc, options);
}

/// The mesh of the object named `name` in `text` (parsed as "uv.swp").
Mesh mesh_of(const std::string& text, const char* name, double tolerance = 0.0) {
  const Document doc = sweep::io::parse_swp(text, "uv.swp");
  const int index = doc.find(name);
  EXPECT_GE(index, 0) << name;
  return evaluate(doc, tolerance).objects.at(static_cast<std::size_t>(index)).mesh;
}

void expect_finite_uvs(const Mesh& mesh, const std::string& what) {
  ASSERT_EQ(mesh.uvs.size(), mesh.positions.size()) << what;
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size()) << what;
  for (std::size_t k = 0; k < mesh.uvs.size(); ++k) {
    ASSERT_TRUE(std::isfinite(mesh.uvs[k].x) && std::isfinite(mesh.uvs[k].y)) << what << " vertex " << k;
  }
}

/// The largest difference in u (or v) between two corners of one triangle.
float largest_triangle_extent(const Mesh& mesh, int axis) {
  float largest = 0.0f;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    float lo = mesh.uvs[mesh.indices[t]][axis], hi = lo;
    for (std::size_t k = 1; k < 3; ++k) {
      lo = std::min(lo, mesh.uvs[mesh.indices[t + k]][axis]);
      hi = std::max(hi, mesh.uvs[mesh.indices[t + k]][axis]);
    }
    largest = std::max(largest, hi - lo);
  }
  return largest;
}

/// The first vertex (below `before`) at exactly this position, or -1.
int original_at(const Mesh& mesh, const glm::vec3& p, std::size_t before) {
  for (std::size_t k = 0; k < before; ++k) {
    if (mesh.positions[k] == p) return static_cast<int>(k);
  }
  return -1;
}

/// Length of the polygon through a closed curve's samples (its last sample is its first).
double polygon_length(const sweep::CurveSamples& curve) {
  double length = 0.0;
  for (std::size_t i = 1; i < curve.frames.size(); ++i)
    length += glm::distance(curve.frames[i - 1].V, curve.frames[i].V);
  return length;
}

// A circle profile of 16 samples around, a straight sweep of 4 pieces x 3 steps (13 rings) along
// z from 0 to 6, an open profile, a closed sweep, a cage and a patch.
const std::string kCurves =
    "circ c 16 0.5\n"
    "bez3 line 3 13 [0 0 0] [0 0 0.5] [0 0 1] [0 0 1.5] [0 0 2] [0 0 2.5] [0 0 3] [0 0 3.5] [0 0 4] [0 0 4.5] "
    "[0 0 5] [0 0 5.5] [0 0 6]\n"
    "bez2 prof 4 4 [0.5 0] [1.5 0.5] [0.5 1.5] [1 3]\n"
    "circ loop 24 2\n";
const std::string kCage =
    "mesh cage 8 6 [0 0 0] [4 0 0] [4 2 0] [0 2 0] [0 0 1] [4 0 1] [4 2 1] [0 2 1]\n"
    "[0 3 2 1] [4 5 6 7] [0 1 5 4] [1 2 6 5] [2 3 7 6] [3 0 4 7]\n";
const std::string kPatchPoints =
    "[0 0 0] [1 0 0] [2 0 0] [3 0 0] [0 1 0.5] [1 1 0.5] [2 1 0.5] [3 1 0.5] "
    "[0 2 0.5] [1 2 0.5] [2 2 0.5] [3 2 0.5] [0 3 0] [1 3 0] [2 3 0] [3 3 0]";

/// Every surface kind, each with `clause` (e.g. " material m") after its fixed fields.
std::string every_surface(const std::string& clause) {
  std::string text = kCurves;
  text += "material m checker 4\nbez3 rail2 3 4 [3 0 0] [3 0 2] [3 0 4] [3 0 6]\n";
  for (const char* surface :
       {"srev rev 12 prof", "srev revc 12 prof caps", "gcyl open prof line", "gcyl tube c line",
        "gcyl capped c line caps", "gcyl torus c loop", "gcyl ribbon prof loop", "birail bi prof line rail2"}) {
    (text += surface) += clause;
    text += '\n';
  }
  ((text += "bezpatch bp 4 1") += clause) += ' ';
  (text += kPatchPoints) += '\n';
  ((text += "bsppatch sp 3 4 4") += clause) += ' ';
  (text += kPatchPoints) += '\n';
  ((text += kCage.substr(0, 13)) += clause) += kCage.substr(13);  // after "mesh cage 8 6"
  for (const char* subd : {"subd sdm 2 cage", "subd sdg 1 tube", "subd sdl 1 sdm loop"}) {
    (text += subd) += clause;
    text += '\n';
  }
  return text;
}

TEST(TextureCoordinates, EverySurfaceKindGetsOneFiniteUvPerVertex) {
  for (const std::string clause : {"", " material m"}) {
    const std::string text = every_surface(clause);
    const Document doc = sweep::io::parse_swp(text, "uv.swp");
    for (const double tolerance : {0.0, 0.01}) {
      const Scene scene = evaluate(doc, tolerance);
      int surfaces = 0;
      for (std::size_t i = 0; i < doc.objects.size(); ++i) {
        if (!sweep::is_surface(doc.objects[i].kind())) {
          EXPECT_TRUE(scene.objects[i].mesh.uvs.empty()) << doc.objects[i].name;
          continue;
        }
        ++surfaces;
        const Mesh& mesh = scene.objects[i].mesh;
        ASSERT_GT(mesh.vertex_count(), 0u) << doc.objects[i].name;
        expect_finite_uvs(mesh, doc.objects[i].name + clause + " tolerance " + std::to_string(tolerance));
        if (!clause.empty()) {
          EXPECT_EQ(doc.objects[i].as<sweep::MaterialPart>().material, 4) << doc.objects[i].name;
        }
      }
      EXPECT_EQ(surfaces, 14);
    }
  }
}

TEST(TextureCoordinates, EveryStarterSurfaceGetsFiniteUvs) {
  for (const auto& file : sweep::test::starter_files()) {
    const Document doc = sweep::io::load_swp_file(file);
    const Scene scene = evaluate(doc);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      if (!sweep::is_surface(doc.objects[i].kind())) continue;
      expect_finite_uvs(scene.objects[i].mesh,
                        file.filename().string() + " " + sweep::display_name(doc, static_cast<int>(i)));
    }
  }
}

TEST(TextureCoordinates, URunsFrom0To1AlongAnOpenProfile) {
  const Document doc = sweep::io::parse_swp(kCurves + "gcyl open prof line\n", "uv.swp");
  const Scene scene = evaluate(doc);
  const Mesh& mesh = scene.objects[4].mesh;
  const std::size_t ring = scene.objects[2].curve.frames.size();   // 4 steps of 1 piece: 5
  const std::size_t rings = scene.objects[1].curve.frames.size();  // 13
  ASSERT_EQ(ring, 5u);
  ASSERT_EQ(rings, 13u);
  ASSERT_EQ(
      static_cast<std::int64_t>(mesh.vertex_count()),
      sweep::cylinder_vertex_count(static_cast<std::int64_t>(ring), false, static_cast<std::int64_t>(rings), false));
  expect_finite_uvs(mesh, "open");
  for (std::size_t j = 0; j < rings; ++j) {
    EXPECT_EQ(mesh.uvs[j * ring].x, 0.0f) << j;
    EXPECT_FLOAT_EQ(mesh.uvs[j * ring + ring - 1].x, 1.0f) << j;
    for (std::size_t i = 1; i < ring; ++i) {
      EXPECT_GT(mesh.uvs[j * ring + i].x, mesh.uvs[j * ring + i - 1].x) << j << " " << i;
      EXPECT_EQ(mesh.uvs[j * ring + i].y, mesh.uvs[j * ring].y) << "one v per ring";
    }
    if (j > 0) {
      EXPECT_GT(mesh.uvs[j * ring].y, mesh.uvs[(j - 1) * ring].y) << j;
    }
  }
  EXPECT_EQ(mesh.uvs[0].y, 0.0f);
}

TEST(TextureCoordinates, UFollowsTheProfilesArcLength) {
  // Uneven chords: a straight sweep carries the profile unchanged, so every ring's u steps are
  // the profile's chord lengths over its length.
  const Document doc = sweep::io::parse_swp(
      kCurves + "bez2 uneven 3 7 [0 0] [0.1 0] [0.2 0] [0.3 0] [1 0.5] [2 0.5] [3 1]\ngcyl g uneven line\n", "uv.swp");
  const Scene scene = evaluate(doc);
  const auto& profile = scene.objects[4].curve.frames;
  const Mesh& mesh = scene.objects[5].mesh;
  const std::size_t ring = profile.size();
  ASSERT_EQ(ring, 7u);
  std::vector<double> chord(ring, 0.0);
  double length = 0.0;
  for (std::size_t i = 1; i < ring; ++i) {
    chord[i] = glm::distance(profile[i - 1].V, profile[i].V);
    length += chord[i];
  }
  // The chords really differ (else this test proves nothing).
  EXPECT_GT(*std::max_element(chord.begin() + 1, chord.end()), 3.0 * *std::min_element(chord.begin() + 1, chord.end()));
  const std::size_t rings = mesh.vertex_count() / ring;
  ASSERT_EQ(rings, 13u);
  for (std::size_t j = 0; j < rings; ++j) {
    double expected = 0.0;
    for (std::size_t i = 1; i < ring; ++i) {
      expected += chord[i] / length;
      const double du = mesh.uvs[j * ring + i].x - mesh.uvs[j * ring + i - 1].x;
      EXPECT_NEAR(du, chord[i] / length, 1e-5) << j << " " << i;
      EXPECT_NEAR(mesh.uvs[j * ring + i].x, expected, 1e-5) << j << " " << i;
    }
  }
}

TEST(TextureCoordinates, VMakesSquareCellsAlongAStraightSweep) {
  const Document doc = sweep::io::parse_swp(kCurves + "gcyl tube c line\n", "uv.swp");
  const Scene scene = evaluate(doc);
  const Mesh& mesh = scene.objects[4].mesh;
  const double circumference = polygon_length(scene.objects[0].curve);  // of the sampled circle
  EXPECT_NEAR(circumference, std::numbers::pi, 0.03);                   // 2 pi 0.5, a 16-gon
  const std::size_t ring = 16;
  ASSERT_EQ(mesh.vertex_count(), ring * 13);
  const double length = 6.0;
  for (std::size_t i = 0; i < ring; ++i) {
    EXPECT_EQ(mesh.uvs[i].y, 0.0f);
    const double v_end = mesh.uvs[12 * ring + i].y;
    EXPECT_NEAR(v_end, length / circumference, 1e-3 * length / circumference) << i;
  }
  // Each ring's v is its distance along the sweep over the circumference (the line's samples
  // are 0.5 apart).
  for (std::size_t j = 0; j < 13; ++j) {
    EXPECT_NEAR(mesh.uvs[j * ring].y, 0.5 * static_cast<double>(j) / circumference, 1e-5) << j;
  }
  // u around the ring: equal steps of 1/16 on a regular polygon.
  for (std::size_t i = 0; i < ring; ++i) EXPECT_NEAR(mesh.uvs[i].x, static_cast<double>(i) / 16.0, 1e-5) << i;
}

struct SeamSplit {
  Mesh plain;
  Mesh textured;
};

SeamSplit both_ways(const std::string& curves, const std::string& surface, const std::string& material) {
  const Document plain = sweep::io::parse_swp(curves + surface + "\n", "uv.swp");
  const Document textured = sweep::io::parse_swp(curves + material + "\n" + surface + " material m\n", "uv.swp");
  return {evaluate(plain).objects.back().mesh, evaluate(textured).objects.back().mesh};
}

/// The copies past `grid` vertices: same position and normal as a grid vertex, which they
/// return; `moved` says which coordinates differ.
void expect_copies_of_grid(const Mesh& mesh, std::size_t grid) {
  for (std::size_t k = grid; k < mesh.vertex_count(); ++k) {
    const int original = original_at(mesh, mesh.positions[k], grid);
    ASSERT_GE(original, 0) << "copy " << k << " has no original";
    const auto o = static_cast<std::size_t>(original);
    EXPECT_EQ(mesh.normals[k], mesh.normals[o]) << k;
    EXPECT_NE(mesh.uvs[k], mesh.uvs[o]) << k;
  }
}

TEST(TextureCoordinates, ATexturedClosedProfileSplitsItsSeam) {
  const SeamSplit s = both_ways(kCurves, "gcyl tube c line", "material m checker 4");
  const std::size_t ring = 16, rings = 13;
  const auto formula =
      static_cast<std::size_t>(sweep::cylinder_vertex_count(17, true, static_cast<std::int64_t>(rings), false));
  ASSERT_EQ(formula, ring * rings);
  // Without a texture: as built, and the seam strip runs u back from 15/16 to 0.
  EXPECT_EQ(s.plain.vertex_count(), formula);
  EXPECT_GT(largest_triangle_extent(s.plain, 0), 0.9f);
  // With one: one copy of every seam vertex (one per ring), at u = 1.
  ASSERT_EQ(s.textured.vertex_count(), formula + rings);
  EXPECT_EQ(s.textured.triangle_count(), s.plain.triangle_count());
  expect_finite_uvs(s.textured, "textured tube");
  for (std::size_t k = 0; k < formula; ++k) {
    ASSERT_EQ(s.textured.positions[k], s.plain.positions[k]) << k;
    ASSERT_EQ(s.textured.normals[k], s.plain.normals[k]) << k;
    ASSERT_EQ(s.textured.uvs[k], s.plain.uvs[k]) << k;
  }
  expect_copies_of_grid(s.textured, formula);
  std::vector<int> copies_of(formula, 0);
  for (std::size_t k = formula; k < s.textured.vertex_count(); ++k) {
    const auto o = static_cast<std::size_t>(original_at(s.textured, s.textured.positions[k], formula));
    EXPECT_EQ(o % ring, 0u) << "a copy of a seam vertex";
    EXPECT_EQ(s.textured.uvs[o].x, 0.0f);
    EXPECT_EQ(s.textured.uvs[k].x, 1.0f);
    EXPECT_EQ(s.textured.uvs[k].y, s.textured.uvs[o].y);
    ++copies_of[o];
  }
  for (std::size_t j = 0; j < rings; ++j) EXPECT_EQ(copies_of[j * ring], 1) << j;
  EXPECT_LT(largest_triangle_extent(s.textured, 0), 0.5f);
  // The split changes no triangle's corners in space.
  for (std::size_t t = 0; t < s.plain.indices.size(); ++t) {
    ASSERT_EQ(s.textured.positions[s.textured.indices[t]], s.plain.positions[s.plain.indices[t]]) << t;
  }
}

TEST(TextureCoordinates, OnlyImagesSplitSeams) {
  // A colour alone leaves the mesh as built; a texture, a checker or a bump splits the seams.
  const sweep::test::ScratchFolder folder("sweep-uv");
  sweep::test::write_tiny_png(folder.path() / "b.png");
  const std::string file = (folder.path() / "uv.swp").string();
  const auto count = [&file](const std::string& material) {
    const Document doc = sweep::io::parse_swp(kCurves + material + "\ngcyl tube c line material m\n", file);
    return evaluate(doc).objects.back().mesh.vertex_count();
  };
  const std::size_t grid = 16 * 13;
  EXPECT_EQ(count("material m"), grid);
  EXPECT_EQ(count("material m color 1 0 0 shininess 3"), grid);
  EXPECT_EQ(count("material m checker 1"), grid + 13);
  EXPECT_EQ(count("material m texture b.png"), grid + 13);
  EXPECT_EQ(count("material m bump b.png 0.1"), grid + 13);
  EXPECT_EQ(count("material m color 1 0 0 texture b.png bump b.png 0.1"), grid + 13);
}

TEST(TextureCoordinates, ASurfaceOfRevolutionSplitsItsTurn) {
  // The turn is closed: a textured srev of an open profile gets one copy of every vertex of the
  // first copy of the profile, at the last whole v.
  const SeamSplit s = both_ways(kCurves, "srev rev 12 prof", "material m checker 2");
  const std::size_t ring = 5, copies = 12;
  const auto formula = static_cast<std::size_t>(sweep::revolution_vertex_count(5, false, 12));
  ASSERT_EQ(formula, ring * copies);
  EXPECT_EQ(s.plain.vertex_count(), formula);
  ASSERT_EQ(s.textured.vertex_count(), formula + ring);
  EXPECT_GT(largest_triangle_extent(s.plain, 1), largest_triangle_extent(s.textured, 1) * 3.0f);
  expect_copies_of_grid(s.textured, formula);
  const float v_end = s.textured.uvs[formula].y;
  EXPECT_GE(v_end, 1.0f);
  EXPECT_EQ(v_end, std::round(v_end)) << "a whole number of repeats around the turn";
  for (std::size_t k = formula; k < s.textured.vertex_count(); ++k) {
    const auto o = static_cast<std::size_t>(original_at(s.textured, s.textured.positions[k], formula));
    EXPECT_LT(o, ring) << "a copy of the first ring";
    EXPECT_EQ(s.textured.uvs[o].y, 0.0f);
    EXPECT_EQ(s.textured.uvs[k].y, v_end);
    EXPECT_EQ(s.textured.uvs[k].x, s.textured.uvs[o].x);
  }
  // v grows ring by ring up to the last one, which is short of v_end by one step.
  for (std::size_t j = 1; j < copies; ++j) EXPECT_GT(s.textured.uvs[j * ring].y, s.textured.uvs[(j - 1) * ring].y);
  EXPECT_LT(s.textured.uvs[(copies - 1) * ring].y, v_end);
}

TEST(TextureCoordinates, AClosedSweepEndsOnAWholeNumber) {
  // A torus: closed profile (16) and closed sweep (24). The corner vertex needs three copies
  // (u moved, v moved, both), every other seam vertex one.
  const SeamSplit s = both_ways(kCurves, "gcyl torus c loop", "material m checker 4");
  const std::size_t ring = 16, rings = 24;
  const auto formula = static_cast<std::size_t>(sweep::cylinder_vertex_count(17, true, 25, true));
  ASSERT_EQ(formula, ring * rings);
  EXPECT_EQ(s.plain.vertex_count(), formula);
  ASSERT_EQ(s.textured.vertex_count(), formula + ring + rings + 1);
  expect_copies_of_grid(s.textured, formula);
  EXPECT_LT(largest_triangle_extent(s.textured, 0), 0.5f);
  float v_end = 0.0f;
  int u_moved = 0, v_moved = 0, both = 0;
  for (std::size_t k = formula; k < s.textured.vertex_count(); ++k) {
    const auto o = static_cast<std::size_t>(original_at(s.textured, s.textured.positions[k], formula));
    const bool du = s.textured.uvs[k].x != s.textured.uvs[o].x;
    const bool dv = s.textured.uvs[k].y != s.textured.uvs[o].y;
    if (du) {
      EXPECT_EQ(s.textured.uvs[o].x, 0.0f);
      EXPECT_EQ(s.textured.uvs[k].x, 1.0f);
    }
    if (dv) {
      EXPECT_EQ(s.textured.uvs[o].y, 0.0f);
      v_end = s.textured.uvs[k].y;
    }
    u_moved += du && !dv;
    v_moved += dv && !du;
    both += du && dv;
  }
  EXPECT_EQ(u_moved, static_cast<int>(rings));
  EXPECT_EQ(v_moved, static_cast<int>(ring));
  EXPECT_EQ(both, 1);
  // The sweep is about 2 pi 2 long, the profile 2 pi 0.5: four repeats.
  EXPECT_EQ(v_end, 4.0f);
  for (std::size_t k = formula; k < s.textured.vertex_count(); ++k) {
    const auto o = static_cast<std::size_t>(original_at(s.textured, s.textured.positions[k], formula));
    if (s.textured.uvs[k].y != s.textured.uvs[o].y) {
      EXPECT_EQ(s.textured.uvs[k].y, v_end) << k;
    }
  }
  // Every triangle spans less than half the v range, too.
  EXPECT_LT(largest_triangle_extent(s.textured, 1), 0.5f * v_end);
  EXPECT_GT(largest_triangle_extent(s.plain, 1), 0.9f * v_end);
}

TEST(TextureCoordinates, AdaptiveSamplingSplitsTheSameWay) {
  const Document doc = sweep::io::parse_swp(kCurves + "material m checker 4\ngcyl tube c line material m\n", "uv.swp");
  const Scene scene = evaluate(doc, 0.001);
  const Mesh& mesh = scene.objects.back().mesh;
  expect_finite_uvs(mesh, "adaptive tube");
  EXPECT_LT(largest_triangle_extent(mesh, 0), 0.5f);
  float u_max = 0.0f;
  for (const auto& uv : mesh.uvs) u_max = std::max(u_max, uv.x);
  EXPECT_EQ(u_max, 1.0f);
}

TEST(TextureCoordinates, CapsGetFiniteUvsInTheProfilesUnits) {
  for (const std::string material : {"", " material m"}) {
    const Document doc =
        sweep::io::parse_swp(kCurves + "material m checker 4\ngcyl capped c line caps" + material + "\n", "uv.swp");
    const Scene scene = evaluate(doc);
    const Mesh& mesh = scene.objects.back().mesh;
    const std::size_t grid = 16 * 13;
    ASSERT_GT(mesh.vertex_count(), grid);
    expect_finite_uvs(mesh, "caps" + material);
    const double circumference = polygon_length(scene.objects[0].curve);
    // The cap vertices (after the grid, before any seam copies) on each end: a disk of diameter
    // 1, so their uvs span at most 1 / circumference in each direction (square cells).
    std::map<bool, std::vector<glm::vec2>> by_end;  // far end?
    for (std::size_t k = grid; k < mesh.vertex_count(); ++k) {
      if (std::abs(glm::dot(mesh.normals[k], glm::vec3(0.0f, 0.0f, 1.0f))) > 0.99f)
        by_end[mesh.positions[k].z > 3.0f].push_back(mesh.uvs[k]);
    }
    ASSERT_EQ(by_end.size(), 2u) << material;
    for (const auto& [z, uvs] : by_end) {
      glm::vec2 lo = uvs.front(), hi = lo;
      for (const glm::vec2& uv : uvs) {
        lo = glm::min(lo, uv);
        hi = glm::max(hi, uv);
      }
      for (int axis = 0; axis < 2; ++axis) {
        EXPECT_LE(hi[axis] - lo[axis], 1.0 / circumference + 1e-5) << z;
        EXPECT_GE(hi[axis] - lo[axis], std::cos(std::numbers::pi / 16.0) / circumference - 1e-5) << z;
      }
    }
  }
  // srev caps too (the profile's ends are off the axis).
  const Mesh rev = mesh_of(kCurves + "material m checker 4\nsrev r 12 prof caps material m\n", "r");
  ASSERT_GT(rev.vertex_count(), 5u * 12u + 5u);
  expect_finite_uvs(rev, "srev caps");
}

TEST(TextureCoordinates, BoxProjectionSpansTheLongestSide) {
  // The cage is 4 x 2 x 1: u along x from 0 to 1, v along y from 0 to 0.5 (same scale).
  const Mesh cage = mesh_of(kCurves + kCage, "cage");
  ASSERT_EQ(cage.vertex_count(), 8u);
  expect_finite_uvs(cage, "cage");
  for (std::size_t k = 0; k < 8; ++k) {
    EXPECT_FLOAT_EQ(cage.uvs[k].x, cage.positions[k].x / 4.0f) << k;
    EXPECT_FLOAT_EQ(cage.uvs[k].y, cage.positions[k].y / 4.0f) << k;
  }
  const auto range = [](const Mesh& mesh, int axis) {
    float lo = mesh.uvs.front()[axis], hi = lo;
    for (const glm::vec2& uv : mesh.uvs) {
      lo = std::min(lo, uv[axis]);
      hi = std::max(hi, uv[axis]);
    }
    return std::pair<float, float>(lo, hi);
  };
  EXPECT_EQ(range(cage, 0), (std::pair<float, float>(0.0f, 1.0f)));
  EXPECT_EQ(range(cage, 1), (std::pair<float, float>(0.0f, 0.5f)));
  // Its subdivision is smaller than the cage but spans its own box the same way.
  const Mesh smooth = mesh_of(kCurves + kCage + "material m checker 4\nsubd s 2 cage material m\n", "s");
  expect_finite_uvs(smooth, "subd");
  EXPECT_EQ(range(smooth, 0).first, 0.0f);
  EXPECT_FLOAT_EQ(range(smooth, 0).second, 1.0f);
  EXPECT_GT(range(smooth, 1).second, 0.2f);
  EXPECT_LT(range(smooth, 1).second, 0.8f);
  // A patch 3 x 3 x 0.5: its uvs fill the unit square, with no split for a textured material.
  const Mesh plain = mesh_of(kCurves + "bezpatch p 4 1 " + kPatchPoints + "\n", "p");
  const Mesh patch = mesh_of(kCurves + "material m checker 4\nbezpatch p 4 1 material m " + kPatchPoints + "\n", "p");
  EXPECT_EQ(patch.vertex_count(), plain.vertex_count());
  EXPECT_EQ(patch.uvs, plain.uvs);
  EXPECT_EQ(range(patch, 0).first, 0.0f);
  EXPECT_FLOAT_EQ(range(patch, 0).second, 1.0f);
  EXPECT_EQ(range(patch, 1).first, 0.0f);
  EXPECT_FLOAT_EQ(range(patch, 1).second, 1.0f);
}

TEST(TextureCoordinates, DirectCallsOnDegenerateInput) {
  // An empty mesh, and a layout that does not fit the mesh, fall back to the box projection.
  Mesh empty;
  sweep::add_box_texture_coordinates(empty);
  EXPECT_TRUE(empty.uvs.empty());
  Mesh point;
  point.positions = {glm::vec3(1.0f, 2.0f, 3.0f), glm::vec3(1.0f, 2.0f, 3.0f)};
  point.normals = {glm::vec3(0.0f, 0.0f, 1.0f), glm::vec3(0.0f, 0.0f, 1.0f)};
  sweep::add_box_texture_coordinates(point);
  ASSERT_EQ(point.uvs.size(), 2u);
  EXPECT_EQ(point.uvs[0], glm::vec2(0.0f));
  sweep::GridLayout too_big;
  too_big.ring = 4;
  too_big.rings = 4;
  sweep::add_grid_texture_coordinates(point, too_big, true);
  ASSERT_EQ(point.uvs.size(), 2u);
  EXPECT_EQ(point.vertex_count(), 2u);
}

}  // namespace
