// The sampler of curves made of cubic Bezier pieces (piece_sampling.hpp).
#include "geometry/curves/piece_sampling.hpp"

#include "geometry/sample_limits.hpp"
#include "geometry/unit_vector.hpp"

#include <algorithm>

namespace sweep::piece_detail {
namespace {

/// Joints whose arriving and leaving tangents differ by more than this (radians) are corners.
constexpr double kCornerAngle = 1e-6;

}  // namespace

/// Size of a set of points, for relative tolerances (never zero).
double extent(std::span<const glm::dvec3> points) {
  glm::dvec3 lo(0.0), hi(0.0);
  if (!points.empty()) lo = hi = points.front();
  for (const auto& p : points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return std::max(vector_length(hi - lo), 1e-300);
}

/// Unit tangent of a Bezier piece at t. Where the first derivative vanishes (repeated control
/// points, cusps) the direction of the first non-zero higher derivative is the limit of the
/// tangent; approached from the left (t = 1) the second derivative's sign flips.
/// Returns a zero vector if every derivative vanishes (all four points coincide).
glm::dvec3 piece_tangent(const PieceDerivatives& d, double t, double scale) {
  const double eps = 1e-9 * scale;
  if (vector_length(d.d1) > eps) return unit_vector(d.d1);
  if (vector_length(d.d2) > eps) return unit_vector(t >= 1.0 ? -d.d2 : d.d2);
  if (vector_length(d.d3) > eps) return unit_vector(d.d3);
  return glm::dvec3(0.0);
}

/// Gives every zero tangent the direction of travel towards the nearest distinct point ahead,
/// else from the nearest distinct point behind, else the previous tangent, or +x for a curve that
/// is a single point. Linear time: a backward pass carries the nearest point ahead that differs
/// from the current run of (nearly) coincident samples, a forward pass the nearest one behind, so
/// a long run of repeated points costs one step per sample instead of a search each.
void repair_tangents(std::vector<Frame>& frames, double scale) {
  const double eps = 1e-12 * scale;
  const std::size_t n = frames.size();
  const auto is_zero = [](const glm::dvec3& t) { return vector_length(t) <= 0.5; };
  constexpr std::size_t kNone = static_cast<std::size_t>(-1);
  std::size_t ahead = kNone;
  for (std::size_t i = n; i-- > 0;) {
    if (i + 1 < n && vector_length(frames[i + 1].V - frames[i].V) > eps) ahead = i + 1;
    if (!is_zero(frames[i].T) || ahead == kNone) continue;
    const glm::dvec3 d = frames[ahead].V - frames[i].V;
    if (vector_length(d) > eps) frames[i].T = unit_vector(d);
  }
  std::size_t behind = kNone;
  for (std::size_t i = 0; i < n; ++i) {
    if (i > 0 && vector_length(frames[i].V - frames[i - 1].V) > eps) behind = i - 1;
    if (!is_zero(frames[i].T)) continue;
    const glm::dvec3 d = behind == kNone ? glm::dvec3(0.0) : frames[i].V - frames[behind].V;
    if (vector_length(d) > eps) {
      frames[i].T = unit_vector(d);
    } else {
      frames[i].T = i > 0 ? frames[i - 1].T : glm::dvec3(1.0, 0.0, 0.0);
    }
  }
}

/// |kappa| = |c' x c''| / |c'|^3, or 0 where c' vanishes (the curvature is unbounded or
/// undefined there; neighbouring samples tell).
double curvature_of(const PieceDerivatives& d, double scale) {
  const double speed = vector_length(d.d1);
  if (speed <= 1e-9 * scale) return 0.0;
  return vector_length(glm::cross(d.d1, d.d2)) / (speed * speed * speed);
}

/// A tangent confined to the xy-plane for planar curves; zero stays zero.
glm::dvec3 planar_tangent(glm::dvec3 t, bool planar) {
  if (!planar) return t;
  t.z = 0.0;
  return vector_length(t) > 0.0 ? unit_vector(t) : t;
}

/// The parameters of piece k's samples: t = 0 (the joint, evaluated with this piece's leaving
/// tangent) and the ones after it up to, but without, t = 1 (the next piece's t = 0), which only
/// the last piece keeps. False if adaptive samples would pass limits::kMaxCurveSamples.
bool piece_parameters(const std::array<glm::dvec3, 4>& p, std::size_t k, std::size_t pieces,
                      const PieceSampling& sampling, std::size_t samples_so_far, std::vector<double>& ts) {
  const bool last_piece = k + 1 == pieces;
  if (!sampling.at.empty()) {
    const auto begin = std::lower_bound(sampling.at.begin(), sampling.at.end(), static_cast<double>(k));
    const auto end =
        last_piece ? sampling.at.end() : std::lower_bound(begin, sampling.at.end(), static_cast<double>(k + 1));
    ts.clear();
    for (auto it = begin; it != end; ++it) ts.push_back(std::clamp(*it - static_cast<double>(k), 0.0, 1.0));
    return true;
  }
  ts.assign(1, 0.0);
  if (sampling.tolerance.adaptive()) {
    const auto cap = static_cast<std::size_t>(limits::kMaxCurveSamples);
    if (samples_so_far >= cap || !adaptive_piece_parameters(p, sampling.tolerance, cap - samples_so_far, ts)) {
      return false;
    }
  } else {
    for (int s = 1; s <= sampling.steps; ++s) ts.push_back(static_cast<double>(s) / sampling.steps);
  }
  if (!last_piece) ts.pop_back();
  return true;
}

bool is_corner(const glm::dvec3& incoming, const glm::dvec3& leaving) {
  return std::atan2(vector_length(glm::cross(incoming, leaving)), glm::dot(incoming, leaving)) > kCornerAngle;
}

void note_joint(CurveSamples& curve, std::size_t index, const std::array<glm::dvec3, 4>& previous, double scale,
                std::vector<Corner>& pending) {
  const glm::dvec3 incoming =
      planar_tangent(piece_tangent(evaluate_bezier_piece(previous, 1.0), 1.0, scale), curve.planar);
  if (vector_length(incoming) <= 0.5) return;
  const glm::dvec3& leaving = curve.frames[index].T;
  if (vector_length(leaving) < 0.5) {
    pending.push_back({index, incoming});
  } else if (is_corner(incoming, leaving)) {
    curve.corners.push_back({index, incoming});
  }
}

void finish_pieces(CurveSamples& curve, std::vector<Corner>& pending, bool ends_meet, double scale,
                   const FrameOptions& options) {
  repair_tangents(curve.frames, scale);
  if (!pending.empty()) {
    std::erase_if(pending, [&](const Corner& c) { return !is_corner(c.incoming, curve.frames[c.sample].T); });
    std::vector<Corner> merged(curve.corners.size() + pending.size());
    std::merge(curve.corners.begin(), curve.corners.end(), pending.begin(), pending.end(), merged.begin(),
               [](const Corner& a, const Corner& b) { return a.sample < b.sample; });
    curve.corners = std::move(merged);
  }
  compute_frames(curve.frames, curve.planar, options);
  curve.closed = ends_meet && is_closed(curve.frames);
  if (curve.closed && !curve.planar && options.close_seam)
    curve.seam_angle = close_frames(curve.frames, options.seam_spread);
}

}  // namespace sweep::piece_detail
