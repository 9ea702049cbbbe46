// The viewer's colour modes and the texture coordinates they need: the uv colours re-evaluate the
// scene with every surface's, the other modes keep only those a material shows.
#include "app/viewer/actions.hpp"
#include "app/viewer/viewer_state.hpp"
#include "io/swp/read.hpp"

#include <gtest/gtest.h>

namespace {

using sweep::render::ColorMode;
using sweep::viewer::ViewerState;

const char* const kText =
    "material tiles checker 4\n"
    "circ ring 12 0.5\n"
    "circ path 24 3\n"
    "gcyl plain ring path\n"
    "gcyl tiled ring path material tiles\n";

bool has_uvs(const sweep::Mesh& mesh) {
  return !mesh.positions.empty() && mesh.uvs.size() == mesh.positions.size();
}

TEST(ColorMode, UvColoursGiveEverySurfaceTextureCoordinatesAndMaterialsDropThePlainOnes) {
  ViewerState s;
  s.session.load(sweep::io::parse_swp(kText, "uv.swp"), "uv.swp");
  EXPECT_FALSE(has_uvs(s.session.scene().objects[3].mesh));
  EXPECT_TRUE(has_uvs(s.session.scene().objects[4].mesh));

  sweep::viewer::set_color_mode(s, ColorMode::Uv);
  EXPECT_EQ(s.display.color, ColorMode::Uv);
  EXPECT_TRUE(has_uvs(s.session.scene().objects[3].mesh));
  EXPECT_TRUE(has_uvs(s.session.scene().objects[4].mesh));

  sweep::viewer::set_color_mode(s, ColorMode::Normals);
  EXPECT_EQ(s.display.color, ColorMode::Normals);
  EXPECT_FALSE(has_uvs(s.session.scene().objects[3].mesh));
  EXPECT_TRUE(has_uvs(s.session.scene().objects[4].mesh));
  EXPECT_FALSE(s.session.can_undo()) << "a colour mode is not an edit";
}

TEST(ColorMode, ChangingBetweenModesThatNeedTheSameCoordinatesReevaluatesNothing) {
  ViewerState s;
  s.session.load(sweep::io::parse_swp(kText, "uv.swp"), "uv.swp");
  const std::uint64_t revision = s.session.scene().objects[3].revision;
  sweep::viewer::set_color_mode(s, ColorMode::Gaussian);
  sweep::viewer::set_color_mode(s, ColorMode::Material);
  EXPECT_EQ(s.session.scene().objects[3].revision, revision);
}

}  // namespace
