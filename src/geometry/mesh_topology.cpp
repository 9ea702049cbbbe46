#include "geometry/mesh_topology.hpp"

#include <glm/geometric.hpp>

#include <array>
#include <bit>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace sweep {
namespace {

struct PositionKey {
  std::array<std::uint32_t, 3> bits;
  bool operator==(const PositionKey&) const = default;
};

struct PositionHash {
  std::size_t operator()(const PositionKey& k) const {
    std::uint64_t h = 1469598103934665603ull;
    for (const std::uint32_t b : k.bits) h = (h ^ b) * 1099511628211ull;
    return static_cast<std::size_t>(h);
  }
};

PositionKey key_of(const glm::vec3& p) {
  // +0 and -0 are one position.
  const auto bits = [](float v) { return std::bit_cast<std::uint32_t>(v == 0.0f ? 0.0f : v); };
  return {{bits(p.x), bits(p.y), bits(p.z)}};
}

}  // namespace

std::vector<std::uint32_t> weld_equal_positions(const Mesh& mesh, std::size_t& distinct) {
  std::unordered_map<PositionKey, std::uint32_t, PositionHash> first;
  first.reserve(mesh.positions.size());
  std::vector<std::uint32_t> welded(mesh.positions.size());
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    welded[i] = first.try_emplace(key_of(mesh.positions[i]), static_cast<std::uint32_t>(first.size())).first->second;
  }
  distinct = first.size();
  return welded;
}

MeshTopology mesh_topology(const Mesh& mesh) {
  MeshTopology topology;
  const std::vector<std::uint32_t> welded = weld_equal_positions(mesh, topology.welded_vertices);
  // Per undirected edge (smaller index high): uses each way.
  struct Uses {
    std::uint32_t forward = 0;
    std::uint32_t backward = 0;
  };
  std::unordered_map<std::uint64_t, Uses> edges;
  edges.reserve(mesh.indices.size());
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::array<std::uint32_t, 3> v{welded[mesh.indices[t]], welded[mesh.indices[t + 1]],
                                         welded[mesh.indices[t + 2]]};
    if (v[0] == v[1] || v[1] == v[2] || v[2] == v[0]) continue;  // degenerate once welded
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t a = v[k], b = v[(k + 1) % 3];
      const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
      Uses& uses = edges[key];
      ++(a < b ? uses.forward : uses.backward);
    }
  }
  for (const auto& [key, uses] : edges) {
    if (uses.forward + uses.backward == 1) {
      ++topology.boundary_edges;
    } else if (uses.forward != 1 || uses.backward != 1) {
      ++topology.non_manifold_edges;
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
