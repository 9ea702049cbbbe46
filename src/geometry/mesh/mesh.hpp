#pragma once
// A triangle mesh laid out for a vertex buffer: contiguous float3 positions and normals and
// uint32 triangle indices, counterclockwise seen from the side the normals point to.
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sweep {

struct Mesh {
  std::vector<glm::vec3> positions;
  std::vector<glm::vec3> normals;      // unit, one per position
  std::vector<std::uint32_t> indices;  // 3 per triangle
  /// Texture coordinates, one per position, or none (empty). Swept surfaces: u along the
  /// profile's arc length, v along the sweep's (or the turn's), see texture_coordinates.hpp.
  std::vector<glm::vec2> uvs;
  /// A polygon mesh's own faces (a `mesh` cage), for exporters that keep polygons (OBJ):
  /// polygon_sizes[f] indices each, in order. Empty: the triangles are the faces.
  std::vector<std::uint32_t> polygon_sizes;
  std::vector<std::uint32_t> polygon_indices;

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return indices.size() / 3; }
};

/// `mesh` with every array empty but its capacity kept: the storage a builder fills again, so a
/// re-mesh of a surface no larger than before allocates (and page-faults) nothing.
inline Mesh emptied(Mesh mesh) {
  mesh.positions.clear();
  mesh.normals.clear();
  mesh.indices.clear();
  mesh.uvs.clear();
  mesh.polygon_sizes.clear();
  mesh.polygon_indices.clear();
  return mesh;
}

/// A grid's quads are emitted in bands this many columns wide, each band row after row: a band's
/// row touches kBandQuads + 1 new vertices, so a 16-entry vertex cache (a GPU's, and glb's
/// measure) keeps the row before while the next is drawn.
inline constexpr std::size_t kBandQuads = 7;

/// Appends the two triangles of the grid quad (a, b, c, d) = ((i, j), (i+1, j), (i, j+1),
/// (i+1, j+1)). `natural` keeps the order whose geometric normal is (b - a) x (c - a);
/// otherwise it is flipped.
inline void add_quad(std::vector<std::uint32_t>& out, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                     std::uint32_t d, bool natural) {
  if (natural) {
    out.insert(out.end(), {a, b, c, b, d, c});
  } else {
    out.insert(out.end(), {a, c, b, b, c, d});
  }
}

/// add_quad less the triangles of zero area where the quad's corners meet: when a and c are one
/// point (`ac`: both on a surface of revolution's axis) only the triangle without that side, when
/// b and d are (`bd`), likewise; when both are, nothing. So a pole is closed by a fan of triangles.
inline void add_quad_unless_collapsed(std::vector<std::uint32_t>& out, std::uint32_t a, std::uint32_t b,
                                      std::uint32_t c, std::uint32_t d, bool natural, bool ac, bool bd) {
  if (ac && bd) return;
  if (ac) {
    out.insert(out.end(), {b, natural ? d : c, natural ? c : d});  // add_quad's second triangle
  } else if (bd) {
    out.insert(out.end(), {a, natural ? b : c, natural ? c : b});  // add_quad's first triangle
  } else {
    add_quad(out, a, b, c, d, natural);
  }
}

/// add_quad less each triangle two of whose corners are at one place in `positions` (a ring
/// that collapses to a point where a birail's rails meet, rings clipped onto a tube's mitre
/// plane, a bevel strip folded on the bend's axis): no triangle of zero area is written, and the
/// quad's other triangle, if it has an area, is kept. So a mesh built with it may have fewer
/// triangles than its grid's count formula (which is then an upper bound).
inline void add_quad_without_collapsed(std::vector<std::uint32_t>& out, const std::vector<glm::vec3>& positions,
                                       std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d,
                                       bool natural) {
  const auto apart = [&positions](std::uint32_t p, std::uint32_t q) { return positions[p] != positions[q]; };
  const bool first = apart(a, b) && apart(b, c) && apart(a, c);
  const bool second = apart(b, d) && apart(d, c) && apart(b, c);
  if (first && second) {
    add_quad(out, a, b, c, d, natural);
  } else if (first) {
    out.insert(out.end(), {a, natural ? b : c, natural ? c : b});  // add_quad's first triangle
  } else if (second) {
    out.insert(out.end(), {b, natural ? d : c, natural ? c : d});  // add_quad's second triangle
  }
}

}  // namespace sweep
