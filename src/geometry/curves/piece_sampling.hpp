#pragma once
// Sampling curves made of cubic Bezier pieces: the shared sampler of the control-point bases
// (Bezier, B-spline, Catmull-Rom, Kochanek-Bartels) and the basis table built from a basis's
// pieces. Internal to geometry: curve.hpp is the interface.
#include "geometry/curves/curve.hpp"
#include "geometry/unit_vector.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <span>
#include <vector>

namespace sweep::piece_detail {

/// Size of a set of points, for relative tolerances (never zero).
double extent(std::span<const glm::dvec3> points);
/// Unit tangent of a Bezier piece at t, or the limit direction where the derivative vanishes;
/// a zero vector if every derivative vanishes (all four points coincide).
glm::dvec3 piece_tangent(const PieceDerivatives& d, double t, double scale);
/// Gives every zero tangent the direction of travel to the nearest distinct sample (linear time).
void repair_tangents(std::vector<Frame>& frames, double scale);
/// |kappa| = |c' x c''| / |c'|^3, or 0 where c' vanishes.
double curvature_of(const PieceDerivatives& d, double scale);
/// A tangent confined to the xy-plane for planar curves; zero stays zero.
glm::dvec3 planar_tangent(glm::dvec3 t, bool planar);
/// Whether the tangent turns by more than float noise from `incoming` to `leaving`.
bool is_corner(const glm::dvec3& incoming, const glm::dvec3& leaving);

/// Where the samples of each cubic piece go: `steps` evenly, adaptively for `tolerance`, or at
/// the given curve parameters (sorted; pieces: piece k covers k..k+1).
struct PieceSampling {
  int steps = 1;
  AdaptiveTolerance tolerance;
  std::span<const double> at;
};

/// The parameters of piece k's samples: t = 0 and the ones after it up to, but without, t = 1,
/// which only the last piece keeps. False if adaptive samples would pass the sample cap.
bool piece_parameters(const std::array<glm::dvec3, 4>& p, std::size_t k, std::size_t pieces,
                      const PieceSampling& sampling, std::size_t samples_so_far, std::vector<double>& ts);

/// Records the joint at `index` as a corner if the previous piece arrives there with another
/// tangent (decided after the tangent repair when the leaving one is still zero: `pending`).
void note_joint(CurveSamples& curve, std::size_t index, const std::array<glm::dvec3, 4>& previous, double scale,
                std::vector<Corner>& pending);
/// Repairs tangents, merges the pending corners, computes frames and closes the seam of a curve
/// whose ends meet (`ends_meet`: the basis's rule) when its samples meet smoothly there.
void finish_pieces(CurveSamples& curve, std::vector<Corner>& pending, bool ends_meet, double scale,
                   const FrameOptions& options);

/// Samples consecutive Bezier pieces (piece_at(k): 4 control points) as `sampling` says
/// (CurveSamples::steps is 0 unless evenly). `ends_meet` is the basis's closed rule for the
/// curve; `tangent_continuous` says that only a vanishing derivative can jump at a joint.
template <typename PieceAt>
CurveSamples sample_pieces(std::size_t pieces, const PieceSampling& sampling, bool planar, bool tangent_continuous,
                           bool ends_meet, double scale, const FrameOptions& options, PieceAt piece_at) {
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
  std::vector<Corner> pending;
  std::array<glm::dvec3, 4> previous{};
  std::vector<double> ts;
  for (std::size_t k = 0; k < pieces; ++k) {
    const std::array<glm::dvec3, 4> p = piece_at(k);
    if (!piece_parameters(p, k, pieces, sampling, curve.frames.size(), ts)) {
      CurveSamples capped = sample_pieces(pieces, {sampling.steps, {}, {}}, planar, tangent_continuous, ends_meet,
                                          scale, options, piece_at);
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
      // A B-spline's derivative is continuous, so only a vanishing one can jump at a joint.
      if (t == 0.0 && k > 0 && !(tangent_continuous && vector_length(d.d1) > 1e-9 * scale)) {
        note_joint(curve, index, previous, scale, pending);
      }
    }
    previous = p;
  }
  finish_pieces(curve, pending, ends_meet, scale, options);
  return curve;
}

/// The basis table of a basis of cubic pieces. `Pieces` has static count(curve),
/// continuous(curve), closed(curve), piece_at(curve) (a function of k giving piece k's 4 Bezier
/// points) and evaluate (by steps or adaptively, with the basis's own preconditions).
template <typename Pieces>
struct PieceCurve {
  static CurveSamples evaluate_at(const CurveDescriptor& c, std::span<const double> parameters,
                                  const FrameOptions& options) {
    return sample_pieces(Pieces::count(c), {c.steps, {}, parameters}, c.planar, Pieces::continuous(c),
                         Pieces::closed(c), extent(c.points), options, Pieces::piece_at(c));
  }
  static glm::dvec3 position(const CurveDescriptor& c, double parameter) {
    const std::size_t pieces = Pieces::count(c);
    const double k = std::clamp(std::floor(parameter), 0.0, static_cast<double>(pieces - 1));
    glm::dvec3 p = evaluate_bezier_piece(Pieces::piece_at(c)(static_cast<std::size_t>(k)), parameter - k).position;
    if (c.planar) p.z = 0.0;
    return p;
  }
  static PieceDerivatives derivatives(const CurveDescriptor& c, double parameter) {
    const std::size_t pieces = Pieces::count(c);
    const double k = std::clamp(std::floor(parameter), 0.0, static_cast<double>(pieces - 1));
    PieceDerivatives d = evaluate_bezier_piece(Pieces::piece_at(c)(static_cast<std::size_t>(k)), parameter - k);
    if (c.planar) d.position.z = d.d1.z = d.d2.z = 0.0;
    return d;
  }
  static std::vector<BezierPiece> pieces(const CurveDescriptor& c) {
    const std::size_t count = Pieces::count(c);
    const auto piece_at = Pieces::piece_at(c);
    std::vector<BezierPiece> out;
    out.reserve(count);
    for (std::size_t k = 0; k < count; ++k) {
      BezierPiece& p = out.emplace_back(piece_at(k));
      if (c.planar) {
        for (glm::dvec3& point : p) point.z = 0.0;
      }
    }
    return out;
  }
  /// `straight`: the pieces are the segments between consecutive points (CurveBasis::straight).
  static constexpr CurveBasis basis(std::string_view name, bool straight = false) {
    return {name,         true,    &Pieces::evaluate, &evaluate_at, &position, nullptr, &Pieces::closed,
            &derivatives, &pieces, straight};
  }
};

}  // namespace sweep::piece_detail
