#pragma once
// Is a shell a closed solid? Its edges counted by use (open, non-manifold, inconsistently
// oriented), its holes counted as loops, and its volume: what the printability checks report.
#include "geometry/mesh/shell.hpp"

#include <glm/vec3.hpp>

#include <cstddef>

namespace sweep {

struct ShellTopology {
  std::size_t boundary_edges = 0;      // used by one triangle
  std::size_t boundary_loops = 0;      // connected runs of boundary edges: the holes
  std::size_t non_manifold_edges = 0;  // used by more than two triangles
  std::size_t misoriented_edges = 0;   // used by two triangles in the same direction
  double volume = 0.0;                 // signed: > 0 when the triangles face out of a closed shell
  glm::dvec3 boundary_at{0.0};         // the middle of a boundary edge (when there is one)
  glm::dvec3 non_manifold_at{0.0};     // likewise for the others
  glm::dvec3 misoriented_at{0.0};

  bool closed_manifold() const { return boundary_edges == 0 && non_manifold_edges == 0; }
  bool consistently_oriented() const { return misoriented_edges == 0; }
};

/// The topology of `shell` (welded: edges meet at shared vertex indices). Linear in the edges
/// (grouped by their lower vertex, a few per group).
ShellTopology shell_topology(const Shell& shell);

}  // namespace sweep
