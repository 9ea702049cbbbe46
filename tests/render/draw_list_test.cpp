// Draw lists without GL: draw_list shows every object with the control polygons of the
// control-point curves (not circles, not surfaces); visibility defaults to visible.
#include "render/draw_list.hpp"

#include "io/swp/read.hpp"

#include <gtest/gtest.h>

namespace sweep::render {
namespace {

TEST(DrawList, HasTheControlPolygonsOfControlPointCurvesOnly) {
  const Document doc = io::parse_swp(
      "bez2 profile 4 4 [0 0] [1 1] [2 1] [3 0]\n"
      "bsp3 path 4 4 [0 0 0] [1 0 1] [2 1 0] [3 0 1]\n"
      "circ ring 12 1\n"
      "srev vase 8 profile\n");
  const Scene scene = evaluate_document(doc);
  const DrawList list = draw_list(doc, scene);
  EXPECT_EQ(list.scene, &scene);
  ASSERT_EQ(list.control_polygons.size(), 4u);
  for (std::size_t i : {0u, 1u}) {
    EXPECT_EQ(list.control_polygons[i].data(), doc.objects[i].as<sweep::PointsPart>().points.data()) << i;
    EXPECT_EQ(list.control_polygons[i].size(), 4u) << i;
  }
  EXPECT_TRUE(list.control_polygons[2].empty()) << "a circle has no control points";
  EXPECT_TRUE(list.control_polygons[3].empty()) << "a surface has none";
  EXPECT_TRUE(list.overlay.empty());
  for (std::size_t i = 0; i < 4; ++i) EXPECT_TRUE(list.is_visible(i)) << i;
}

TEST(DrawList, ObjectsPastTheEndOfVisibleAreVisible) {
  DrawList list;
  list.visible = {true, false};
  EXPECT_TRUE(list.is_visible(0));
  EXPECT_FALSE(list.is_visible(1));
  EXPECT_TRUE(list.is_visible(2));
}

}  // namespace
}  // namespace sweep::render
