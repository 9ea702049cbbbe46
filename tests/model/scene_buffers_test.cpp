// What evaluation spends memory on: texture coordinates only for the surfaces that show an image
// (or for every surface when asked, as exports do), and re-evaluation into the same scene that
// reuses each surface's buffers and gives exactly what a fresh evaluation gives.
#include "io/swp/read.hpp"
#include "model/evaluation/scene.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using sweep::Document;
using sweep::EvaluationOptions;
using sweep::Mesh;
using sweep::Scene;
using sweep::TextureCoordinates;

// 0 material, 1 profile, 2 sweep, 3 plain gcyl, 4 textured gcyl, 5 plain srev, 6 textured srev,
// 7 plain patch (a net object: box-projected uvs).
const char* const kText =
    "material tiles checker 4\n"
    "bez2 profile 4 4 [-1 1] [-2 0.5] [-2 -0.5] [-1 -1]\n"
    "circ sweep 24 3\n"
    "gcyl plain profile sweep\n"
    "gcyl tiled profile sweep material tiles\n"
    "srev vase 16 profile\n"
    "srev tiledvase 16 profile material tiles\n"
    "bezpatch flat 4 1\n"
    "[0 0 0] [1 0 0] [2 0 0] [3 0 0]\n"
    "[0 1 0] [1 1 1] [2 1 1] [3 1 0]\n"
    "[0 2 0] [1 2 1] [2 2 1] [3 2 0]\n"
    "[0 3 0] [1 3 0] [2 3 0] [3 3 0]\n";

bool has_uvs(const Mesh& mesh) {
  return !mesh.positions.empty() && mesh.uvs.size() == mesh.positions.size();
}

void expect_same_mesh(const Mesh& a, const Mesh& b, const std::string& what) {
  EXPECT_EQ(a.positions, b.positions) << what;
  EXPECT_EQ(a.normals, b.normals) << what;
  EXPECT_EQ(a.indices, b.indices) << what;
  EXPECT_EQ(a.uvs, b.uvs) << what;
}

TEST(SceneBuffers, OnlyTexturedSurfacesGetTextureCoordinatesByDefault) {
  const Document doc = sweep::io::parse_swp(kText, "uvs.swp");
  ASSERT_EQ(doc.objects.size(), 8u);
  const Scene scene = sweep::evaluate_document(doc);
  EXPECT_TRUE(scene.objects[3].mesh.uvs.empty());
  EXPECT_TRUE(has_uvs(scene.objects[4].mesh));
  EXPECT_TRUE(scene.objects[5].mesh.uvs.empty());
  EXPECT_TRUE(has_uvs(scene.objects[6].mesh));
  EXPECT_TRUE(scene.objects[7].mesh.uvs.empty());
  // The textured surfaces' seams are split for the image; the plain ones keep the grid.
  EXPECT_GT(scene.objects[4].mesh.vertex_count(), scene.objects[3].mesh.vertex_count());
}

TEST(SceneBuffers, EverywhereGivesEverySurfaceItsTextureCoordinatesAndChangesNothingElse) {
  const Document doc = sweep::io::parse_swp(kText, "uvs.swp");
  const Scene plain = sweep::evaluate_document(doc);
  EvaluationOptions options;
  options.texture_coordinates = TextureCoordinates::Everywhere;
  const Scene all = sweep::evaluate_document(doc, options);
  for (const std::size_t i : {3u, 4u, 5u, 6u, 7u}) {
    EXPECT_TRUE(has_uvs(all.objects[i].mesh)) << i;
    EXPECT_EQ(all.objects[i].mesh.positions, plain.objects[i].mesh.positions) << i;
    EXPECT_EQ(all.objects[i].mesh.indices, plain.objects[i].mesh.indices) << i;
  }
  expect_same_mesh(all.objects[4].mesh, plain.objects[4].mesh, "a textured surface is the same either way");
}

/// Gives each of the mesh's arrays room for four times its size: a builder that reserves its
/// own exact size keeps that room only if it fills these same buffers.
void make_room(Mesh& mesh) {
  mesh.positions.reserve(4 * mesh.positions.size());
  mesh.normals.reserve(4 * mesh.normals.size());
  mesh.indices.reserve(4 * mesh.indices.size());
  mesh.uvs.reserve(4 * mesh.uvs.size());
}

TEST(SceneBuffers, ReevaluatingAnEditReusesTheSurfacesBuffersAndMatchesAFreshEvaluation) {
  Document doc = sweep::io::parse_swp(kText, "uvs.swp");
  Scene scene = sweep::evaluate_document(doc);
  for (const std::size_t i : {3u, 4u, 5u, 6u}) make_room(scene.objects[i].mesh);
  const Mesh& tube = scene.objects[3].mesh;
  const Mesh& tiled = scene.objects[4].mesh;
  const Mesh& vase = scene.objects[5].mesh;
  const glm::vec3* tube_positions = tube.positions.data();
  const std::size_t room = tube.positions.capacity();

  doc.objects[1].as<sweep::PointsPart>().points[1].x = -2.5;  // a drag of the profile
  sweep::reevaluate(scene, doc, 1);
  EXPECT_EQ(tube.positions.data(), tube_positions);
  EXPECT_EQ(tube.positions.capacity(), room);
  EXPECT_GE(tube.normals.capacity(), 4 * tube.normals.size());
  EXPECT_GE(tube.indices.capacity(), 4 * tube.indices.size());
  EXPECT_GE(tiled.uvs.capacity(), 2 * tiled.uvs.size());  // the seam copies come on top of the grid
  EXPECT_GE(vase.positions.capacity(), 4 * vase.positions.size());
  EXPECT_GE(vase.indices.capacity(), 4 * vase.indices.size());

  const Scene fresh = sweep::evaluate_document(doc);
  for (std::size_t i = 3; i < doc.objects.size(); ++i) {
    expect_same_mesh(scene.objects[i].mesh, fresh.objects[i].mesh, "object " + std::to_string(i));
  }
}

TEST(SceneBuffers, AReevaluationAtFewerStepsLeavesNothingOfTheLargerMesh) {
  Document doc = sweep::io::parse_swp(kText, "uvs.swp");
  Scene scene = sweep::evaluate_document(doc);
  const std::size_t before = scene.objects[3].mesh.vertex_count();
  doc.objects[2].as<sweep::StepsPart>().steps = 6;    // the sweep circle from 24 to 6 steps
  doc.objects[5].as<sweep::CopiesPart>().copies = 5;  // the vase from 16 copies to 5
  sweep::reevaluate_all(scene, doc);
  const Scene fresh = sweep::evaluate_document(doc);
  EXPECT_LT(scene.objects[3].mesh.vertex_count(), before);
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    expect_same_mesh(scene.objects[i].mesh, fresh.objects[i].mesh, "object " + std::to_string(i));
    EXPECT_EQ(scene.objects[i].curve.frames.size(), fresh.objects[i].curve.frames.size()) << i;
  }
}

TEST(SceneBuffers, ReevaluateAllBumpsEveryRevision) {
  const Document doc = sweep::io::parse_swp(kText, "uvs.swp");
  Scene scene = sweep::evaluate_document(doc);
  const Scene before = scene;
  sweep::reevaluate_all(scene, doc);
  for (std::size_t i = 0; i < doc.objects.size(); ++i) EXPECT_GT(scene.objects[i].revision, before.objects[i].revision);
}

}  // namespace
