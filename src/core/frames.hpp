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
  Projection,
  /// Double reflection (Wang, Juttler, Zheng, Liu 2008): rotation-minimizing.
  RotationMinimizing,
};

struct FrameOptions {
  FrameMethod method = FrameMethod::Projection;
};

/// Fills N and B of samples whose V and T are set. Planar curves get B = +z and N = B x T
/// (normal left of travel). 3D curves start from B_0 = +z, N_0 = normalize(B_0 x T_0)
/// (another seed axis when T_0 is nearly parallel to z) and are carried by options.method.
/// Preconditions: every T is unit length and finite.
void compute_frames(std::span<Frame> samples, bool planar, const FrameOptions& options);

}  // namespace sweep
