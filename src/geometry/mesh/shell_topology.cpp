#include "geometry/mesh/shell_topology.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

namespace sweep {
namespace {

/// An edge of a triangle: its vertices in ascending order, and whether the triangle runs it
/// from the larger to the smaller.
struct Edge {
  std::uint32_t low, high;
  bool reversed;
};

/// Every triangle's edges grouped by their lower vertex (a counting sort: linear), each group
/// sorted by the higher one, so a shared edge's uses are side by side.
std::vector<Edge> sorted_edges(const Shell& shell) {
  std::vector<std::uint32_t> start(shell.positions.size() + 1, 0);
  const auto each_edge = [&shell](auto&& body) {
    for (std::size_t t = 0; t + 2 < shell.indices.size(); t += 3) {
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t a = shell.indices[t + k];
        const std::uint32_t b = shell.indices[t + (k + 1) % 3];
        body(Edge{std::min(a, b), std::max(a, b), a > b});
      }
    }
  };
  each_edge([&start](const Edge& e) { ++start[e.low + 1]; });
  for (std::size_t v = 1; v < start.size(); ++v) start[v] += start[v - 1];
  std::vector<Edge> edges(shell.indices.size());
  std::vector<std::uint32_t> filled(start.begin(), start.end() - 1);
  each_edge([&](const Edge& e) { edges[filled[e.low]++] = e; });
  for (std::size_t v = 0; v + 1 < start.size(); ++v) {
    std::sort(edges.begin() + start[v], edges.begin() + start[v + 1],
              [](const Edge& x, const Edge& y) { return x.high < y.high; });
  }
  return edges;
}

std::uint32_t root(std::vector<std::uint32_t>& parent, std::uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

/// Connected components of the boundary edges' graph.
std::size_t loops(std::size_t vertices, const std::vector<Edge>& boundary) {
  std::vector<std::uint32_t> parent(vertices);
  std::iota(parent.begin(), parent.end(), 0u);
  std::vector<bool> on_boundary(vertices, false);
  for (const Edge& e : boundary) {
    on_boundary[e.low] = on_boundary[e.high] = true;
    parent[root(parent, e.low)] = root(parent, e.high);
  }
  std::size_t count = 0;
  for (std::uint32_t v = 0; v < vertices; ++v) count += on_boundary[v] && root(parent, v) == v;
  return count;
}

double signed_volume(const Shell& shell) {
  double six_volume = 0.0;
  for (std::size_t t = 0; t + 2 < shell.indices.size(); t += 3) {
    const glm::dvec3& a = shell.positions[shell.indices[t]];
    six_volume += glm::dot(a, glm::cross(shell.positions[shell.indices[t + 1]], shell.positions[shell.indices[t + 2]]));
  }
  return six_volume / 6.0;
}

}  // namespace

ShellTopology shell_topology(const Shell& shell) {
  ShellTopology out;
  const std::vector<Edge> edges = sorted_edges(shell);
  std::vector<Edge> boundary;
  const auto middle = [&shell](const Edge& e) { return 0.5 * (shell.positions[e.low] + shell.positions[e.high]); };
  for (std::size_t i = 0; i < edges.size();) {
    std::size_t j = i;
    std::size_t reversed = 0;
    for (; j < edges.size() && edges[j].low == edges[i].low && edges[j].high == edges[i].high; ++j) {
      reversed += edges[j].reversed;
    }
    const std::size_t uses = j - i;
    if (uses == 1) {
      if (boundary.empty()) out.boundary_at = middle(edges[i]);
      boundary.push_back(edges[i]);
    } else if (uses > 2) {
      if (out.non_manifold_edges++ == 0) out.non_manifold_at = middle(edges[i]);
    } else if (reversed != 1) {
      if (out.misoriented_edges++ == 0) out.misoriented_at = middle(edges[i]);
    }
    i = j;
  }
  out.boundary_edges = boundary.size();
  out.boundary_loops = loops(shell.positions.size(), boundary);
  out.volume = signed_volume(shell);
  return out;
}

}  // namespace sweep
