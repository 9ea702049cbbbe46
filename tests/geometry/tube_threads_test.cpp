// A large tube is built on the worker threads (its arrays sized side by side, its rings placed
// and its quads written in their places) and its texture coordinates' arc lengths measured there:
// the mesh and the coordinates must be the same numbers whatever the thread count, for a smooth
// closed sweep (quads written in place) and for a path with corners (clipped rings: the quads
// appended on one thread), with caps (issue 44, item 4).
#include "geometry/curves/curve.hpp"
#include "geometry/curves/polyline.hpp"
#include "geometry/surfaces/surface.hpp"
#include "geometry/surfaces/texture_coordinates.hpp"
#include "geometry/thread_pool.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace {

constexpr int kRing = 400;  // large enough that each tube below is built on the worker threads

/// A zigzag of `corners` right-angle corners in the xy plane, with 8 samples along each segment:
/// the rings of samples nearer a corner than the profile's radius (0.1) reach past it on the
/// inside and are clipped onto its mitre plane, several onto the same points.
std::vector<glm::dvec3> zigzag(int corners) {
  std::vector<glm::dvec3> path;
  for (int k = 0; k + 1 < corners; ++k) {
    const glm::dvec3 from(0.2 * k, (k % 2) * 0.2, 0.0), to(0.2 * (k + 1), ((k + 1) % 2) * 0.2, 0.0);
    for (int s = 0; s < 8; ++s) path.push_back(from + (to - from) * (s / 8.0));
  }
  path.emplace_back(0.2 * (corners - 1), ((corners - 1) % 2) * 0.2, 0.0);
  return path;
}

struct Built {
  sweep::Mesh mesh;
  std::vector<glm::vec2> uvs;
};

Built build(const sweep::CurveSamples& profile, const sweep::CurveSamples& path, bool caps) {
  sweep::SweepControls controls;
  controls.caps = caps;
  Built b{sweep::build_generalized_cylinder(profile, path, sweep::SeamMode::Full, nullptr, controls), {}};
  sweep::GridLayout grid;
  grid.ring = sweep::ring_size(profile);
  grid.rings = b.mesh.positions.size() / grid.ring;  // no caps: every vertex is a ring's
  grid.profile_closed = profile.closed;
  grid.sweep_closed = path.closed;
  sweep::Mesh textured = b.mesh;
  if (!caps) sweep::add_grid_texture_coordinates(textured, grid, false);
  b.uvs = textured.uvs;
  return b;
}

class TubeThreads : public ::testing::Test {
 protected:
  void TearDown() override { sweep::set_worker_count(sweep::default_worker_count()); }

  /// Returns the mesh built on one thread.
  sweep::Mesh expect_same_at_any_thread_count(const sweep::CurveSamples& path, bool caps) {
    const sweep::CurveSamples profile = sweep::evaluate_circle(0.1, kRing);
    sweep::set_worker_count(1);
    const Built one = build(profile, path, caps);
    EXPECT_GE(one.mesh.positions.size(), 65536u);  // past the tube's kParallelVertices
    for (const int threads : {2, 3, 8}) {
      sweep::set_worker_count(threads);
      const Built many = build(profile, path, caps);
      EXPECT_EQ(many.mesh.positions, one.mesh.positions) << threads << " threads";
      EXPECT_EQ(many.mesh.normals, one.mesh.normals) << threads << " threads";
      EXPECT_EQ(many.mesh.indices, one.mesh.indices) << threads << " threads";
      EXPECT_EQ(many.uvs, one.uvs) << threads << " threads";
    }
    return one.mesh;
  }
};

TEST_F(TubeThreads, ASmoothClosedTubeIsTheSameWhateverTheThreadCount) {
  const sweep::CurveSamples ring = sweep::evaluate_circle(1.0, 300);
  ASSERT_TRUE(ring.closed);
  expect_same_at_any_thread_count(ring, false);
}

TEST_F(TubeThreads, ATubeWithClippedCornersIsTheSameWhateverTheThreadCount) {
  const std::vector<glm::dvec3> path = zigzag(30);
  const sweep::CurveSamples samples = sweep::evaluate_polyline(path, true);
  const sweep::Mesh open = expect_same_at_any_thread_count(samples, false);
  // Triangles of no area were left out where clipped rings meet: the quads went the one-thread way.
  EXPECT_LT(open.indices.size(), 6u * kRing * (samples.frames.size() - 1));
  expect_same_at_any_thread_count(samples, true);
}

TEST_F(TubeThreads, TheQuadsCoverTheGridOnceInPlace) {
  // Written in place by bands, every quad of the closed tube is there once: each grid edge
  // between two rings is used by exactly two triangles (a closed tube has no border).
  sweep::set_worker_count(2);
  const sweep::Mesh mesh = build(sweep::evaluate_circle(0.1, kRing), sweep::evaluate_circle(1.0, 300), false).mesh;
  ASSERT_EQ(mesh.indices.size(), 6u * kRing * 300);
  std::vector<int> uses(mesh.positions.size(), 0);
  for (const std::uint32_t v : mesh.indices) ++uses[v];
  for (const int u : uses) EXPECT_EQ(u, 6);  // a vertex of a closed grid is in six triangles
}

}  // namespace
