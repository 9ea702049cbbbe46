#pragma once
// Texture coordinates (Mesh::uvs). Swept surfaces are grids of `rings` rings of `ring` vertices
// (vertex (j, i) at j * ring + i): u runs along the profile's arc length, 0 to 1 around it, and v
// along the sweep's (or the turn's) arc length in the same units, so a checker has square cells;
// a closed sweep's v ends on a whole number, so a repeating texture meets itself at the seam.
// Other surfaces (patches, cages, subdivision) are projected onto the two longest sides of their
// box. Vertices past the grid (caps) are projected onto their own plane.
#include "geometry/mesh/mesh.hpp"

#include <cstddef>

namespace sweep {

struct GridLayout {
  std::size_t ring = 0;   // vertices per ring (a closed profile's seam is shared: not repeated)
  std::size_t rings = 0;  // rings (a closed sweep's seam is shared)
  bool profile_closed = false;
  bool sweep_closed = false;
};

/// Fills mesh.uvs for a grid surface. With `split_seams`, the vertices on a closed seam are
/// duplicated for the triangles on its far side (u = 1, or v = the last whole number), so a
/// texture does not run backwards across the seam; the positions and normals are copied, so
/// the surface does not change. Without it the vertex count stays as built (the seam strip then
/// interpolates back; the viewer's uv colours show it).
void add_grid_texture_coordinates(Mesh& mesh, const GridLayout& grid, bool split_seams);

/// Fills mesh.uvs of any mesh by projecting onto the two longest sides of its bounding box
/// (scaled by the longest, so cells stay square).
void add_box_texture_coordinates(Mesh& mesh);

}  // namespace sweep
