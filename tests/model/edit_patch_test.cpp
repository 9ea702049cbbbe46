// Editing patches, cages and subdivision surfaces: points move (every copy of a shared patch
// point together, so nothing tears), nets keep their shape (no insert or delete), a subd's level
// and clauses change within what the reader accepts, and every refusal is an exact EditError
// that leaves the document as it was.
#include "model/edit/edit.hpp"

#include "geometry/mesh/mesh_topology.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/evaluation/scene.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <functional>
#include <string>

namespace {

using glm::dvec3;
using sweep::Document;
using sweep::EditError;
using sweep::SurfaceFlag;

using sweep::test::edit_error;

const char* const kCubeAndTetra =
    "mesh cube 8 6\n[-1 -1 -1] [1 -1 -1] [1 1 -1] [-1 1 -1] [-1 -1 1] [1 -1 1] [1 1 1] [-1 1 1]\n"
    "[0 3 2 1] [4 5 6 7] [0 1 5 4] [1 2 6 5] [2 3 7 6] [3 0 4 7]\n"
    "subd smooth 2 cube\n"
    "mesh tet 4 4 [1 1 1] [1 -1 -1] [-1 1 -1] [-1 -1 1] [0 1 2] [0 3 1] [0 2 3] [1 3 2]\n"
    "subd round 1 tet\n";

TEST(EditPatch, MovingASharedTeapotPointMovesEveryCopyAndKeepsTheSeamsWelded) {
  Document doc = sweep::test::load_starter("teapot.swp");
  const sweep::Scene before = sweep::evaluate_document(doc);
  const std::vector<dvec3>& points = doc.objects[0].as<sweep::PointsPart>().points;
  // The rim's first point is also the body's first (their patches share that edge).
  const dvec3 shared = points[0];
  std::vector<int> copies;
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (points[i] == shared) copies.push_back(static_cast<int>(i));
  }
  ASSERT_GE(copies.size(), 2u);
  const dvec3 to = shared + dvec3(0.0, 0.3, 0.0);
  sweep::move_point(doc, 0, copies.back(), to);
  for (const int i : copies)
    EXPECT_EQ(doc.objects[0].as<sweep::PointsPart>().points[static_cast<std::size_t>(i)], to) << i;
  const sweep::Scene after = sweep::evaluate_document(doc);
  EXPECT_EQ(after.objects[0].mesh.vertex_count(), before.objects[0].mesh.vertex_count());
  EXPECT_EQ(sweep::mesh_topology(after.objects[0].mesh).boundary_edges,
            sweep::mesh_topology(before.objects[0].mesh).boundary_edges);
  // Saved and read back, the moved point is there.
  EXPECT_EQ(sweep::io::parse_swp(sweep::io::write_swp(doc), "t.swp"), doc);
}

TEST(EditPatch, MovingACagePointReshapesItsSubdivisionSurface) {
  Document doc = sweep::io::parse_swp(kCubeAndTetra, "t.swp");
  sweep::Scene scene = sweep::evaluate_document(doc);
  const glm::vec3 top_before = scene.objects[1].mesh.positions[6];  // the cage's vertices come first
  sweep::move_point(doc, 0, 6, dvec3(2.0, 2.0, 2.0));
  const std::vector<int> changed = sweep::reevaluate(scene, doc, 0);
  EXPECT_EQ(changed, (std::vector<int>{0, 1}));
  const glm::vec3 top_after = scene.objects[1].mesh.positions[6];
  EXPECT_GT(top_after.x, top_before.x);
  EXPECT_GT(top_after.z, top_before.z);
}

TEST(EditPatch, NetsKeepTheirShape) {
  Document doc = sweep::test::load_starter("teapot.swp");
  EXPECT_EQ(edit_error(doc, [&] { sweep::delete_point(doc, 0, 3); }),
            "'teapot' is a surface (bezpatch) with a fixed net of points: they can be moved, not inserted or deleted");
  Document cage = sweep::io::parse_swp(kCubeAndTetra, "t.swp");
  EXPECT_EQ(edit_error(cage, [&] { sweep::delete_point(cage, 0, 0); }),
            "'cube' is a surface (mesh) with a fixed net of points: they can be moved, not inserted or deleted");
  EXPECT_EQ(edit_error(cage, [&] { sweep::set_steps_or_levels(cage, 0, 4); }),
            "surface 'cube' is a polygon cage (mesh): it has no STEPS");
}

TEST(EditPatch, LevelsRunFromZeroToSix) {
  Document doc = sweep::io::parse_swp(kCubeAndTetra, "t.swp");
  for (int level : {0, 3, 6}) {
    sweep::set_steps_or_levels(doc, 1, level);
    EXPECT_EQ(doc.objects[1].as<sweep::SubdivisionSurface>().levels, level);
    EXPECT_NO_THROW(sweep::io::validate_document(doc));
  }
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_steps_or_levels(doc, 1, 7); }), "LEVELS must be from 0 to 6, not 7");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_steps_or_levels(doc, 1, -1); }), "LEVELS must be from 0 to 6, not -1");
  // A patch's STEPS is its samples per side.
  Document teapot = sweep::test::load_starter("teapot.swp");
  sweep::set_steps_or_levels(teapot, 0, 4);
  EXPECT_EQ(sweep::evaluate_document(teapot).objects[0].mesh.triangle_count(), 32u * 4u * 4u * 2u - 8u * 4u);
}

TEST(EditPatch, LoopNeedsATriangleCage) {
  Document doc = sweep::io::parse_swp(kCubeAndTetra, "t.swp");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_surface_flag(doc, 1, SurfaceFlag::Loop, true); }),
            "surface 'smooth': expected a triangle cage for loop (face 1 of 'cube' has 4 vertices; Catmull-Clark, "
            "the default, takes any polygons)");
  sweep::set_surface_flag(doc, 3, SurfaceFlag::Loop, true);
  sweep::set_surface_flag(doc, 3, SurfaceFlag::SmoothBoundary, true);
  EXPECT_TRUE(doc.objects[3].as<sweep::SubdivisionSurface>().loop);
  EXPECT_TRUE(doc.objects[3].as<sweep::SubdivisionSurface>().smooth_boundary);
  EXPECT_NE(sweep::io::write_swp(doc).find("subd round 1 tet loop smooth-boundary\n"), std::string::npos);
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_surface_flag(doc, 0, SurfaceFlag::Loop, true); }),
            "'cube' has no loop clause (mesh)");
}

TEST(EditPatch, ALevelPastTheVertexCapIsRefusedBeforeRefining) {
  // 40 000 quads in a strip: level 6 is a (40000 * 64 + 1) x 65 grid, 166 400 065 vertices.
  std::string text = "mesh strip 80002 40000\n";
  for (int i = 0; i <= 40000; ++i) text += "[" + std::to_string(i) + " 0 0] [" + std::to_string(i) + " 1 0]\n";
  for (int i = 0; i < 40000; ++i) {
    text += "[" + std::to_string(2 * i) + " " + std::to_string(2 * i + 2) + " " + std::to_string(2 * i + 3) + " " +
            std::to_string(2 * i + 1) + "]\n";
  }
  text += "subd s 0 strip\n";
  Document doc = sweep::io::parse_swp(text, "t.swp");
  EXPECT_EQ(edit_error(doc, [&] { sweep::set_steps_or_levels(doc, 1, 6); }),
            "surface 's': expected a surface of at most 50000000 vertices (this one would have 166400065)");
}

}  // namespace
