#pragma once
// A rider's loop as keyframes, for exports that animate it (the glb scene, io/mesh/gltf_writer.hpp):
// one key at every sample of its path, timed by arc length, plus the keys that make a loop whole.
// Played back with linear interpolation (spherical for the rotations) over [0, seconds] and
// repeated, the keys retrace rider_frame (model/evaluation/riders.hpp) through every sample.
#include "model/evaluation/scene.hpp"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace sweep {

/// The gap, in seconds, between the two keys of an open path's jump back to its start.
inline constexpr double kRiderJumpSeconds = 1e-6;

struct RiderKeys {
  /// Strictly increasing, also once rounded to float (as glTF stores them); front() is 0 and
  /// back() is the rider's `seconds`.
  std::vector<double> times;
  std::vector<glm::dvec3> translations;  // the frame's V at each time
  /// The rotation [N B T] (columns) at each time: unit, and sign-continuous (each has a
  /// non-negative dot product with the one before), so interpolation takes the short way round.
  std::vector<glm::dquat> rotations;
};

/// The unit quaternion of the rotation whose columns are the frame's N, B, T (model +x, +y, +z).
/// Precondition: N, B, T orthonormal and right-handed (a frame of a track).
glm::dquat frame_rotation(const Frame& frame);

/// The keys of rider `index`, at the times its path's samples are reached: for sample i at arc
/// length lengths[i] of a path of length L, time seconds * fract(lengths[i] / L - start), the
/// frame there rider_frame at that time. Added: keys at 0 and at `seconds` (rider_frame then; for
/// an open path with start 0, the key at `seconds` is the path's end, where the loop wraps to its
/// start), and, for an open path with start > 0, its jump back to the start at time
/// t = seconds * (1 - start): the path's end at t - rider_jump_gap(seconds) and its start at t.
/// Keys whose times are equal as floats are dropped (the added ones kept). A path of length 0
/// gives two keys, at 0 and `seconds`, at its first frame. Preconditions: doc.objects[index] is a
/// rider and `scene` is evaluated from `doc`.
RiderKeys rider_keys(const Document& doc, const Scene& scene, int index);

/// The gap between an open path's jump keys: kRiderJumpSeconds, or more where glTF's float times
/// near `seconds` are further apart than half of it (two float steps), or less for loops shorter
/// than a millisecond (a thousandth of the loop). Precondition: seconds > 0.
double rider_jump_gap(double seconds);

}  // namespace sweep
