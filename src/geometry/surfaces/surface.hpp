#pragma once
// Swept surfaces built from evaluated curves.
#include "geometry/curves/curve.hpp"
#include "geometry/mesh/mesh.hpp"
#include "geometry/surfaces/sweep_controls.hpp"

#include <cstdint>
#include <vector>

namespace sweep {

/// How a generalized cylinder along a closed sweep closes its seam.
enum class SeamMode : std::uint8_t {
  /// The end frame equals the start frame: the whole closure rotation is spread (by arc length,
  /// or by sample index as the course's reference tool: FrameOptions::seam_spread).
  Full,
  /// For a profile with k-fold rotational symmetry about its origin only the closure rotation
  /// modulo 2 pi / k is spread, and each end vertex joins its rotated partner at the start.
  Symmetric,
};

/// Sweep samples (inclusive) where |kappa| * r >= 1: the tube folds over itself there.
/// t = curve parameter in pieces (0..piece count; a circle: 0..1).
struct FoldRange {
  int first_sample;
  int last_sample;
  double t_begin;
  double t_end;
};

/// What building a generalized cylinder measured.
struct SweepDiagnostics {
  bool closed = false;       // the sweep is closed (and so is the tube's seam)
  double seam_angle = 0.0;   // radians spread along the sweep to close the seam
  double total_twist = 0.0;  // radians of rotation about T relative to rotation-minimizing transport, summed
                             // in absolute value over the sweep's segments after the seam correction
  std::vector<FoldRange> folds;
  /// Corners bevelled (past the mitre limit): each adds a ring to the tube's grid.
  std::size_t bevels = 0;
};

/// Rotational symmetry of a closed planar profile about its origin (the point the sweep carries).
struct ProfileSymmetry {
  int order = 1;  // k: turning the profile by 2 pi / k counterclockwise maps it onto itself
  int shift = 0;  // ... and ring sample i onto ring sample (i + shift) mod ring size
};

/// The largest k >= 1 such that the profile's distinct samples map onto each other, in order,
/// under a turn of 2 pi / k about the origin (tolerance relative to the profile's radius).
/// Open profiles have order 1.
ProfileSymmetry profile_symmetry(const CurveSamples& profile);

/// Largest distance of a profile sample from the profile's origin.
double profile_radius(const CurveSamples& profile);

/// How many distinct samples a curve contributes to a ring of a swept surface: a closed curve's
/// last sample is its first, so the ring wraps around instead of repeating it.
std::size_t ring_size(const CurveSamples& c);

/// Vertex count the surface will have; used to check caps before allocating.
std::int64_t revolution_vertex_count(std::int64_t profile_samples, bool profile_closed, std::int64_t steps);
/// Whether a profile sample is exactly on the axis (x = 0 as a float): a pole, where every copy
/// is one point and build_surface_of_revolution closes the surface with a fan.
bool on_revolution_axis(const Frame& sample);
/// Triangle count of build_surface_of_revolution before caps: per copy, two a profile segment,
/// less one for each of the segment's ends on the axis (a pole's fan), so no triangle has zero area.
std::int64_t revolution_triangle_count(const CurveSamples& profile, std::int64_t steps);
/// A generalized cylinder's, with `bevels` bevelled corners (build_generalized_cylinder).
std::int64_t cylinder_vertex_count(std::int64_t profile_samples, bool profile_closed, std::int64_t sweep_samples,
                                   bool sweep_closed, std::int64_t bevels = 0);
/// Its triangles: 2 per quad of the grid and of each bevel's strip, before any caps. (A closed
/// curve's last sample repeats its first, so either curve has samples - 1 segments.) An upper
/// bound: a triangle with two corners at one place where rings are clipped together at a corner,
/// or where a bevel's strip folds on the bend's axis, is left out (add_quad_without_collapsed).
std::int64_t cylinder_triangle_count(std::int64_t profile_samples, std::int64_t sweep_samples, std::int64_t bevels = 0);

/// Surface of revolution: `steps` copies of the planar profile turned counterclockwise about +y
/// (seen from above). A closed profile shares its seam vertices; so does the turn.
/// Normal rule: the profile is closed through the y axis if it is open (its ends are joined by
/// their projections onto the axis); normals point out of the region it then bounds. For the
/// usual profile traced top to bottom at x < 0 these are the reversed profile normals (-N), as in
/// the original tool; for a profile at x > 0, or a clockwise closed one, they are +N. Samples on
/// the axis (|x| tiny relative to the profile's size) where the profile meets it at a right
/// angle (a smooth pole) get the pole normal +y or -y, whichever points out of the solid; at a
/// cone point (the profile meets the axis at an angle) each copy's vertex keeps its turned
/// profile normal, the normal of the faces beside it.
/// With `caps`, an open profile's ends off the axis are closed by disks (caps.hpp), so the
/// surface bounds a solid. The mesh is built in `storage`'s buffers (emptied first; pass the
/// surface's last mesh so a re-mesh reuses its memory).
/// Preconditions: profile.planar, profile has >= 2 samples, steps >= 1.
Mesh build_surface_of_revolution(const CurveSamples& profile, int steps, bool caps = false, Mesh storage = {});

/// Generalized cylinder: every profile sample (x, y) placed by every sweep frame as
/// P = V + x N + y B. Closed profiles get normals out of the region they bound (-N for a
/// counterclockwise one); open profiles get the reversed profile normals (-N), as the original
/// tool. A closed profile or sweep closes its seam by sharing vertices (with SeamMode::Symmetric
/// the last ring joins the first one shifted by the symmetry). At a sharp corner of the sweep
/// (CurveSamples::corners) the profile lies in the mitre plane, stretched across the bend by
/// 1 / cos(half the turn) so the tube keeps its width; past the controls' mitre limit the corner
/// is bevelled instead (bevels_corner): the grid gets a second ring there, the profile across the
/// arriving segment's end, and the two rings are joined by a strip of flat quads with vertices of
/// their own (per bevel: one more ring of ring samples, and 4 vertices and 2 triangles per profile
/// segment, appended after the grid). Fills `diagnostics` if given. `controls` scale and twist the profile along the
/// sweep (sweep_controls.hpp; the normals tilt with the taper and the twist, from the exact derivative of the placement
/// along the sweep) and cap a closed profile on an open sweep (caps.hpp). On a closed sweep a twist that is a whole
/// number of the profile's symmetry turns joins the seam shifted as the symmetric seam does. The mesh
/// is built in `storage`'s buffers (emptied first), as build_surface_of_revolution's. Preconditions:
/// profile.planar, both have >= 2 samples.
Mesh build_generalized_cylinder(const CurveSamples& profile, const CurveSamples& sweep, SeamMode seam = SeamMode::Full,
                                SweepDiagnostics* diagnostics = nullptr, const SweepControls& controls = {},
                                Mesh storage = {});

/// True if a sweep corner from unit tangent `incoming` to unit `leaving` is bevelled rather than
/// mitred: its mitre would stretch the profile by 1 / cos(half the turn) > limit (SVG's
/// stroke-miterlimit rule; a turn back on itself always is).
bool bevels_corner(const glm::dvec3& incoming, const glm::dvec3& leaving, double limit);

/// How many of the sweep's corners a generalized cylinder bevels at mitre limit `limit`.
std::size_t bevel_count(const CurveSamples& sweep, double limit);

}  // namespace sweep
