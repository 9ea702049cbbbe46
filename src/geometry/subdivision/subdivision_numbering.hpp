#pragma once
// How Far's uniform refinement numbers the vertices and quads inside one cage face, so that
// subdivide_by_faces writes each refined vertex and triangle where Far's refinement would
// (internal to geometry: subdivision.hpp is the interface).
//
// The rules (Vtr's Refinement and QuadRefinement, default options): a level's vertices are its
// parent level's vertices' children (same index), then its faces' (in face order), then its
// edges'; its faces are each parent face's children, n for a face of n corners, in face order,
// the child at corner j being (child of corner j, child of edge j, child of the face, child of
// edge j - 1), turned so that the corner's child is at place j in a quad's child (at place 0 in
// another polygon's); its edges are the faces' children (face f's edge j joins the face's child
// to edge j's child) then two per parent edge (from the edge's child to its first vertex's
// child, then its second's). Following a cage face down the levels with those rules gives every
// refined vertex and quad in it its index, with no topology but the cage's.
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace sweep::subdivision_detail {

/// Where one level's children start in the next level's numbering.
struct ChildStarts {
  std::uint32_t face_vertex = 0;  // the child vertex of face f is face_vertex + f
  std::uint32_t edge_vertex = 0;  // the child vertex of edge e is edge_vertex + e
  std::uint32_t edge_edge = 0;    // the child edges of edge e are edge_edge + 2 e and + 1
};

/// The whole refinement's numbering: the starts per level and each cage face's first child,
/// and the last level's counts.
struct Numbering {
  int levels = 0;
  std::vector<ChildStarts> starts;          // per level 0 .. levels - 1
  std::vector<std::uint32_t> face_offsets;  // per cage face, its first corner (and first child)
  std::int64_t vertices = 0, edges = 0, faces = 0;
};

/// The numbering of `levels` uniform refinements of a cage with these counts and face sizes.
/// The last level's counts may pass 32 bits: the caller checks them before numbering anything.
Numbering number_levels(std::int64_t vertices, std::int64_t edges, const std::vector<int>& face_sizes, int levels);

/// An edge of a refined quad: its index, and whether it starts at the quad's corner it leaves
/// from (its first vertex is that corner).
struct EdgeRef {
  std::uint32_t index = 0;
  bool forward = false;
};

/// A point of a face's grid: (a, b) = (u, v) times the grid's size.
struct GridPoint {
  int a = 0, b = 0;
};

/// A quad of some level on its way down: its index, and per place (0-3, counterclockwise) its
/// vertex, that vertex's grid point, and the edge to the next place.
struct Quad {
  std::uint32_t face = 0;
  std::array<std::uint32_t, 4> vertices{};
  std::array<GridPoint, 4> at{};
  std::array<EdgeRef, 4> edges{};
};

/// A grid of (size + 1)^2 points over a cage quad (size 2^L) or over one quarter of another
/// polygon (2^(L-1)): each point's refined vertex, limit position and derivatives.
struct Grid {
  int size = 0;
  std::vector<std::uint32_t> vertex;
  std::vector<glm::dvec3> position, du, dv;
  std::vector<glm::dvec3> cells;  // per cell, its diagonals crossed (twice its area vector)

  void resize(int n);
  std::size_t at(int a, int b) const { return static_cast<std::size_t>(a * (size + 1) + b); }
};

/// Cage quad `face` (its corners, and its edges from each corner) as the level-0 quad over the
/// whole grid of `size`.
Quad cage_quad(std::uint32_t face, const std::array<std::uint32_t, 4>& corners, const std::array<EdgeRef, 4>& edges,
               int size);

/// The level-1 child quad at corner j of cage polygon `face` with `n` corners (`corners` and
/// `edges` from its corner 0, its children from `first_child`), over a whole grid of `size`.
Quad polygon_child(const Numbering& numbering, std::uint32_t face, const std::uint32_t* corners, const EdgeRef* edges,
                   int n, int j, int size);

/// Numbers the quads inside `quad` (of `level`, its children starting at `first_child`) down to
/// the last level: their triangles into `indices` (6 per last-level quad, at 6 × its index),
/// their vertices into the grid.
void number(const Numbering& numbering, const Quad& quad, int level, std::uint32_t first_child, std::uint32_t* indices,
            Grid& grid);

}  // namespace sweep::subdivision_detail
