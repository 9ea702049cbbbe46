#include "geometry/curves/frames.hpp"

#include "base/precondition.hpp"
#include "geometry/unit_vector.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sweep {
namespace {

constexpr glm::dvec3 kZ(0.0, 0.0, 1.0);

/// A unit vector perpendicular to unit t: the coordinate axis least aligned with t, made
/// perpendicular.
glm::dvec3 any_perpendicular(const glm::dvec3& t) {
  const glm::dvec3 a = std::abs(t.x) <= std::abs(t.y) && std::abs(t.x) <= std::abs(t.z) ? glm::dvec3(1, 0, 0)
                       : std::abs(t.y) <= std::abs(t.z)                                 ? glm::dvec3(0, 1, 0)
                                                                                        : glm::dvec3(0, 0, 1);
  return unit_vector(a - glm::dot(a, t) * t);
}

/// `n` made perpendicular to unit t and unit length; `fallback` (also projected) if n is
/// (nearly) parallel to t.
glm::dvec3 perpendicular_to(const glm::dvec3& t, const glm::dvec3& n, const glm::dvec3& fallback) {
  glm::dvec3 p = n - glm::dot(n, t) * t;
  if (vector_length(p) > 1e-9) return unit_vector(p);
  p = fallback - glm::dot(fallback, t) * t;
  if (vector_length(p) > 1e-9) return unit_vector(p);
  return any_perpendicular(t);
}

void start_frame(Frame& f) {
  // The original convention: B_0 = +z, N_0 = normalize(B_0 x T_0). When T_0 is (nearly) along z,
  // that cross product is meaningless and another axis seeds the frame.
  glm::dvec3 n = glm::cross(kZ, f.T);
  if (vector_length(n) < 1e-6) n = glm::cross(any_perpendicular(f.T), f.T);
  f.N = unit_vector(n);
  f.B = unit_vector(glm::cross(f.T, f.N));
}

void propagate_projection(std::span<Frame> s) {
  for (std::size_t i = 1; i < s.size(); ++i) {
    const glm::dvec3 n = glm::cross(s[i - 1].B, s[i].T);
    // B_{i-1} parallel to T_i (a quarter turn within one step): keep the previous normal instead.
    s[i].N = vector_length(n) > 1e-9 ? unit_vector(n) : perpendicular_to(s[i].T, s[i - 1].N, s[i - 1].B);
    s[i].B = unit_vector(glm::cross(s[i].T, s[i].N));
  }
}

// Double reflection: Wang, Juttler, Zheng, Liu, "Computation of rotation minimizing frames",
// ACM Transactions on Graphics 27(1), 2008, Algorithm 1. Reflect the frame in the bisecting plane
// of the two sample points, then in the plane that maps the reflected tangent onto the new one.
void double_reflection(const Frame& a, Frame& b) {
  glm::dvec3 r = a.N;
  glm::dvec3 t = a.T;
  const glm::dvec3 v1 = b.V - a.V;
  const double c1 = glm::dot(v1, v1);
  if (c1 > 1e-300) {
    r -= (2.0 / c1) * glm::dot(v1, r) * v1;
    t -= (2.0 / c1) * glm::dot(v1, t) * v1;
  } else if (glm::dot(a.T, b.T) > -1.0 + 1e-12) {
    // No chord (a point whose tangent turns, like a circle of radius 0): the second reflection
    // alone would mirror the frame, so turn it by the least rotation taking a.T onto b.T
    // (Rodrigues' formula about a.T x b.T), which is what the two reflections approximate.
    const glm::dvec3 axis = glm::cross(a.T, b.T);
    const glm::dvec3 ar = glm::cross(axis, r);
    b.N = perpendicular_to(b.T, r + ar + glm::cross(axis, ar) / (1.0 + glm::dot(a.T, b.T)), a.B);
    b.B = unit_vector(glm::cross(b.T, b.N));
    return;
  }
  const glm::dvec3 v2 = b.T - t;
  const double c2 = glm::dot(v2, v2);
  if (c2 > 1e-300) r -= (2.0 / c2) * glm::dot(v2, r) * v2;
  b.N = perpendicular_to(b.T, r, a.B);
  b.B = unit_vector(glm::cross(b.T, b.N));
}

void propagate_rotation_minimizing(std::span<Frame> s) {
  for (std::size_t i = 1; i < s.size(); ++i) double_reflection(s[i - 1], s[i]);
}

}  // namespace

void compute_frames(std::span<Frame> samples, bool planar, const FrameOptions& options) {
  SWEEP_EXPECTS(std::all_of(samples.begin(), samples.end(),
                            [](const Frame& f) { return std::abs(glm::dot(f.T, f.T) - 1.0) <= 1e-6; }),
                "every T is unit length and finite");
  if (samples.empty()) return;
  if (planar) {
    for (Frame& f : samples) {
      f.B = kZ;
      f.N = unit_vector(glm::cross(kZ, f.T));
    }
    return;
  }
  start_frame(samples[0]);
  if (options.method == FrameMethod::Projection) {
    propagate_projection(samples);
  } else {
    propagate_rotation_minimizing(samples);
  }
}

double angle_about(const glm::dvec3& axis, const glm::dvec3& from, const glm::dvec3& to) {
  const glm::dvec3 a = from - glm::dot(from, axis) * axis;
  const glm::dvec3 b = to - glm::dot(to, axis) * axis;
  if (vector_length(a) <= 1e-300 || vector_length(b) <= 1e-300) return 0.0;
  return std::atan2(glm::dot(glm::cross(a, b), axis), glm::dot(a, b));
}

void rotate_about_tangent(Frame& frame, double angle) {
  const double c = std::cos(angle);
  const double s = std::sin(angle);
  const glm::dvec3 n = c * frame.N + s * frame.B;
  frame.N = unit_vector(n - glm::dot(n, frame.T) * frame.T);
  frame.B = unit_vector(glm::cross(frame.T, frame.N));
}

std::vector<double> chord_lengths(std::span<const Frame> samples) {
  std::vector<double> lengths(samples.size(), 0.0);
  for (std::size_t i = 1; i < samples.size(); ++i) {
    lengths[i] = lengths[i - 1] + vector_length(samples[i].V - samples[i - 1].V);
  }
  return lengths;
}

double close_frames(std::span<Frame> samples, SeamSpread spread) {
  if (samples.size() < 2) return 0.0;
  const Frame& start = samples.front();
  // The end tangent equals the start tangent within the closure tolerance, so the angle is
  // measured about the start tangent.
  const double gap = angle_about(start.T, start.N, samples.back().N);
  const std::size_t last = samples.size() - 1;
  if (spread == SeamSpread::SampleIndex) {
    for (std::size_t i = 1; i < last; ++i) {
      rotate_about_tangent(samples[i], -gap * static_cast<double>(i) / static_cast<double>(last));
    }
  } else {
    // Frame i turns back by gap * s_i / L (chord length of the samples).
    const std::vector<double> length = chord_lengths(samples);
    const double total = length.back();
    if (total > 0.0) {
      for (std::size_t i = 1; i < last; ++i) rotate_about_tangent(samples[i], -gap * length[i] / total);
    }
  }
  Frame& end = samples.back();
  end.T = start.T;
  end.N = start.N;
  end.B = start.B;
  return gap;
}

Frame transport_rotation_minimizing(const Frame& from, const Frame& to) {
  Frame out = to;
  double_reflection(from, out);
  return out;
}

}  // namespace sweep
