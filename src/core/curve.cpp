#include "core/curve.hpp"

#include "core/bezier.hpp"

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
  return std::max(glm::length(hi - lo), 1e-300);
}

/// Unit tangent of a Bezier piece at t. Where the first derivative vanishes (repeated control
/// points, cusps) the direction of the first non-zero higher derivative is the limit of the
/// tangent; approached from the left (t = 1) the second derivative's sign flips.
/// Returns a zero vector if every derivative vanishes (all four points coincide).
glm::dvec3 piece_tangent(const PieceDerivatives& d, double t, double scale) {
  const double eps = 1e-9 * scale;
  if (glm::length(d.d1) > eps) return glm::normalize(d.d1);
  if (glm::length(d.d2) > eps) return glm::normalize(t >= 1.0 ? -d.d2 : d.d2);
  if (glm::length(d.d3) > eps) return glm::normalize(d.d3);
  return glm::dvec3(0.0);
}

/// Gives every zero tangent the direction of travel towards the nearest distinct neighbour,
/// or the previous tangent, or +x for a curve that is a single point.
void repair_tangents(std::vector<Frame>& frames, double scale) {
  const double eps = 1e-12 * scale;
  const std::size_t n = frames.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (glm::length(frames[i].T) > 0.5) continue;
    glm::dvec3 direction(0.0);
    for (std::size_t k = i + 1; k < n; ++k) {
      if (glm::length(frames[k].V - frames[i].V) > eps) {
        direction = glm::normalize(frames[k].V - frames[i].V);
        break;
      }
    }
    if (direction == glm::dvec3(0.0)) {
      for (std::size_t k = i; k-- > 0;) {
        if (glm::length(frames[i].V - frames[k].V) > eps) {
          direction = glm::normalize(frames[i].V - frames[k].V);
          break;
        }
      }
    }
    if (direction == glm::dvec3(0.0)) direction = i > 0 ? frames[i - 1].T : glm::dvec3(1.0, 0.0, 0.0);
    frames[i].T = direction;
  }
}

/// Samples consecutive Bezier pieces (given as 4 control points each) at `steps` segments each.
template <typename PieceAt>
CurveSamples sample_pieces(std::size_t pieces, int steps, bool planar, double scale, const FrameOptions& options,
                           PieceAt piece_at) {
  CurveSamples curve;
  curve.planar = planar;
  curve.frames.resize(pieces * static_cast<std::size_t>(steps) + 1);
  std::size_t index = 0;
  for (std::size_t k = 0; k < pieces; ++k) {
    const std::array<glm::dvec3, 4> p = piece_at(k);
    const int last = k + 1 == pieces ? steps : steps - 1;  // the next piece's t = 0 is this one's t = 1
    for (int s = 0; s <= last; ++s) {
      const double t = static_cast<double>(s) / steps;
      const PieceDerivatives d = evaluate_bezier_piece(p, t);
      Frame& f = curve.frames[index++];
      f.V = d.position;
      f.T = piece_tangent(d, t, scale);
      if (planar) {
        f.V.z = 0.0;
        f.T.z = 0.0;
        if (glm::length(f.T) > 0.0) f.T = glm::normalize(f.T);
      }
    }
  }
  repair_tangents(curve.frames, scale);
  compute_frames(curve.frames, planar, options);
  curve.closed = is_closed(curve.frames);
  return curve;
}

}  // namespace

CurveSamples evaluate_bezier(const std::vector<glm::dvec3>& points, int steps, bool planar, const FrameOptions& options) {
  const std::size_t pieces = (points.size() - 1) / 3;
  return sample_pieces(pieces, steps, planar, extent(points), options, [&](std::size_t k) {
    return std::array<glm::dvec3, 4>{points[3 * k], points[3 * k + 1], points[3 * k + 2], points[3 * k + 3]};
  });
}

CurveSamples evaluate_bspline(const std::vector<glm::dvec3>& points, int steps, bool planar, const FrameOptions& options) {
  const std::size_t pieces = points.size() - 3;
  return sample_pieces(pieces, steps, planar, extent(points), options, [&](std::size_t k) {
    return bspline_piece_to_bezier({points[k], points[k + 1], points[k + 2], points[k + 3]});
  });
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
    default:
      return {};
  }
}

bool is_closed(const std::vector<Frame>& frames) {
  if (frames.size() < 3) return false;
  glm::dvec3 lo = frames.front().V, hi = lo;
  for (const auto& f : frames) {
    lo = glm::min(lo, f.V);
    hi = glm::max(hi, f.V);
  }
  const double size = glm::length(hi - lo);
  if (size <= 0.0) return false;
  const Frame& a = frames.front();
  const Frame& b = frames.back();
  // Relative tolerances: files write coordinates with about 6 digits, evaluation adds rounding.
  return glm::length(b.V - a.V) <= 1e-6 * size && glm::dot(a.T, b.T) >= 1.0 - 1e-8;
}

}  // namespace sweep
