#pragma once
// How a generalized cylinder turns the sharp corners of its sweep (CurveSamples::corners), as a
// stroke renderer joins segments (SVG's stroke-linejoin miter with stroke-miterlimit): a mitre,
// the profile in the plane that bisects the bend, stretched across it by 1 / cos(half the turn)
// so both segments keep their width; or, where that stretch would pass the mitre limit, a bevel:
// the profile placed across the end of each segment at the corner (two rings at the joint) and
// the two rings joined by a strip of flat quads. Internal to surface.cpp (surface.hpp is the
// interface).
#include "geometry/curves/curve.hpp"
#include "geometry/mesh/mesh.hpp"

#include <cstddef>
#include <vector>

namespace sweep::surface_detail {

/// How a ring places the profile: P = V + M (x N + y B), with M the identity except at a mitre,
/// where it stretches by `stretch` along `across` (the bend direction in the mitre plane).
struct Placement {
  Frame frame;
  glm::dvec3 across{0.0};
  double stretch = 1.0;

  glm::dvec3 offset(double x, double y) const;
  /// Normals transform with the inverse transpose: the stretch divides instead.
  glm::dvec3 normal(double x, double y) const;
};

/// The rings of a tube's grid, in order along the sweep: one per sweep sample, two at a bevelled
/// corner (the arriving segment's end, then the leaving segment's start).
struct TubeRings {
  std::vector<Placement> rings;
  std::vector<std::size_t> sample;  // per ring: the sweep sample it is placed at
  std::vector<std::size_t> arrive;  // per sweep sample: the ring the segment before it ends on
  std::vector<std::size_t> leave;   // per sweep sample: the ring the segment after it starts from
  std::size_t bevels = 0;

  bool bevelled(std::size_t sample_index) const { return arrive[sample_index] != leave[sample_index]; }
};

/// The rings for sweep placements `by_sample` (one per ring sample of the sweep, the corner
/// samples' frames carrying the leaving tangent) with each corner mitred, or bevelled where
/// bevels_corner(limit) says so. Precondition: limit >= 1.
TubeRings corner_rings(std::vector<Placement> by_sample, const std::vector<Corner>& corners, double limit);

/// Rings close to a corner can reach past it on the inside of the bend (samples closer to the
/// corner than r tan(half the turn)), which would fold the tube there. Such vertices slide along
/// their ring's tangent back onto the plane the segment ends in at the corner (the mitre plane,
/// or at a bevel the plane across that segment's own end), so the tube ends cleanly there (the
/// clipped triangles become degenerate instead of inverted). Walks away from each corner until a
/// ring needs no clipping or the next corner is reached. `frames`: the sweep's, per sample.
/// Returns, per grid ring, whether a point of it was moved: only quads of such rings can have two
/// corners at one place (the grid checks just those, add_quad_without_collapsed).
std::vector<bool> clip_at_corners(Mesh& mesh, std::size_t ring, const std::vector<Frame>& frames, const TubeRings& tube,
                                  const std::vector<Corner>& corners);

/// Appends each bevel's strip: for every profile segment (i, i + 1) (`segments` of them, the last
/// wrapping round a closed profile of `ring` samples) a quad between the bevel's two rings, with
/// four vertices of its own at the rings' positions and the quad's flat normal; `natural` is the
/// tube's winding (add_quad). Precondition: the mesh holds the grid of tube.rings rings first.
void add_bevel_strips(Mesh& mesh, std::size_t ring, std::size_t segments, const TubeRings& tube, bool natural);

}  // namespace sweep::surface_detail
