// The Edit panel's surface controls as the editor runs them: scale and twist graphs, a twist in
// degrees, caps and height, each one undo step; edits the reader would refuse are refused with
// its message; a dragged scale graph re-meshes its surface live; what is saved reads back.
#include "editor/edit_session.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "support/editor_test_support.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace sweep::editor {
namespace {

constexpr const char* kText =
    "circ c 16 0.5\n"
    "bez3 up 4 4 [0 0 0] [0 1 0] [0 2 0] [0 3 0]\n"
    "cr2 taper 4 3 [0 1] [0.5 0.6] [1 0.2]\n"
    "cr2 turn 4 2 [0 0] [1 90]\n"
    "bsp3 path3 4 4 [0 0 0] [1 0 0] [2 1 0] [3 1 1]\n"
    "gcyl tube c up\n"
    "cr2 arc 4 3 [0 0] [1 0.5] [2 0]\n"
    "birail b arc up path3\n";
constexpr int kTaper = 2, kTurn = 3, kPath3 = 4, kTube = 5, kBirail = 7;

TEST(SurfaceControlsEdit, EachControlIsOneUndoStepAndSavesBack) {
  EditSession session = test::session_of(kText);
  const Document original = session.document();
  ASSERT_TRUE(
      session.edit("set scale", [](Document& d) { return set_surface_graph(d, kTube, SurfaceGraph::Scale, kTaper); }));
  ASSERT_TRUE(session.edit("set twist", [](Document& d) { return set_twist(d, kTube, 45.0); }));
  ASSERT_TRUE(
      session.edit("set caps", [](Document& d) { return set_surface_flag(d, kTube, SurfaceFlag::Caps, true); }));
  ASSERT_TRUE(
      session.edit("set height", [](Document& d) { return set_surface_flag(d, kBirail, SurfaceFlag::Height, true); }));
  const std::string text = io::write_swp(session.document());
  EXPECT_NE(text.find("gcyl tube c up scale taper twist 45 caps\n"), std::string::npos) << text;
  EXPECT_NE(text.find("birail b arc up path3 height\n"), std::string::npos) << text;
  EXPECT_EQ(io::parse_swp(text), session.document());
  // The capped, tapered tube has two more rings (its caps) than the plain one.
  const std::size_t capped = session.scene().objects[kTube].mesh.vertex_count();
  EXPECT_EQ(capped, evaluate_document(original).objects[kTube].mesh.vertex_count() + 2 * 16);
  // A twist curve replaces the degrees; degrees replace the curve.
  ASSERT_TRUE(
      session.edit("twist curve", [](Document& d) { return set_surface_graph(d, kTube, SurfaceGraph::Twist, kTurn); }));
  EXPECT_EQ(session.document().objects[kTube].as<sweep::CylinderSurface>().twist_curve, kTurn);
  EXPECT_NE(io::write_swp(session.document()).find("twist turn"), std::string::npos);
  for (int k = 0; k < 5; ++k) ASSERT_TRUE(session.undo());
  EXPECT_EQ(session.document(), original);
  EXPECT_FALSE(session.dirty());
}

TEST(SurfaceControlsEdit, RefusedEditsKeepTheDocumentAndSayWhy) {
  EditSession session = test::session_of(kText);
  const Document original = session.document();
  EXPECT_FALSE(
      session.edit("scale", [](Document& d) { return set_surface_graph(d, kTube, SurfaceGraph::Scale, kPath3); }));
  EXPECT_EQ(
      session.error(),
      "'path3': expected the name of a 2D curve (bez2, bsp2, circ, cr2, kb2, poly2, herm2) defined above as a scale "
      "curve (it is a 3D curve (bsp3))");
  EXPECT_FALSE(session.edit("caps", [](Document& d) { return set_surface_flag(d, kBirail, SurfaceFlag::Caps, true); }));
  EXPECT_EQ(session.error(), "'b' has no caps clause (birail)");
  ASSERT_TRUE(
      session.edit("set scale", [](Document& d) { return set_surface_graph(d, kTube, SurfaceGraph::Scale, kTaper); }));
  // Dragging the graph's middle point left of its first one would make x go back: refused.
  EXPECT_FALSE(session.edit("move", [](Document& d) { return move_point(d, kTaper, 1, {-0.5, 0.6, 0.0}); }));
  EXPECT_EQ(session.error(),
            "surface 'tube': expected a scale curve whose x never decreases (sample 2 of 9 goes back from x = 0 to "
            "-0.151825)");
  // ... and a scale of 0 too.
  EXPECT_FALSE(session.edit("move", [](Document& d) { return move_point(d, kTaper, 2, {1.0, -0.1, 0.0}); }));
  EXPECT_EQ(session.document().objects[kTaper], original.objects[kTaper]);
}

TEST(SurfaceControlsEdit, DraggingTheScaleGraphReshapesTheSurfaceLive) {
  EditSession session = test::session_of(kText);
  ASSERT_TRUE(
      session.edit("set scale", [](Document& d) { return set_surface_graph(d, kTube, SurfaceGraph::Scale, kTaper); }));
  const auto before = session.scene().objects[kTube].revision;
  const glm::vec3 top_before = session.scene().objects[kTube].mesh.positions.back();
  ASSERT_TRUE(session.edit("move", [](Document& d) { return move_point(d, kTaper, 2, {1.0, 0.5, 0.0}); }));
  EXPECT_NE(session.scene().objects[kTube].revision, before);
  // The last ring's radius follows the graph's last y: 0.5 * 0.5 instead of 0.5 * 0.2.
  const glm::vec3 top = session.scene().objects[kTube].mesh.positions.back();
  EXPECT_NEAR(std::hypot(top.x, top.z), 0.25, 1e-5);
  EXPECT_NEAR(std::hypot(top_before.x, top_before.z), 0.1, 1e-5);
}

}  // namespace
}  // namespace sweep::editor
