#pragma once
// Birail surfaces: a 2D profile swept along two rails. The profile's first sample rides the
// first rail and its last sample the second, at equal fractions of the rails' arc lengths (of
// their samples). At each station the profile is turned and scaled so that its end chord lies
// on the chord between the rails, in the plane through that chord perpendicular to the rails'
// mean direction of travel; the profile's plane normal (+z) goes to that direction, as a
// generalized cylinder's does to T. The plane follows the rails continuously, so the profile
// never flips about the chord.
#include "geometry/curves/curve.hpp"
#include "geometry/mesh/mesh.hpp"

#include <cstdint>
#include <vector>

namespace sweep {

/// Where the profile goes at one fraction of the rails: its first sample at `origin`, its end
/// chord along `across` (unit, towards the second rail), its left (+z cross the chord) along
/// `up` (unit); lengths along the chord scale by `along_scale`, across it by `up_scale`.
struct BirailStation {
  double fraction = 0.0;
  glm::dvec3 origin{0.0};
  glm::dvec3 across{1.0, 0.0, 0.0};
  glm::dvec3 up{0.0, 1.0, 0.0};
  glm::dvec3 travel{0.0, 0.0, 1.0};
  double along_scale = 1.0;
  double up_scale = 1.0;
};

/// The profile's own frame: its first sample, the unit direction of its end chord, that
/// direction turned 90 degrees counterclockwise, and the chord's length.
struct ProfileChord {
  glm::dvec3 first{0.0};
  glm::dvec3 along{1.0, 0.0, 0.0};
  glm::dvec3 left{0.0, 1.0, 0.0};
  double length = 0.0;
};
/// Precondition: the profile has >= 2 samples.
ProfileChord profile_chord(const CurveSamples& profile);

/// The stations: at every fraction of arc length where either rail has a sample (merged, so
/// both rails' corners are kept), in order from 0 to 1. `keep_height` scales only along the
/// chord (the `height` clause). Preconditions: both rails have >= 2 samples, chord.length > 0.
std::vector<BirailStation> birail_stations(const CurveSamples& rail1, const CurveSamples& rail2,
                                           const ProfileChord& chord, bool keep_height);

/// The most vertices a birail surface of these sample counts has: one ring of the profile per
/// sample of either rail.
inline std::int64_t birail_vertex_count(std::int64_t profile, std::int64_t rail1, std::int64_t rail2) {
  return profile * (rail1 + rail2);
}

/// Where profile point p goes at `station`.
glm::dvec3 place_on_station(const BirailStation& station, const ProfileChord& chord, const glm::dvec3& p);

/// The birail surface: one ring of all profile samples per station; when both rails are closed
/// the last station (fraction 1) is the first and the ring wraps. Normals are the reversed
/// profile normals carried along, as for a generalized cylinder of an open profile (outward for
/// a counterclockwise profile). Two triangles per grid quad, less those of no area (where the
/// rails meet, a station's ring is one point: add_quad_without_collapsed). Preconditions: profile.planar with its ends
/// apart (its chord longer than 0), both rails have >= 2 samples.
Mesh build_birail(const CurveSamples& profile, const CurveSamples& rail1, const CurveSamples& rail2, bool keep_height);

}  // namespace sweep
