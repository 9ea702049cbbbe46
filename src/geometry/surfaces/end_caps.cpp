#include "geometry/surfaces/end_caps.hpp"

#include "base/precondition.hpp"
#include "geometry/mesh/polygon_triangulation.hpp"

#include <glm/geometric.hpp>

#include <array>
#include <vector>

namespace sweep {
namespace {

std::uint32_t index_of(std::size_t i) {
  return static_cast<std::uint32_t>(i);
}

/// Copies of the vertices `first` .. `first + count` (every `stride`-th) with one flat normal.
std::size_t copy_rim(Mesh& mesh, std::size_t first, std::size_t count, std::size_t stride, const glm::vec3& normal) {
  const std::size_t start = mesh.positions.size();
  for (std::size_t k = 0; k < count; ++k) {
    mesh.positions.push_back(mesh.positions[first + k * stride]);
    mesh.normals.push_back(normal);
  }
  return start;
}

}  // namespace

void add_tube_caps(Mesh& mesh, std::span<const glm::dvec2> ring, std::size_t rings, const glm::dvec3& start_out,
                   const glm::dvec3& end_out) {
  SWEEP_EXPECTS(ring.size() >= 3, "ring.size() >= 3");
  SWEEP_EXPECTS(rings >= 2, "rings >= 2");
  SWEEP_EXPECTS(mesh.positions.size() >= rings * ring.size(), "the mesh holds the tube's vertices first");
  const std::vector<std::array<std::uint32_t, 3>> triangles = triangulate_polygon(ring);
  const bool counterclockwise = polygon_twice_signed_area(ring) >= 0.0;
  const std::size_t n = ring.size();
  mesh.positions.reserve(mesh.positions.size() + 2 * n);
  mesh.normals.reserve(mesh.normals.size() + 2 * n);
  mesh.indices.reserve(mesh.indices.size() + 6 * triangles.size());
  for (const bool end : {false, true}) {
    const glm::dvec3& out = end ? end_out : start_out;
    const std::size_t rim = copy_rim(mesh, end ? (rings - 1) * n : 0, n, 1, glm::vec3(out));
    // The triangles turn as the profile does, seen from +T: the end cap (facing +T) keeps a
    // counterclockwise profile's order, the start cap (facing -T) reverses it.
    const bool keep = counterclockwise == end;
    for (const auto& t : triangles) {
      mesh.indices.insert(mesh.indices.end(), {index_of(rim + t[0]), index_of(rim + (keep ? t[1] : t[2])),
                                               index_of(rim + (keep ? t[2] : t[1]))});
    }
  }
}

void add_revolution_caps(Mesh& mesh, const CurveSamples& profile, std::size_t copies, double on_axis) {
  if (profile.closed || copies < 3) return;
  const std::size_t ring = profile.frames.size();
  // Twice the signed area of the profile closed through the axis tells which side is inside.
  double area = 0.0;
  const auto edge = [&area](const glm::dvec3& a, const glm::dvec3& b) { area += a.x * b.y - b.x * a.y; };
  for (std::size_t i = 0; i + 1 < ring; ++i) edge(profile.frames[i].V, profile.frames[i + 1].V);
  const glm::dvec3 first = profile.frames.front().V;
  const glm::dvec3 last = profile.frames.back().V;
  edge(last, {0.0, last.y, 0.0});
  edge({0.0, last.y, 0.0}, {0.0, first.y, 0.0});
  edge({0.0, first.y, 0.0}, first);
  const double orientation = area >= 0.0 ? 1.0 : -1.0;
  mesh.positions.reserve(mesh.positions.size() + 2 * (copies + 1));  // copy_rim reads from the same vector
  mesh.normals.reserve(mesh.normals.size() + 2 * (copies + 1));
  for (const bool at_last : {false, true}) {
    const glm::dvec3& end = at_last ? last : first;
    if (std::abs(end.x) <= on_axis) continue;
    // The closing segment runs from the end to the axis (last) or from the axis to the end
    // (first); outside is to its right for a counterclockwise outline.
    const double up = orientation * (at_last ? (end.x > 0.0 ? 1.0 : -1.0) : (end.x > 0.0 ? -1.0 : 1.0));
    const glm::vec3 normal(0.0f, static_cast<float>(up), 0.0f);
    const std::size_t centre = mesh.positions.size();
    mesh.positions.emplace_back(0.0f, static_cast<float>(end.y), 0.0f);
    mesh.normals.push_back(normal);
    const std::size_t rim = copy_rim(mesh, at_last ? ring - 1 : 0, copies, ring, normal);
    // Copies turn counterclockwise about +y seen from above, so (centre, j, j + 1) faces +y.
    for (std::size_t j = 0; j < copies; ++j) {
      const std::size_t a = rim + j;
      const std::size_t b = rim + (j + 1) % copies;
      if (up > 0.0) {
        mesh.indices.insert(mesh.indices.end(), {index_of(centre), index_of(a), index_of(b)});
      } else {
        mesh.indices.insert(mesh.indices.end(), {index_of(centre), index_of(b), index_of(a)});
      }
    }
  }
}

}  // namespace sweep
