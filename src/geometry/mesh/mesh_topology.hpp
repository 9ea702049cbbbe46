#pragma once
// Is a mesh a closed solid? Counts of its edges once vertices at equal positions are welded (as
// STL readers and slicers do), and its signed volume.
#include "geometry/mesh/mesh.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sweep {

struct MeshTopology {
  std::size_t boundary_edges = 0;      // used by one triangle
  std::size_t non_manifold_edges = 0;  // used by more than two, or twice in the same direction
  std::size_t welded_vertices = 0;     // distinct positions

  bool closed_manifold() const { return boundary_edges == 0 && non_manifold_edges == 0; }
};

/// The welded index of every vertex: vertices at exactly equal positions (+0 and -0 alike) share
/// one, numbered in order of first appearance; `distinct` receives how many there are. Linear
/// time (an open-addressing table of the vertices).
std::vector<std::uint32_t> weld_equal_positions(const Mesh& mesh, std::size_t& distinct);

/// Welds vertices at exactly equal positions (+0 and -0 alike), skips triangles with a repeated
/// welded corner, and counts the undirected edges by use. A closed, consistently oriented surface
/// has every edge used twice, once each way. Linear time (the weld, then the edges filed under
/// their smaller vertex: flat arrays).
MeshTopology mesh_topology(const Mesh& mesh);

/// The signed volume of the mesh, sum of a . (b x c) / 6 over its triangles, in double: positive
/// for a closed mesh whose triangles are counterclockwise seen from outside.
double signed_volume(const Mesh& mesh);

}  // namespace sweep
