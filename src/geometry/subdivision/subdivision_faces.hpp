#pragma once
// The Catmull-Clark limit of a uniform refinement evaluated face by face, in parallel, without
// refining (internal to geometry: subdivision.hpp is the interface). Each cage face's limit
// surface (OpenSubdiv's Bfr: RefinerSurfaceFactory, Surface; a regular face in closed form) is
// evaluated at the parameters of the refined vertices inside it, and the refined vertices and
// quads are numbered as Far numbers them, so the mesh is the one Far's refinement gives.
#include "geometry/subdivision/subdivision.hpp"

#include <optional>

namespace sweep::subdivision_detail {

/// subdivide()'s result for Catmull-Clark at levels 1 and above, computed on `threads` threads
/// (1: the calling thread only); the same bytes whatever `threads` is. Positions within float
/// rounding of subdivide_by_refinement's, normals the same up to rounding, indices equal.
/// Nothing (std::nullopt) where it does not apply (Loop, level 0, a cage that is not manifold
/// apart from points in no face) or where a normal may be subdivide_by_refinement's fallback
/// (limit tangents nearly parallel, or their normal against the quads around the vertex), so
/// subdivide refines there instead. Preconditions: subdivide's.
std::optional<Subdivided> subdivide_by_faces(const Cage& cage, const SubdivisionOptions& options, int threads);

/// The threads subdivide uses for `options`' refinement of `cage`: worker_count() for a large
/// one, 1 where starting threads would cost more than they save.
int subdivision_threads(const Cage& cage, const SubdivisionOptions& options);

}  // namespace sweep::subdivision_detail
