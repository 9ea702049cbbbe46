#pragma once
// The limit of the last level of a uniform Catmull-Clark refinement without the last level's full
// topology (internal to geometry: subdivision.hpp is the interface). PrimvarRefiner::Limit needs
// fullTopologyInLastLevel, which more than doubles the time of refining a 10 000-quad cage to
// level 3; every ring of the last level can be read from the level before it instead.
#include "geometry/mesh/mesh.hpp"
#include "geometry/subdivision/subdivision.hpp"

#include <opensubdiv/far/topologyRefiner.h>
#include <glm/vec3.hpp>

#include <memory>

namespace sweep::subdivision_detail {

/// The cage's refiner (its faces as a Far::TopologyDescriptor, the scheme and boundary rule of
/// `options`), not refined yet; null if Far refuses the cage.
std::unique_ptr<OpenSubdiv::Far::TopologyRefiner> cage_refiner(const Cage& cage, const SubdivisionOptions& options);

/// subdivide() through Far's refinement (the positions carried down every level, the limit at the
/// last level's vertices by catmark_limit or PrimvarRefiner::Limit), one thread; what subdivide
/// returns where subdivide_by_faces (subdivision_faces.hpp) does not apply. Preconditions:
/// subdivide's, and a cage with faces.
Subdivided subdivide_by_refinement(const Cage& cage, const SubdivisionOptions& options);

/// A position as Far::PrimvarRefiner carries it down the levels (Clear, AddWithWeight).
struct RefinedPoint {
  glm::dvec3 p;  // left uninitialised: a refined level is written before it is read
  void Clear(void* = nullptr) { p = glm::dvec3(0.0); }
  void AddWithWeight(const RefinedPoint& source, double weight) { p += weight * source.p; }
};

/// Whether catmark_limit can evaluate `refiner` once it is refined: Catmull-Clark, its cage
/// manifold at every edge and vertex (a non-manifold vertex has no ring to read) and without
/// semi-sharp creases (their sharpness changes from level to level). Reads only the cage level.
bool catmark_limit_applies(const OpenSubdiv::Far::TopologyRefiner& refiner);

/// The limit positions and unit normals of the last level's vertices into mesh.positions and
/// mesh.normals (vertex i at index i), from `refined`, the last level's refined positions. The
/// normal is dP/du x dP/dv of OpenSubdiv's limit tangents (the masks PrimvarRefiner::Limit
/// applies); where those are parallel or disagree with the vertex's refined quads, the
/// area-weighted normal of its quads on the limit surface. Preconditions:
/// catmark_limit_applies(refiner); refined uniformly at least once (fullTopologyInLastLevel is not
/// needed); `refined` has one point per vertex of the last level.
void catmark_limit(const OpenSubdiv::Far::TopologyRefiner& refiner, const RefinedPoint* refined, Mesh& mesh);

}  // namespace sweep::subdivision_detail
