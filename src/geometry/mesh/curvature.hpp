#pragma once
// Per-vertex Gaussian and mean curvature of a triangle mesh, with the discrete operators of
// Meyer, Desbrun, Schroeder and Barr (2003), for colouring a surface by its curvature.
//
// Seams: meshes repeat vertices where a surface closes (a surface of revolution's or a tube's
// seam column, a cap's rim), so vertices at exactly equal positions (+0 and -0 alike) are welded
// first, as mesh_topology does; the curvatures are computed on the welded mesh and every vertex
// gets its welded vertex's values.
//
// Sign convention: mean curvature H = (k1 + k2) / 2 is positive where the surface bends away from
// its normal, as a sphere with outward normals: a sphere of radius r has H = +1/r, K = 1/r^2 at
// every point; turning the normals inward makes H = -1/r (K does not change). The side is taken
// from the mesh's vertex normals.
#include "geometry/mesh/mesh.hpp"

#include <vector>

namespace sweep {

struct Curvatures {
  std::vector<float> gaussian;  // K = k1 k2, one per mesh vertex
  std::vector<float> mean;      // H = (k1 + k2) / 2, one per mesh vertex, sign as above
};

/// Gaussian curvature from the angle deficit, (2 pi - sum of the corner angles) / A_mixed, and
/// mean curvature from the cotangent Laplacian, |Hn| / 2 signed by the vertex normal, each over
/// the vertex's mixed Voronoi area A_mixed (obtuse triangles split by halves and quarters).
/// Boundary vertices (on a welded edge used by one triangle): K = (pi - sum of angles) / A_mixed;
/// H comes from the same cotangent sum over the edges there are, only an estimate (its one-ring
/// is cut in half). Triangles with a repeated welded corner are skipped; zero-area triangles
/// (collinear corners) add their corner angles (0, 0 and pi) but no area and no cotangent
/// weights; a vertex with no area gets K = H = 0. Always finite. Linear time.
/// H's side: the sum of the normals of the welded vertex's copies (seam copies agree; at a cap's
/// rim the side's and the cap's average), or of its triangles' area normals when the mesh has no
/// normals (the winding, counterclockwise seen from the front).
Curvatures vertex_curvatures(const Mesh& mesh);

/// Total angle deficit over the welded vertices that triangles use: sum of (2 pi - sum of angles)
/// at interior ones plus (pi - sum of angles) at boundary ones (in general (2 - b / 2) pi - sum
/// for b boundary edges at the vertex, so two boundary loops touching at a vertex count right).
/// By the discrete Gauss-Bonnet theorem this is 2 pi chi (chi = V - E + F of the welded mesh,
/// without collapsed triangles) whenever no edge has more than two triangles: 4 pi for a closed
/// sphere-like solid, 0 for a torus, 2 pi for a disk. In double, from the same angles as
/// vertex_curvatures.
double total_angle_deficit(const Mesh& mesh);

}  // namespace sweep
