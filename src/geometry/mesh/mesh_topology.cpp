#include "geometry/mesh/mesh_topology.hpp"

#include "base/fnv1a.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <vector>

namespace sweep {
namespace {

struct PositionKey {
  std::array<std::uint32_t, 3> bits;
  bool operator==(const PositionKey&) const = default;
};

struct PositionHash {
  std::size_t operator()(const PositionKey& k) const {
    Fnv1a hash(kShortFnvOffsetBasis);
    for (const std::uint32_t b : k.bits) hash.add_word(b);
    return static_cast<std::size_t>(hash.value());
  }
};

PositionKey key_of(const glm::vec3& p) {
  // +0 and -0 are one position.
  const auto bits = [](float v) { return std::bit_cast<std::uint32_t>(v == 0.0f ? 0.0f : v); };
  return {{bits(p.x), bits(p.y), bits(p.z)}};
}

}  // namespace

std::vector<std::uint32_t> weld_equal_positions(const Mesh& mesh, std::size_t& distinct) {
  // Open addressing over the vertices themselves: a slot holds a representative vertex + 1 (0:
  // empty), the table at most half full. One flat array, no allocation per entry.
  const std::size_t n = mesh.positions.size();
  const std::size_t capacity = std::bit_ceil(std::max<std::size_t>(2 * n, 16));
  const std::size_t mask = capacity - 1;
  std::vector<std::uint32_t> slots(capacity, 0);
  std::vector<std::uint32_t> welded(n);
  distinct = 0;
  const PositionHash hash;
  for (std::size_t i = 0; i < n; ++i) {
    const PositionKey key = key_of(mesh.positions[i]);
    for (std::size_t slot = hash(key) & mask;; slot = (slot + 1) & mask) {
      if (slots[slot] == 0) {
        slots[slot] = static_cast<std::uint32_t>(i + 1);
        welded[i] = static_cast<std::uint32_t>(distinct++);
        break;
      }
      const std::uint32_t rep = slots[slot] - 1;
      if (key_of(mesh.positions[rep]) == key) {
        welded[i] = welded[rep];
        break;
      }
    }
  }
  return welded;
}

MeshTopology mesh_topology(const Mesh& mesh) {
  MeshTopology topology;
  const std::vector<std::uint32_t> welded = weld_equal_positions(mesh, topology.welded_vertices);
  // Each use of an undirected edge is filed under its smaller welded vertex as (other * 2 +
  // forward), counted once and sorted once per vertex (a handful each): linear time, two flat
  // arrays. Vertex counts are capped far below 2^31 (limits.hpp), so an entry fits 32 bits.
  const auto corners = [&](std::size_t t) {
    return std::array<std::uint32_t, 3>{welded[mesh.indices[t]], welded[mesh.indices[t + 1]],
                                        welded[mesh.indices[t + 2]]};
  };
  const auto degenerate = [](const std::array<std::uint32_t, 3>& v) {
    return v[0] == v[1] || v[1] == v[2] || v[2] == v[0];  // once welded
  };
  std::vector<std::uint32_t> start(topology.welded_vertices + 1, 0);
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const auto v = corners(t);
    if (degenerate(v)) continue;
    for (std::size_t k = 0; k < 3; ++k) ++start[std::min(v[k], v[(k + 1) % 3]) + 1];
  }
  for (std::size_t i = 1; i < start.size(); ++i) start[i] += start[i - 1];
  std::vector<std::uint32_t> uses(start.back());
  std::vector<std::uint32_t> next(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const auto v = corners(t);
    if (degenerate(v)) continue;
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = v[k], b = v[(k + 1) % 3];
      uses[next[std::min(a, b)]++] = 2 * std::max(a, b) + (a < b ? 1u : 0u);
    }
  }
  for (std::size_t vertex = 0; vertex + 1 < start.size(); ++vertex) {
    const auto first = uses.begin() + start[vertex], last = uses.begin() + start[vertex + 1];
    std::sort(first, last);
    for (auto edge = first; edge != last;) {
      std::uint32_t forward = 0, backward = 0;
      const std::uint32_t other = *edge / 2;
      for (; edge != last && *edge / 2 == other; ++edge) ++(*edge % 2 ? forward : backward);
      if (forward + backward == 1) {
        ++topology.boundary_edges;
      } else if (forward != 1 || backward != 1) {
        ++topology.non_manifold_edges;
      }
    }
  }
  return topology;
}

double signed_volume(const Mesh& mesh) {
  double volume = 0.0;
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const glm::dvec3 a(mesh.positions[mesh.indices[t]]);
    const glm::dvec3 b(mesh.positions[mesh.indices[t + 1]]);
    const glm::dvec3 c(mesh.positions[mesh.indices[t + 2]]);
    volume += glm::dot(a, glm::cross(b, c));
  }
  return volume / 6.0;
}

}  // namespace sweep
