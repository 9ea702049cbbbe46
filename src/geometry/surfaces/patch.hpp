#pragma once
// Bicubic patches: Bezier (bezpatch, 16 points each) and uniform B-spline (bsppatch, M rows of N
// points). A patch is P(u, v) = sum B_i(u) B_j(v) P_ij with i the row and j the place in the
// row, and its normal is dP/du x dP/dv: data ordered counterclockwise seen from outside (rows
// running along u, points in a row along v) faces out. swp/teapot.swp is Newell's data with each
// row's points reversed, since the published order faces out with the other cross product.
#include "geometry/mesh/mesh.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace sweep {

/// One patch's 16 control points, row by row: P_ij = points[4 i + j].
using PatchPoints = std::array<glm::dvec3, 16>;

struct PatchSample {
  glm::dvec3 position{0.0};
  glm::dvec3 du{0.0};  // dP/du (along the rows' index i)
  glm::dvec3 dv{0.0};  // dP/dv (along a row)
};

enum class PatchBasis : std::uint8_t { Bezier, BSpline };

/// P and its partial derivatives at (u, v) in [0, 1]^2.
PatchSample evaluate_patch(const PatchPoints& points, PatchBasis basis, double u, double v);

/// The unit normal dP/du x dP/dv at (u, v). Where it vanishes (a collapsed edge, such as the
/// teapot's lid and bottom poles) it is the limit from inside the patch: the normal a short step
/// towards the patch's centre, the step growing until the cross product is well defined.
glm::dvec3 patch_normal(const PatchPoints& points, PatchBasis basis, double u, double v);

/// The 16 Bezier control points of a uniform bicubic B-spline patch (the same surface).
PatchPoints bspline_to_bezier(const PatchPoints& points);

/// Bezier patches `points` (16 each, size a multiple of 16) sampled `steps` times per side, as
/// one mesh: positions within 1e-9 of the surface's size are welded (shared patch edges, collapsed
/// edges), their normals averaged, and triangles collapsed by the welding dropped.
Mesh build_bezier_patches(std::span<const glm::dvec3> points, int steps);

/// The uniform bicubic B-spline surface of `rows` x `columns` points (row by row, both >= 4):
/// (rows - 3) x (columns - 3) patches, `steps` samples per patch side, welded like Bezier
/// patches, so a periodic direction (its first three rows or columns repeated at the end) closes.
Mesh build_bspline_patch(std::span<const glm::dvec3> points, int rows, int columns, int steps);

struct Cage;
/// The quad grids of build_bezier_patches and build_bspline_patch as subdivision cages (before
/// their triangles are welded: a quad at a pole becomes a triangle), for `subd` of a patch.
Cage bezier_patch_cage(std::span<const glm::dvec3> points, int steps);
Cage bspline_patch_cage(std::span<const glm::dvec3> points, int rows, int columns, int steps);

/// The 16 points of B-spline patch (r, c) of a rows x columns net.
PatchPoints bspline_patch_points(std::span<const glm::dvec3> points, int columns, int r, int c);

/// Vertices a patch mesh has before welding (an upper bound, for the caps).
std::int64_t bezier_patch_vertex_count(std::int64_t patches, std::int64_t steps);
std::int64_t bspline_patch_vertex_count(std::int64_t rows, std::int64_t columns, std::int64_t steps);

/// The control net's grid lines as pairs of positions: each Bezier patch's 4 x 4 grid
/// (`columns` 0), or the rows x columns grid of a B-spline net.
std::vector<glm::vec3> patch_net_lines(std::span<const glm::dvec3> points, int rows, int columns);

}  // namespace sweep
