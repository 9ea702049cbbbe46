#include "core/curve.hpp"

#include "core/bezier.hpp"
#include "core/catmull_rom.hpp"
#include "core/helix.hpp"
#include "core/torus_knot.hpp"
#include "core/unit_vector.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace sweep {
namespace {

/// Size of a set of points, for relative tolerances (never zero).
double extent(const std::vector<glm::dvec3>& points) {
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

/// Joints whose arriving and leaving tangents differ by more than this (radians) are corners.
constexpr double kCornerAngle = 1e-6;

/// Samples consecutive Bezier pieces (given as 4 control points each) at `steps` segments each.
template <typename PieceAt>
CurveSamples sample_pieces(std::size_t pieces, int steps, bool planar, bool tangent_continuous, double scale,
                           const FrameOptions& options, PieceAt piece_at) {
  CurveSamples curve;
  curve.planar = planar;
  curve.steps = steps;
  const std::size_t count = pieces * static_cast<std::size_t>(steps) + 1;
  curve.frames.resize(count);
  curve.curvature.resize(count);
  // Joints whose leaving tangent is still zero are decided after the repair.
  std::vector<Corner> pending;
  const auto is_corner = [](const glm::dvec3& incoming, const glm::dvec3& leaving) {
    return std::atan2(vector_length(glm::cross(incoming, leaving)), glm::dot(incoming, leaving)) > kCornerAngle;
  };
  std::array<glm::dvec3, 4> previous{};
  std::size_t index = 0;
  for (std::size_t k = 0; k < pieces; ++k) {
    const std::array<glm::dvec3, 4> p = piece_at(k);
    const int last = k + 1 == pieces ? steps : steps - 1;  // the next piece's t = 0 is this one's t = 1
    for (int s = 0; s <= last; ++s) {
      const double t = static_cast<double>(s) / steps;
      const PieceDerivatives d = evaluate_bezier_piece(p, t);
      curve.curvature[index] = curvature_of(d, scale);
      Frame& f = curve.frames[index];
      f.V = d.position;
      f.T = planar_tangent(piece_tangent(d, t, scale), planar);
      if (planar) f.V.z = 0.0;
      // A joint (the next piece's t = 0) is a corner if the previous piece arrives at t = 1 with
      // another tangent. A B-spline's derivative is continuous, so only a vanishing one can jump.
      if (s == 0 && k > 0 && !(tangent_continuous && vector_length(d.d1) > 1e-9 * scale)) {
        const glm::dvec3 incoming =
            planar_tangent(piece_tangent(evaluate_bezier_piece(previous, 1.0), 1.0, scale), planar);
        if (vector_length(incoming) > 0.5) {
          if (vector_length(f.T) < 0.5) {
            pending.push_back({index, incoming});
          } else if (is_corner(incoming, f.T)) {
            curve.corners.push_back({index, incoming});
          }
        }
      }
      ++index;
    }
    previous = p;
  }
  repair_tangents(curve.frames, scale);
  if (!pending.empty()) {
    std::erase_if(pending, [&](const Corner& c) { return !is_corner(c.incoming, curve.frames[c.sample].T); });
    std::vector<Corner> merged(curve.corners.size() + pending.size());
    std::merge(curve.corners.begin(), curve.corners.end(), pending.begin(), pending.end(), merged.begin(),
               [](const Corner& a, const Corner& b) { return a.sample < b.sample; });
    curve.corners = std::move(merged);
  }
  compute_frames(curve.frames, planar, options);
  curve.closed = is_closed(curve.frames);
  if (curve.closed && !planar && options.close_seam) curve.seam_angle = close_frames(curve.frames);
  return curve;
}

}  // namespace

CurveSamples evaluate_bezier(const std::vector<glm::dvec3>& points, int steps, bool planar,
                             const FrameOptions& options) {
  const std::size_t pieces = (points.size() - 1) / 3;
  return sample_pieces(pieces, steps, planar, false, extent(points), options, [&](std::size_t k) {
    return std::array<glm::dvec3, 4>{points[3 * k], points[3 * k + 1], points[3 * k + 2], points[3 * k + 3]};
  });
}

CurveSamples evaluate_bspline(const std::vector<glm::dvec3>& points, int steps, bool planar,
                              const FrameOptions& options) {
  const std::size_t pieces = points.size() - 3;
  return sample_pieces(pieces, steps, planar, true, extent(points), options, [&](std::size_t k) {
    return bspline_piece_to_bezier({points[k], points[k + 1], points[k + 2], points[k + 3]});
  });
}

CurveSamples evaluate_catmull_rom(const std::vector<glm::dvec3>& points, int steps, double alpha, double tension,
                                  bool planar, const FrameOptions& options) {
  const bool closed = is_closed_interpolating(points);
  // The derivative is continuous across joints (G1: each segment has its own parameter).
  return sample_pieces(points.size() - 1, steps, planar, true, extent(points), options,
                       [&](std::size_t k) { return catmull_rom_piece(points, k, closed, alpha, tension); });
}

CurveSamples evaluate_kochanek_bartels(const std::vector<glm::dvec3>& points, int steps,
                                       const KochanekBartelsShape& shape, bool planar, const FrameOptions& options) {
  const bool closed = is_closed_interpolating(points);
  return sample_pieces(points.size() - 1, steps, planar, shape.continuity == 0.0, extent(points), options,
                       [&](std::size_t k) { return kochanek_bartels_piece(points, k, closed, shape); });
}

CurveSamples evaluate_circle(double radius, int steps) {
  CurveSamples curve;
  curve.planar = true;
  curve.frames.resize(static_cast<std::size_t>(steps) + 1);
  for (int i = 0; i < steps; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / steps;
    Frame& f = curve.frames[static_cast<std::size_t>(i)];
    f.V = radius * glm::dvec3(std::cos(angle), std::sin(angle), 0.0);
    f.T = glm::dvec3(-std::sin(angle), std::cos(angle), 0.0);
  }
  curve.frames.back() = curve.frames.front();  // exactly closed
  compute_frames(curve.frames, true, {});
  curve.closed = true;
  curve.steps = steps;
  curve.curvature.assign(curve.frames.size(), 1.0 / radius);
  return curve;
}

CurveSamples evaluate_curve(const Object& object, const FrameOptions& options) {
  const bool planar = is_planar_curve(object.kind);
  switch (object.kind) {
    case ObjectKind::Bezier2:
    case ObjectKind::Bezier3:
      return evaluate_bezier(object.points, object.steps, planar, options);
    case ObjectKind::BSpline2:
    case ObjectKind::BSpline3:
      return evaluate_bspline(object.points, object.steps, planar, options);
    case ObjectKind::Circle:
      return evaluate_circle(object.radius, object.steps);
    case ObjectKind::CatmullRom2:
    case ObjectKind::CatmullRom3:
      return evaluate_catmull_rom(object.points, object.steps, object.alpha, object.tension, planar, options);
    case ObjectKind::KochanekBartels2:
    case ObjectKind::KochanekBartels3:
      return evaluate_kochanek_bartels(object.points, object.steps, {object.tension, object.continuity, object.bias},
                                       planar, options);
    case ObjectKind::Helix:
      return evaluate_helix(object.radius, object.pitch, object.turns, object.steps, options);
    case ObjectKind::TorusKnot:
      return evaluate_torus_knot({object.knot_p, object.knot_q, object.major_radius, object.radius}, object.steps,
                                 options);
    case ObjectKind::SurfaceOfRevolution:
    case ObjectKind::GeneralizedCylinder:
      break;  // not curves
  }
  return {};
}

bool is_closed(const std::vector<Frame>& frames) {
  if (frames.size() < 3) return false;
  glm::dvec3 lo = frames.front().V, hi = lo;
  for (const auto& f : frames) {
    lo = glm::min(lo, f.V);
    hi = glm::max(hi, f.V);
  }
  const double size = vector_length(hi - lo);
  if (size <= 0.0) return false;
  const Frame& a = frames.front();
  const Frame& b = frames.back();
  // Relative tolerances: files write coordinates with about 6 digits, evaluation adds rounding.
  return vector_length(b.V - a.V) <= 1e-6 * size && glm::dot(a.T, b.T) >= 1.0 - 1e-8;
}

}  // namespace sweep
