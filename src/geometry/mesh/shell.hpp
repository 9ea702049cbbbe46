#pragma once
// A surface as a printer receives it: positions in millimetres (double), welded so that a seam
// or a pole is one vertex, and triangles counterclockwise seen from outside, none with two
// corners at one vertex. The printability checks (print_checks.hpp, intersections.hpp,
// wall_thickness.hpp) and the print exports read it.
#include "geometry/mesh/mesh.hpp"
#include "geometry/mesh/print_placement.hpp"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace sweep {

struct Shell {
  std::vector<glm::dvec3> positions;
  std::vector<std::uint32_t> indices;  // 3 per triangle

  std::size_t vertex_count() const { return positions.size(); }
  std::size_t triangle_count() const { return indices.size() / 3; }
};

/// How close two placed vertices are when the print exports make them one: 0.1 micrometre, far
/// below what a printer resolves and a hundred times the 3MF file's precision (1e-6 mm).
inline constexpr double kPrintWeldMillimetres = 1e-4;

/// `mesh` placed (print_placement.hpp) and welded: vertices within kPrintWeldMillimetres of an
/// earlier one become it (a seam built twice, the copies of a profile point on or a hair off
/// the turning axis), numbered in order of first appearance, and a triangle left with two
/// corners at one vertex is left out. So a surface whose caps close it becomes one closed shell
/// with no triangle of zero area. Expected linear time (weld_points).
Shell welded_shell(const Mesh& mesh, const PrintPlacement& placement);

/// Triangles of `shell` whose corners, as a file stores them (single precision), are on one
/// line: zero area as written.
std::size_t zero_area_triangles(const Shell& shell);

}  // namespace sweep
