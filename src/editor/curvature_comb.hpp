#pragma once
// A curve's curvature comb, as Rhino's and Alias's curvature graphs: at every sample a needle
// across the curve, as long as the curvature there times a scale, pointing away from the centre
// of the bend (minus the curvature vector: for a 2D curve -kappa N, N = +z x T), the needle tips
// joined by a line, so a designer sees where a curve bends more, less, or jumps. Curvature comes
// from the curve's exact derivatives (curve_curvature.hpp), not from the samples. At a joint of
// pieces the comb has two needles, the end of the piece before and the start of the one after,
// so a curvature jump (or a corner) shows as a break in the tip line. No GL.
#include "geometry/curves/curve.hpp"
#include "geometry/mesh/overlay.hpp"
#include "model/object.hpp"

#include <glm/vec3.hpp>

#include <vector>

namespace sweep::editor {

inline const glm::vec3 kCombColor{0.35f, 0.85f, 0.45f};

struct CurvatureComb {
  std::vector<glm::dvec3> bases;  // on the curve: the samples, a joint's twice
  std::vector<glm::dvec3> tips;   // bases - scale * curvature vector
  /// Signed for a 2D curve (positive where it turns left), the magnitude for a 3D one; 1/r on a
  /// circle of radius r.
  std::vector<double> curvature;
  std::vector<double> arc_length;         // along the samples' polyline from the first
  std::vector<double> joint_arc_lengths;  // where the pieces meet (control-point curves)
  double scale = 0.0;                     // needle length per unit of curvature (model units squared)
};

/// The needle length per unit of curvature that makes the longest needle a fifth of `extent`
/// (the curve's size); 1 when the curve is straight everywhere or `extent` is not positive.
double default_comb_scale(const std::vector<double>& curvature, double extent);

/// The comb of `curve` over its samples `samples` (the scene's evaluation of it), needles
/// `factor` times default_comb_scale long. Preconditions: is_curve(curve.kind()); `samples` are
/// its samples, with their parameters; factor > 0. O(samples).
CurvatureComb curvature_comb(const Object& curve, const CurveSamples& samples, double factor);

/// The comb as overlay lines: the needles and the line through their tips, in `color`.
std::vector<OverlayBatch> comb_overlay(const CurvatureComb& comb, const glm::vec3& color = kCombColor);

/// The comb's curvature at `count` (>= 2) evenly spaced arc lengths from the first sample to the
/// last (linear between samples; at a joint the value after it), for a plot.
std::vector<float> curvature_plot(const CurvatureComb& comb, int count);

}  // namespace sweep::editor
