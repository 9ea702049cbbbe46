#include "geometry/subdivision/subdivision_numbering.hpp"

namespace sweep::subdivision_detail {
namespace {

GridPoint midpoint(GridPoint p, GridPoint q) {
  return {(p.a + q.a) / 2, (p.b + q.b) / 2};
}

constexpr std::array<GridPoint, 4> corners_of(int size) {
  return {GridPoint{0, 0}, GridPoint{size, 0}, GridPoint{size, size}, GridPoint{0, size}};
}

}  // namespace

Numbering number_levels(std::int64_t vertices, std::int64_t edges, const std::vector<int>& face_sizes, int levels) {
  Numbering numbering;
  numbering.levels = levels;
  numbering.face_offsets.reserve(face_sizes.size());
  std::int64_t corners = 0;
  for (const int n : face_sizes) {
    numbering.face_offsets.push_back(static_cast<std::uint32_t>(corners));
    corners += n;
  }
  // Counts level by level: V' = V + F + E, F' = corners, E' = corners + 2 E, corners' = 4 F'.
  auto faces = static_cast<std::int64_t>(face_sizes.size());
  for (int level = 0; level < levels; ++level) {
    numbering.starts.push_back({static_cast<std::uint32_t>(vertices), static_cast<std::uint32_t>(vertices + faces),
                                static_cast<std::uint32_t>(corners)});
    vertices += faces + edges;
    edges = corners + 2 * edges;
    faces = corners;
    corners = 4 * faces;
  }
  numbering.vertices = vertices;
  numbering.edges = edges;
  numbering.faces = faces;
  return numbering;
}

void Grid::resize(int n) {
  size = n;
  const auto points = static_cast<std::size_t>((n + 1) * (n + 1));
  vertex.resize(points);
  position.resize(points);
  du.resize(points);
  dv.resize(points);
  cells.resize(static_cast<std::size_t>(n * n));
}

Quad cage_quad(std::uint32_t face, const std::array<std::uint32_t, 4>& corners, const std::array<EdgeRef, 4>& edges,
               int size) {
  Quad quad;
  quad.face = face;
  quad.vertices = corners;
  quad.at = corners_of(size);
  quad.edges = edges;
  return quad;
}

Quad polygon_child(const Numbering& numbering, std::uint32_t face, const std::uint32_t* corners, const EdgeRef* edges,
                   int n, int j, int size) {
  const ChildStarts& s = numbering.starts[0];
  const std::uint32_t offset = numbering.face_offsets[face];
  const EdgeRef& leaving = edges[j];
  const EdgeRef& arriving = edges[(j + n - 1) % n];
  Quad quad;
  quad.face = offset + static_cast<std::uint32_t>(j);
  quad.vertices = {corners[j], s.edge_vertex + leaving.index, s.face_vertex + face, s.edge_vertex + arriving.index};
  quad.at = corners_of(size);
  quad.edges = {EdgeRef{s.edge_edge + 2 * leaving.index + (leaving.forward ? 0u : 1u), false},
                EdgeRef{offset + static_cast<std::uint32_t>(j), false},
                EdgeRef{offset + static_cast<std::uint32_t>((j + n - 1) % n), true},
                EdgeRef{s.edge_edge + 2 * arriving.index + (arriving.forward ? 1u : 0u), true}};
  return quad;
}

void number(const Numbering& numbering, const Quad& quad, int level, std::uint32_t first_child, std::uint32_t* indices,
            Grid& grid) {
  if (level == numbering.levels) {
    for (int p = 0; p < 4; ++p) grid.vertex[grid.at(quad.at[p].a, quad.at[p].b)] = quad.vertices[p];
    const std::array<std::uint32_t, 4>& v = quad.vertices;
    std::uint32_t* out = indices + 6 * static_cast<std::size_t>(quad.face);
    // add_quad(v0, v1, v3, v2): the triangles subdivide_by_refinement's add_faces writes.
    out[0] = v[0], out[1] = v[1], out[2] = v[3], out[3] = v[1], out[4] = v[2], out[5] = v[3];
    return;
  }
  const ChildStarts& s = numbering.starts[static_cast<std::size_t>(level)];
  const std::uint32_t center = s.face_vertex + quad.face;
  const GridPoint center_at = midpoint(quad.at[0], quad.at[2]);
  for (int j = 0; j < 4; ++j) {
    const int next = (j + 1) & 3, opposite = (j + 2) & 3, previous = (j + 3) & 3;
    const EdgeRef& leaving = quad.edges[j];
    const EdgeRef& arriving = quad.edges[previous];
    Quad child;
    child.face = first_child + static_cast<std::uint32_t>(j);
    child.vertices[j] = quad.vertices[j];
    child.vertices[next] = s.edge_vertex + leaving.index;
    child.vertices[opposite] = center;
    child.vertices[previous] = s.edge_vertex + arriving.index;
    child.at[j] = quad.at[j];
    child.at[next] = midpoint(quad.at[j], quad.at[next]);
    child.at[opposite] = center_at;
    child.at[previous] = midpoint(quad.at[previous], quad.at[j]);
    child.edges[j] = {s.edge_edge + 2 * leaving.index + (leaving.forward ? 0u : 1u), false};
    child.edges[next] = {first_child + static_cast<std::uint32_t>(j), false};
    child.edges[opposite] = {first_child + static_cast<std::uint32_t>(previous), true};
    child.edges[previous] = {s.edge_edge + 2 * arriving.index + (arriving.forward ? 1u : 0u), true};
    number(numbering, child, level + 1, 4 * child.face, indices, grid);
  }
}

}  // namespace sweep::subdivision_detail
