#include "geometry/mesh/wall_thickness.hpp"

#include "base/precondition.hpp"
#include "geometry/mesh/triangle_bvh.hpp"
#include "geometry/thread_pool.hpp"

#include <glm/geometric.hpp>

#include <optional>
#include <vector>

namespace sweep {
namespace {

constexpr std::size_t kChunk = 1 << 12;
constexpr std::size_t kParallelTriangles = 1 << 12;  // below this one thread is quicker

struct Thinnest {
  std::size_t triangles = 0;
  double thickness = 0.0;
  std::uint32_t triangle = kNoTriangle;

  void add(double t, std::uint32_t at) {
    ++triangles;
    keep_if_thinner(t, at);
  }
  void merge(const Thinnest& other) {
    triangles += other.triangles;
    if (other.triangle != kNoTriangle) keep_if_thinner(other.thickness, other.triangle);
  }
  void keep_if_thinner(double t, std::uint32_t at) {
    if (triangle == kNoTriangle || t < thickness || (t == thickness && at < triangle)) {
      thickness = t;
      triangle = at;
    }
  }
};

glm::dvec3 area_normal(const TriangleCorners& c) {
  return glm::cross(c[1] - c[0], c[2] - c[0]);
}

/// The thickness of the wall under triangle `t`, if below `min_wall` (as the header says).
std::optional<double> thin_wall_at(const TriangleBvh& bvh, std::uint32_t t, double min_wall) {
  const TriangleCorners c = bvh.corners(t);
  const glm::dvec3 normal = area_normal(c);
  const double length = glm::length(normal);
  if (!(length > 0.0)) return std::nullopt;
  const Ray ray{(c[0] + c[1] + c[2]) / 3.0, -normal / length, min_wall};
  const std::optional<RayHit> hit = bvh.nearest_hit(ray, {t, true});
  if (!hit || !(hit->distance < min_wall)) return std::nullopt;
  if (!(glm::dot(area_normal(bvh.corners(hit->triangle)), ray.direction) > 0.0)) return std::nullopt;
  return hit->distance;
}

}  // namespace

ThinWalls thin_walls(const Shell& shell, double min_wall) {
  SWEEP_EXPECTS(min_wall > 0.0, "min_wall > 0");
  return thin_walls(TriangleBvh(shell, shell.triangle_count() < kParallelTriangles ? 1 : worker_count()), min_wall);
}

ThinWalls thin_walls(const TriangleBvh& bvh, double min_wall) {
  SWEEP_EXPECTS(min_wall > 0.0, "min_wall > 0");
  const std::size_t count = bvh.triangle_count();
  const int threads = count < kParallelTriangles ? 1 : worker_count();
  std::vector<Thinnest> found(static_cast<std::size_t>(threads));
  parallel_chunks(count, kChunk, threads, [&](std::size_t begin, std::size_t end, int worker) {
    for (std::size_t k = begin; k < end; ++k) {
      const std::uint32_t triangle = bvh.order()[k];  // in leaf order: neighbours walk the same nodes
      if (const std::optional<double> thickness = thin_wall_at(bvh, triangle, min_wall)) {
        found[static_cast<std::size_t>(worker)].add(*thickness, triangle);
      }
    }
  });
  Thinnest all;
  for (const Thinnest& part : found) all.merge(part);
  if (all.triangle == kNoTriangle) return {};
  const TriangleCorners c = bvh.corners(all.triangle);
  return {all.triangles, all.thickness, (c[0] + c[1] + c[2]) / 3.0};
}

}  // namespace sweep
