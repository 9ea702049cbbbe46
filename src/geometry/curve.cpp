#include "geometry/curve.hpp"

#include "geometry/bezier.hpp"
#include "geometry/catmull_rom.hpp"
#include "geometry/helix.hpp"
#include "geometry/kochanek_bartels.hpp"
#include "geometry/limits.hpp"
#include "geometry/polyline.hpp"
#include "geometry/precondition.hpp"
#include "geometry/torus_knot.hpp"
#include "geometry/unit_vector.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

namespace sweep {
namespace {

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

/// Joints whose arriving and leaving tangents differ by more than this (radians) are corners.
constexpr double kCornerAngle = 1e-6;

/// Where the samples of each cubic piece go: `steps` evenly, adaptively for `tolerance`, or at
/// the given curve parameters (sorted; pieces: piece k covers k..k+1).
struct PieceSampling {
  int steps = 1;
  AdaptiveTolerance tolerance;
  std::span<const double> at;
};

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

/// Samples consecutive Bezier pieces (given as 4 control points each) as `sampling` says
/// (CurveSamples::steps is 0 unless evenly).
template <typename PieceAt>
CurveSamples sample_pieces(std::size_t pieces, const PieceSampling& sampling, bool planar, bool tangent_continuous,
                           double scale, const FrameOptions& options, PieceAt piece_at) {
  CurveSamples curve;
  curve.planar = planar;
  const bool uniform = sampling.at.empty() && !sampling.tolerance.adaptive();
  curve.steps = uniform ? sampling.steps : 0;
  const std::size_t expected = uniform               ? pieces * static_cast<std::size_t>(sampling.steps) + 1
                               : sampling.at.empty() ? 2 * pieces + 1
                                                     : sampling.at.size();
  curve.frames.reserve(expected);
  curve.curvature.reserve(expected);
  curve.parameters.reserve(expected);
  // Joints whose leaving tangent is still zero are decided after the repair.
  std::vector<Corner> pending;
  const auto is_corner = [](const glm::dvec3& incoming, const glm::dvec3& leaving) {
    return std::atan2(vector_length(glm::cross(incoming, leaving)), glm::dot(incoming, leaving)) > kCornerAngle;
  };
  std::array<glm::dvec3, 4> previous{};
  std::vector<double> ts;
  for (std::size_t k = 0; k < pieces; ++k) {
    const std::array<glm::dvec3, 4> p = piece_at(k);
    if (!piece_parameters(p, k, pieces, sampling, curve.frames.size(), ts)) {
      CurveSamples capped =
          sample_pieces(pieces, {sampling.steps, {}, {}}, planar, tangent_continuous, scale, options, piece_at);
      capped.capped = true;
      return capped;
    }
    for (const double t : ts) {
      const PieceDerivatives d = evaluate_bezier_piece(p, t);
      const std::size_t index = curve.frames.size();
      curve.curvature.push_back(curvature_of(d, scale));
      curve.parameters.push_back(static_cast<double>(k) + t);
      Frame& f = curve.frames.emplace_back();
      f.V = d.position;
      f.T = planar_tangent(piece_tangent(d, t, scale), planar);
      if (planar) f.V.z = 0.0;
      // A joint (the next piece's t = 0) is a corner if the previous piece arrives at t = 1 with
      // another tangent. A B-spline's derivative is continuous, so only a vanishing one can jump.
      if (t == 0.0 && k > 0 && !(tangent_continuous && vector_length(d.d1) > 1e-9 * scale)) {
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

CurveSamples evaluate_bezier(std::span<const glm::dvec3> points, int steps, bool planar, const FrameOptions& options,
                             const AdaptiveTolerance& tolerance) {
  SWEEP_EXPECTS(points.size() >= 4 && (points.size() - 1) % 3 == 0, "points.size() = 3n+1 with n >= 1");
  SWEEP_EXPECTS(steps >= 1, "steps >= 1");
  const std::size_t pieces = (points.size() - 1) / 3;
  return sample_pieces(pieces, {steps, tolerance, {}}, planar, false, extent(points), options, [&](std::size_t k) {
    return std::array<glm::dvec3, 4>{points[3 * k], points[3 * k + 1], points[3 * k + 2], points[3 * k + 3]};
  });
}

CurveSamples evaluate_bspline(std::span<const glm::dvec3> points, int steps, bool planar, const FrameOptions& options,
                              const AdaptiveTolerance& tolerance) {
  SWEEP_EXPECTS(points.size() >= 4, "points.size() >= 4");
  SWEEP_EXPECTS(steps >= 1, "steps >= 1");
  const std::size_t pieces = points.size() - 3;
  return sample_pieces(pieces, {steps, tolerance, {}}, planar, true, extent(points), options, [&](std::size_t k) {
    return bspline_piece_to_bezier({points[k], points[k + 1], points[k + 2], points[k + 3]});
  });
}

CurveSamples evaluate_catmull_rom(std::span<const glm::dvec3> points, int steps, double alpha, double tension,
                                  bool planar, const FrameOptions& options, const AdaptiveTolerance& tolerance) {
  SWEEP_EXPECTS(points.size() >= 2, "points.size() >= 2");
  SWEEP_EXPECTS(steps >= 1, "steps >= 1");
  SWEEP_EXPECTS(alpha >= 0.0 && alpha <= 1.0, "alpha in [0, 1]");
  SWEEP_EXPECTS(tension >= 0.0 && tension < 1.0, "tension in [0, 1)");
  const bool closed = is_closed_interpolating(points);
  // The derivative is continuous across joints (G1: each segment has its own parameter).
  return sample_pieces(points.size() - 1, {steps, tolerance, {}}, planar, true, extent(points), options,
                       [&](std::size_t k) { return catmull_rom_piece(points, k, closed, alpha, tension); });
}

CurveSamples evaluate_kochanek_bartels(std::span<const glm::dvec3> points, int steps, const KochanekBartelsShape& shape,
                                       bool planar, const FrameOptions& options, const AdaptiveTolerance& tolerance) {
  SWEEP_EXPECTS(points.size() >= 2, "points.size() >= 2");
  SWEEP_EXPECTS(steps >= 1, "steps >= 1");
  SWEEP_EXPECTS(shape.tension >= -1.0 && shape.tension <= 1.0 && shape.continuity >= -1.0 && shape.continuity <= 1.0 &&
                    shape.bias >= -1.0 && shape.bias <= 1.0,
                "tension, continuity and bias in [-1, 1]");
  const bool closed = is_closed_interpolating(points);
  return sample_pieces(points.size() - 1, {steps, tolerance, {}}, planar, shape.continuity == 0.0, extent(points),
                       options, [&](std::size_t k) { return kochanek_bartels_piece(points, k, closed, shape); });
}

CurveSamples evaluate_circle(double radius, int steps) {
  SWEEP_EXPECTS(steps >= 1, "steps >= 1");
  SWEEP_EXPECTS(radius > 0.0, "radius > 0");
  CurveSamples curve;
  curve.planar = true;
  curve.frames.resize(static_cast<std::size_t>(steps) + 1);
  for (int i = 0; i < steps; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / steps;
    curve.parameters.push_back(static_cast<double>(i) / steps);
    Frame& f = curve.frames[static_cast<std::size_t>(i)];
    f.V = radius * glm::dvec3(std::cos(angle), std::sin(angle), 0.0);
    f.T = glm::dvec3(-std::sin(angle), std::cos(angle), 0.0);
  }
  curve.frames.back() = curve.frames.front();  // exactly closed
  curve.parameters.push_back(1.0);
  compute_frames(curve.frames, true, {});
  curve.closed = true;
  curve.steps = steps;
  curve.curvature.assign(curve.frames.size(), 1.0 / radius);
  return curve;
}

bool has_control_points(CurveBasis basis) {
  return basis == CurveBasis::Bezier || basis == CurveBasis::BSpline || basis == CurveBasis::CatmullRom ||
         basis == CurveBasis::KochanekBartels || basis == CurveBasis::Polyline;
}

CurveSamples evaluate_curve(const CurveDescriptor& curve, const FrameOptions& options,
                            const AdaptiveTolerance& override) {
  const bool planar = curve.planar;
  const AdaptiveTolerance tolerance = override.adaptive() ? override : AdaptiveTolerance{curve.tolerance, 0.0};
  const bool adaptive = tolerance.adaptive();
  switch (curve.basis) {
    case CurveBasis::Bezier:
      return evaluate_bezier(curve.points, curve.steps, planar, options, tolerance);
    case CurveBasis::BSpline:
      return evaluate_bspline(curve.points, curve.steps, planar, options, tolerance);
    case CurveBasis::Circle: {
      const int n = adaptive ? circle_segments(curve.radius + tolerance.offset, tolerance.distance) : curve.steps;
      const bool capped = n >= limits::kMaxCurveSamples;
      CurveSamples samples = evaluate_circle(curve.radius, capped ? curve.steps : n);
      samples.capped = capped;
      return samples;
    }
    case CurveBasis::CatmullRom:
      return evaluate_catmull_rom(curve.points, curve.steps, curve.alpha, curve.spline.tension, planar, options,
                                  tolerance);
    case CurveBasis::KochanekBartels:
      return evaluate_kochanek_bartels(curve.points, curve.steps, curve.spline, planar, options, tolerance);
    case CurveBasis::Helix: {
      // Seen along +z a helix is a circle; its chords stray from it as far as the circle's do.
      const int n = adaptive ? circle_segments(curve.radius + tolerance.offset, tolerance.distance) : curve.steps;
      const bool capped = helix_sample_count(n, curve.turns) > limits::kMaxCurveSamples;
      CurveSamples samples = evaluate_helix(curve.radius, curve.pitch, curve.turns, capped ? curve.steps : n, options);
      samples.capped = capped;
      return samples;
    }
    case CurveBasis::Polyline:
      return evaluate_polyline(curve.points, planar, options);  // one sample per point, whatever the tolerance
    case CurveBasis::TorusKnot: {
      const TorusKnotShape shape{curve.knot_p, curve.knot_q, curve.major_radius, curve.radius};
      if (!adaptive) return evaluate_torus_knot(shape, curve.steps, options);
      const std::vector<double> at =
          torus_knot_parameters(shape, tolerance, static_cast<std::size_t>(limits::kMaxCurveSamples));
      if (!at.empty()) return evaluate_curve_at(curve, at, options);
      CurveSamples samples = evaluate_torus_knot(shape, curve.steps, options);
      samples.capped = true;
      return samples;
    }
  }
  return {};
}

namespace {

/// A point of an analytic curve (circle, helix, torus knot) at a curve parameter u, with its
/// derivatives by u.
PieceDerivatives analytic_point(const CurveDescriptor& o, double u) {
  const double turn = 2.0 * std::numbers::pi;
  const double angle = turn * u;
  const double c = std::cos(angle), s = std::sin(angle);
  PieceDerivatives d{};
  if (o.basis == CurveBasis::TorusKnot) {
    const KnotPoint k = knot_point({o.knot_p, o.knot_q, o.major_radius, o.radius}, angle);
    return {k.position, turn * k.d1, turn * turn * k.d2, glm::dvec3(0.0)};
  }
  const bool helix = o.basis == CurveBasis::Helix;  // u in turns
  d.position = glm::dvec3(o.radius * c, o.radius * s, helix ? o.pitch * u : 0.0);
  d.d1 = glm::dvec3(-turn * o.radius * s, turn * o.radius * c, helix ? o.pitch : 0.0);
  d.d2 = -turn * turn * glm::dvec3(o.radius * c, o.radius * s, 0.0);
  return d;
}

/// Runs `run(pieces, tangent_continuous, piece_at)` for a control-point curve.
template <typename Run>
CurveSamples with_pieces(const CurveDescriptor& o, Run run) {
  const std::span<const glm::dvec3> points = o.points;
  switch (o.basis) {
    case CurveBasis::Bezier:
      return run((points.size() - 1) / 3, false, [&](std::size_t k) {
        return std::array<glm::dvec3, 4>{points[3 * k], points[3 * k + 1], points[3 * k + 2], points[3 * k + 3]};
      });
    case CurveBasis::BSpline:
      return run(points.size() - 3, true, [&](std::size_t k) {
        return bspline_piece_to_bezier({points[k], points[k + 1], points[k + 2], points[k + 3]});
      });
    case CurveBasis::CatmullRom: {
      const bool closed = is_closed_interpolating(points);
      return run(points.size() - 1, true,
                 [&](std::size_t k) { return catmull_rom_piece(points, k, closed, o.alpha, o.spline.tension); });
    }
    case CurveBasis::KochanekBartels: {
      const bool closed = is_closed_interpolating(points);
      return run(points.size() - 1, o.spline.continuity == 0.0,
                 [&](std::size_t k) { return kochanek_bartels_piece(points, k, closed, o.spline); });
    }
    case CurveBasis::Polyline:  // straight cubics, so references and positions follow the segments
      return run(points.size() - 1, false, [&](std::size_t k) {
        const glm::dvec3 step = (points[k + 1] - points[k]) / 3.0;
        return std::array<glm::dvec3, 4>{points[k], points[k] + step, points[k] + 2.0 * step, points[k + 1]};
      });
    case CurveBasis::Circle:
    case CurveBasis::Helix:
    case CurveBasis::TorusKnot:
      break;
  }
  return {};
}

}  // namespace

CurveSamples evaluate_curve_at(const CurveDescriptor& curve, std::span<const double> parameters,
                               const FrameOptions& options) {
  const bool planar = curve.planar;
  if (has_control_points(curve.basis)) {
    return with_pieces(curve, [&](std::size_t pieces, bool continuous, auto piece_at) {
      return sample_pieces(pieces, {curve.steps, {}, parameters}, planar, continuous, extent(curve.points), options,
                           piece_at);
    });
  }
  CurveSamples samples;
  samples.planar = planar;
  samples.steps = 0;
  samples.parameters.assign(parameters.begin(), parameters.end());
  samples.frames.resize(parameters.size());
  samples.curvature.resize(parameters.size());
  for (std::size_t i = 0; i < parameters.size(); ++i) {
    const PieceDerivatives d = analytic_point(curve, parameters[i]);
    samples.frames[i].V = d.position;
    samples.frames[i].T = unit_vector(d.d1);
    samples.curvature[i] = curvature_of(d, 0.0);
  }
  samples.closed = is_closed(samples.frames);
  if (samples.closed) samples.frames.back() = samples.frames.front();
  compute_frames(samples.frames, planar, options);
  if (samples.closed && !planar && options.close_seam) samples.seam_angle = close_frames(samples.frames);
  return samples;
}

glm::dvec3 curve_position(const CurveDescriptor& curve, double parameter) {
  if (!has_control_points(curve.basis)) return analytic_point(curve, parameter).position;
  glm::dvec3 position(0.0);
  with_pieces(curve, [&](std::size_t pieces, bool, auto piece_at) {
    const double k = std::clamp(std::floor(parameter), 0.0, static_cast<double>(pieces - 1));
    position = evaluate_bezier_piece(piece_at(static_cast<std::size_t>(k)), parameter - k).position;
    if (curve.planar) position.z = 0.0;
    return CurveSamples{};
  });
  return position;
}

bool curve_box(const CurveDescriptor& curve, glm::dvec3& lo, glm::dvec3& hi) {
  switch (curve.basis) {
    case CurveBasis::Circle:
      lo = glm::dvec3(-curve.radius, -curve.radius, 0.0);
      hi = -lo;
      return true;
    case CurveBasis::Helix:
      lo = glm::dvec3(-curve.radius, -curve.radius, std::min(0.0, curve.pitch * curve.turns));
      hi = glm::dvec3(curve.radius, curve.radius, std::max(0.0, curve.pitch * curve.turns));
      return true;
    case CurveBasis::TorusKnot:
      hi = glm::dvec3(curve.major_radius + curve.radius, curve.major_radius + curve.radius, curve.radius);
      lo = -hi;
      return true;
    case CurveBasis::Bezier:
    case CurveBasis::BSpline:
    case CurveBasis::CatmullRom:
    case CurveBasis::KochanekBartels:
    case CurveBasis::Polyline:
      break;
  }
  if (curve.points.empty()) return false;
  lo = hi = curve.points.front();
  for (const glm::dvec3& p : curve.points) {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  return true;
}

double curve_extent(const CurveDescriptor& curve) {
  glm::dvec3 lo, hi;
  return curve_box(curve, lo, hi) ? vector_length(hi - lo) : 0.0;
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
