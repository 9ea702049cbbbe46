#pragma once
// The quads of a tube's grid of rings (build_generalized_cylinder), in bands of kBandQuads
// columns so that the triangles come in vertex-cache order (mesh.hpp).
#include "geometry/mesh/mesh.hpp"
#include "geometry/surfaces/surface_corners.hpp"

#include <cstddef>
#include <vector>

namespace sweep::surface_detail {

/// Where a tube's quads join its rings: `ring` vertices per ring (ring k at k * ring in
/// mesh.positions), `segments` quads around, `sweep_segments` along, segment j from ring
/// tube.leave[j] to ring tube.arrive[(j + 1) % rings]; the ring after the last joins the first one
/// `seam_shift` vertices on. `moved`: per ring, whether clip_at_corners moved a point of it.
struct TubeGrid {
  std::size_t ring = 0;
  std::size_t segments = 0;
  std::size_t rings = 0;  // sweep samples (tube.arrive's size)
  std::size_t sweep_segments = 0;
  std::size_t seam_shift = 0;
  const TubeRings* tube = nullptr;
  const std::vector<bool>* moved = nullptr;
};

/// Writes the grid's two triangles per quad at the end of mesh.indices, band by band and in each
/// band row after row; quads touching a moved ring lose their triangles of no area
/// (add_quad_without_collapsed). `sized`: the caller has made room for every quad's 6 indices at
/// the end of mesh.indices; then, unless a ring was moved, the bands are written in their places
/// on `threads` threads (the same indices whatever the count), and otherwise the room is given
/// back and the quads appended on this thread.
/// Preconditions: grid.tube and grid.moved are set; with `sized`, mesh.indices holds at least
/// 6 * grid.segments * grid.sweep_segments entries.
void add_tube_quads(Mesh& mesh, const TubeGrid& grid, bool natural, bool sized, int threads);

}  // namespace sweep::surface_detail
