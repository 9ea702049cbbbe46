// Riders in pictures: the model is drawn where the rider is at the time asked (its pixel centroid
// where the camera maths puts the rider's position), and only there.
#include "headless/headless_renderer.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/riders.hpp"
#include "render/draw_list.hpp"

#include <gtest/gtest.h>

#include <glm/vec4.hpp>

namespace sweep {
namespace {

// A straight open path along x from -2 to 2, and a red ball riding it once every 4 seconds.
const char* kRiderFile =
    "poly3 line 2\n[-2 0 0]\n[2 0 0]\n"
    "circ c 24 0.25\n"
    "material red color 1 0 0\n"
    "srev ball 24 c material red\n"
    "rider r line ball seconds 4\n";

/// The centroid (pixels, origin top left) of the red pixels, and how many there are.
glm::dvec3 red_centroid(const render::Image& image) {
  glm::dvec3 sum{0.0};
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      if (p[0] > p[1] + 60 && p[0] > p[2] + 60) sum += glm::dvec3(x + 0.5, y + 0.5, 1.0);
    }
  }
  return sum.z > 0.0 ? glm::dvec3(sum.x / sum.z, sum.y / sum.z, sum.z) : sum;
}

/// Where the camera puts a world point, in pixels (origin top left).
glm::dvec2 project(const render::Camera& camera, glm::ivec2 size, const glm::dvec3& point) {
  const glm::dvec4 clip =
      camera.projection_matrix(double(size.x) / size.y) * camera.view_matrix() * glm::dvec4(point, 1.0);
  const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
  return {(ndc.x + 1.0) * 0.5 * size.x, (1.0 - ndc.y) * 0.5 * size.y};
}

TEST(RiderRender, TheModelIsDrawnWhereTheRiderIsAtEachTime) {
  const Document doc = io::parse_swp(kRiderFile);
  const Scene scene = evaluate_document(doc);
  headless::HeadlessRenderer renderer;
  const glm::ivec2 size{320, 200};
  render::Camera camera;
  camera.set_view(render::ViewPreset::Front);
  camera.frame(render::scene_bounds(scene), double(size.x) / size.y);
  render::DrawList list = render::draw_list(doc, scene);
  const int rider = doc.find("r");
  double previous_x = -1.0;
  for (const double time : {0.5, 1.0, 2.0, 3.0}) {
    render::add_riders(list, doc, scene, time);
    const glm::dvec3 centroid = red_centroid(renderer.render(list, camera, size, render::DisplaySettings{}));
    ASSERT_GT(centroid.z, 50.0) << "the ball is drawn at time " << time;
    const glm::dvec3 at = rider_frame(doc, scene, rider, time).V;
    EXPECT_NEAR(at.x, -2.0 + time, 1e-9) << "a quarter of the line a second";
    const glm::dvec2 expected = project(camera, size, at);
    EXPECT_NEAR(centroid.x, expected.x, 1.0) << "time " << time;
    EXPECT_NEAR(centroid.y, expected.y, 1.0) << "time " << time;
    EXPECT_GT(centroid.x, previous_x + 20.0) << "it moved right";
    previous_x = centroid.x;
  }
}

TEST(RiderRender, ACarriedModelIsNotDrawnAtItsOwnPlace) {
  const Document doc = io::parse_swp(kRiderFile);
  const Scene scene = evaluate_document(doc);
  headless::HeadlessRenderer renderer;
  render::Camera camera;
  camera.set_view(render::ViewPreset::Front);
  camera.frame(render::scene_bounds(scene), 1.6);
  const render::DrawList list = render::draw_list(doc, scene);  // no riders added: nothing red
  EXPECT_TRUE(list.carried.at(static_cast<std::size_t>(doc.find("ball"))));
  EXPECT_EQ(red_centroid(renderer.render(list, camera, {320, 200}, render::DisplaySettings{})).z, 0.0);
}

}  // namespace
}  // namespace sweep
