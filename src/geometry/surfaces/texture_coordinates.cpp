#include "geometry/surfaces/texture_coordinates.hpp"

#include "geometry/thread_pool.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <unordered_map>
#include <vector>

namespace sweep {
namespace {

glm::dvec3 at(const Mesh& mesh, std::size_t index) {
  return glm::dvec3(mesh.positions[index]);
}

/// Grids of at least this many vertices measure their arc lengths on the worker threads.
constexpr std::size_t kParallelVertices = 1 << 16;

/// Cumulative arc length along the grid's rings (u) or across them (v), averaged over the other
/// direction; one more entry than vertices when the direction is closed (the wrap). Each entry's
/// sum runs over the other direction in order, whichever thread measures it (entries are split
/// among the worker threads), so the lengths are the same at any thread count.
std::vector<double> mean_arc_length(const Mesh& mesh, const GridLayout& g, bool along_ring) {
  const std::size_t count = along_ring ? g.ring : g.rings;
  const std::size_t across = along_ring ? g.rings : g.ring;
  const bool closed = along_ring ? g.profile_closed : g.sweep_closed;
  std::vector<double> length(count + (closed ? 1 : 0), 0.0);
  const std::size_t ring_end = g.ring + (along_ring && closed ? 1 : 0);  // i past the last: the wrap
  const std::size_t rings_end = g.rings + (!along_ring && closed ? 1 : 0);
  // Entry k: the edge from vertex (i - 1, j) to (i, j) summed over j (along a ring), or from
  // (i, j - 1) to (i, j) summed over i (across the rings); index i or j wraps at the closed end.
  const auto edge = [&](std::size_t i, std::size_t j) {
    const std::size_t to = (j % g.rings) * g.ring + i % g.ring;
    const std::size_t from = along_ring ? (j % g.rings) * g.ring + i - 1 : (j - 1) * g.ring + i;
    return glm::distance(at(mesh, from), at(mesh, to));
  };
  const std::size_t entries = along_ring ? ring_end : rings_end;
  const int threads = g.ring * g.rings < kParallelVertices ? 1 : worker_count();
  parallel_chunks(entries - 1, std::max<std::size_t>(1, entries / 16), threads,
                  [&](std::size_t begin, std::size_t end, int) {
                    if (along_ring) {  // ring after ring, in memory order
                      for (std::size_t m = 0; m < across; ++m) {
                        for (std::size_t k = begin + 1; k < end + 1; ++k) length[k] += edge(k, m);
                      }
                      return;
                    }
                    for (std::size_t k = begin + 1; k < end + 1; ++k) {
                      for (std::size_t m = 0; m < across; ++m) length[k] += edge(m, k);
                    }
                  });
  for (std::size_t k = 1; k < length.size(); ++k) length[k] = length[k - 1] + length[k] / static_cast<double>(across);
  return length;
}

/// Two unit vectors spanning the plane perpendicular to `n`.
std::array<glm::dvec3, 2> plane_axes(const glm::dvec3& n) {
  const glm::dvec3 helper = std::abs(n.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  const glm::dvec3 e1 = glm::normalize(glm::cross(n, helper));
  return {e1, glm::cross(n, e1)};
}

/// Duplicates the seam vertices of the triangles that cross a closed seam (see the header).
void split_seam_triangles(Mesh& mesh, const GridLayout& g, double u_end, double v_end) {
  const std::size_t grid = g.ring * g.rings;
  std::unordered_map<std::uint64_t, std::uint32_t> copies;  // (vertex, which seam) -> copy
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    std::uint32_t* v = &mesh.indices[t];
    if (v[0] >= grid || v[1] >= grid || v[2] >= grid) continue;
    bool first_i = false, last_i = false, first_j = false, last_j = false;
    for (int k = 0; k < 3; ++k) {
      first_i |= v[k] % g.ring == 0;
      last_i |= v[k] % g.ring == g.ring - 1;
      first_j |= v[k] / g.ring == 0;
      last_j |= v[k] / g.ring == g.rings - 1;
    }
    const bool wrap_u = g.profile_closed && g.ring >= 3 && first_i && last_i;
    const bool wrap_v = g.sweep_closed && g.rings >= 3 && first_j && last_j;
    if (!wrap_u && !wrap_v) continue;
    for (int k = 0; k < 3; ++k) {
      const bool move_u = wrap_u && v[k] % g.ring == 0;
      const bool move_v = wrap_v && v[k] / g.ring == 0;
      if (!move_u && !move_v) continue;
      const std::uint64_t key = (std::uint64_t{v[k]} << 2) | (move_u ? 1u : 0u) | (move_v ? 2u : 0u);
      auto [it, added] = copies.try_emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
      if (added) {
        mesh.positions.push_back(mesh.positions[v[k]]);
        mesh.normals.push_back(mesh.normals[v[k]]);
        glm::vec2 uv = mesh.uvs[v[k]];
        if (move_u) uv.x = static_cast<float>(u_end);
        if (move_v) uv.y = static_cast<float>(v_end);
        mesh.uvs.push_back(uv);
      }
      v[k] = it->second;
    }
  }
}

}  // namespace

void add_grid_texture_coordinates(Mesh& mesh, const GridLayout& g, bool split_seams) {
  if (g.ring == 0 || g.rings == 0 || g.ring * g.rings > mesh.positions.size()) {
    add_box_texture_coordinates(mesh);
    return;
  }
  const std::vector<double> u = mean_arc_length(mesh, g, true);
  const std::vector<double> v = mean_arc_length(mesh, g, false);
  const double u_length = u.back() > 0.0 ? u.back() : 1.0;
  // v in the units of u (square cells); a closed sweep ends on a whole number of repeats.
  double v_scale = 1.0 / u_length;
  if (g.sweep_closed && v.back() > 0.0) v_scale = std::max(1.0, std::round(v.back() / u_length)) / v.back();
  mesh.uvs.clear();  // filled in vertex order: no zero-fill of what is written next
  mesh.uvs.reserve(mesh.positions.size());
  for (std::size_t j = 0; j < g.rings; ++j) {
    for (std::size_t i = 0; i < g.ring; ++i) {
      mesh.uvs.emplace_back(static_cast<float>(u[i] / u_length), static_cast<float>(v[j] * v_scale));
    }
  }
  // Caps: each vertex onto the plane its flat normal gives, in the profile's units.
  for (std::size_t k = g.ring * g.rings; k < mesh.positions.size(); ++k) {
    const auto axes = plane_axes(glm::normalize(glm::dvec3(mesh.normals[k])));
    const glm::dvec3 p = at(mesh, k);
    mesh.uvs.emplace_back(static_cast<float>(glm::dot(p, axes[0]) / u_length),
                          static_cast<float>(glm::dot(p, axes[1]) / u_length));
  }
  if (split_seams) split_seam_triangles(mesh, g, 1.0, v.back() * v_scale);
}

void add_box_texture_coordinates(Mesh& mesh) {
  mesh.uvs.clear();
  if (mesh.positions.empty()) return;
  mesh.uvs.reserve(mesh.positions.size());
  glm::vec3 lo = mesh.positions.front(), hi = lo;
  for (const glm::vec3& p : mesh.positions) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  const glm::vec3 size = hi - lo;
  std::array<int, 3> axis{0, 1, 2};
  std::sort(axis.begin(), axis.end(), [&size](int a, int b) { return size[a] > size[b]; });
  const float scale = size[axis[0]] > 0.0f ? 1.0f / size[axis[0]] : 1.0f;
  for (std::size_t k = 0; k < mesh.positions.size(); ++k) {
    const glm::vec3 p = mesh.positions[k] - lo;
    mesh.uvs.emplace_back(p[axis[0]] * scale, p[axis[1]] * scale);
  }
}

}  // namespace sweep
