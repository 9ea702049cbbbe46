#pragma once
// Moving coordinate frames along a sampled curve.
#include <glm/vec3.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace sweep {

/// A curve sample: position V and the right-handed orthonormal frame T (unit tangent),
/// N (normal), B (binormal), with B = T x N.
struct Frame {
  glm::dvec3 V{0.0};
  glm::dvec3 T{1.0, 0.0, 0.0};
  glm::dvec3 N{0.0, 1.0, 0.0};
  glm::dvec3 B{0.0, 0.0, 1.0};
};

/// How 3D frames are carried from one sample to the next.
enum class FrameMethod : std::uint8_t {
  /// N_i = normalize(B_{i-1} x T_i), B_i = normalize(T_i x N_i): the original tool's update.
  /// First order accurate; it twists on curves with torsion.
  Projection,
  /// Double reflection (Wang, Juttler, Zheng, Liu 2008): rotation-minimizing, fourth order
  /// accurate. The default.
  RotationMinimizing,
};

/// How a closed curve's seam correction is spread along it (close_frames).
enum class SeamSpread : std::uint8_t {
  ArcLength,    // in proportion to arc length (chord length of the samples): the default
  SampleIndex,  // evenly by sample index, as the course's reference tool does (--seam index)
};

struct FrameOptions {
  FrameMethod method = FrameMethod::RotationMinimizing;
  /// Closed 3D curves: spread the rotation between the propagated end frame and the start frame
  /// along the curve so the end frame equals the start frame. Off only to show an uncorrected
  /// seam (sweep render --seam none, used for before/after pictures).
  bool close_seam = true;
  SeamSpread seam_spread = SeamSpread::ArcLength;
};

/// Fills N and B of samples whose V and T are set. Planar curves get B = +z and N = B x T
/// (normal left of travel). 3D curves start from B_0 = +z, N_0 = normalize(B_0 x T_0)
/// (another seed axis when T_0 is nearly parallel to z) and are carried by options.method.
/// Does not close seams (see close_frames). Preconditions: every T is unit length and finite.
void compute_frames(std::span<Frame> samples, bool planar, const FrameOptions& options);

/// Signed angle in radians by which `from` must turn about the unit `axis` (right-handed) to
/// point like `to`, both first projected onto the plane perpendicular to the axis; 0 if either
/// projection vanishes.
double angle_about(const glm::dvec3& axis, const glm::dvec3& from, const glm::dvec3& to);

/// Turns N and B of `frame` by `angle` radians about its T (right-handed): N -> cos N + sin B.
void rotate_about_tangent(Frame& frame, double angle);

/// Cumulative chord length from the first sample: result[0] = 0, result[i] = sum |V_k - V_{k-1}|.
std::vector<double> chord_lengths(std::span<const Frame> samples);

/// Closes the frames of a closed curve whose last sample repeats the first in position and
/// tangent: measures the angle about T from the start frame to the propagated end frame, turns
/// frame i back by that angle times its share of the curve (s_i / L of the arc length, or
/// i / (n - 1) by sample index), and makes the end frame the start frame. Returns the angle that
/// was spread (radians). Precondition: frames computed.
double close_frames(std::span<Frame> samples, SeamSpread spread = SeamSpread::ArcLength);

/// One double-reflection step: the frame at `to` (whose V and T are set) that a rotation-
/// minimizing transport of `from` gives; used to measure how much a frame sequence twists.
Frame transport_rotation_minimizing(const Frame& from, const Frame& to);

}  // namespace sweep
