#include "editor/curvature_comb.hpp"

#include "base/precondition.hpp"
#include "geometry/curves/curve_curvature.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace sweep::editor {
namespace {

/// The curvature and the curvature vector of one point with derivatives `d`.
void add_needle(CurvatureComb& comb, const glm::dvec3& base, const PieceDerivatives& d, bool planar, double length) {
  const glm::dvec3 vector = curvature_vector(d);
  comb.bases.push_back(base);
  comb.tips.push_back(base - vector);  // scaled below, once the scale is known
  comb.curvature.push_back(planar ? signed_curvature(d) : glm::length(vector));
  comb.arc_length.push_back(length);
}

/// A whole parameter strictly inside a curve of pieces: where two pieces meet.
bool is_joint(double parameter, double last, bool pieces) {
  return pieces && parameter > 0.0 && parameter < last && parameter == std::floor(parameter);
}

}  // namespace

double default_comb_scale(const std::vector<double>& curvature, double extent) {
  double largest = 0.0;
  for (double k : curvature) largest = std::max(largest, std::abs(k));
  if (!(largest > 0.0) || !(extent > 0.0) || !std::isfinite(largest)) return 1.0;
  return 0.2 * extent / largest;
}

CurvatureComb curvature_comb(const Object& curve, const CurveSamples& samples, double factor) {
  SWEEP_EXPECTS(is_curve(curve.kind()), "curve must be a curve");
  SWEEP_EXPECTS(samples.parameters.size() == samples.frames.size(), "samples must carry one parameter per sample");
  SWEEP_EXPECTS(factor > 0.0, "factor must be positive");
  const CurveDescriptor descriptor = describe_curve(curve);
  const bool pieces = descriptor.basis->control_points;
  const double last = samples.parameters.empty() ? 0.0 : samples.parameters.back();
  CurvatureComb comb;
  double length = 0.0;
  for (std::size_t i = 0; i < samples.frames.size(); ++i) {
    const glm::dvec3& base = samples.frames[i].V;
    if (i > 0) length += glm::distance(samples.frames[i - 1].V, base);
    const double t = samples.parameters[i];
    if (is_joint(t, last, pieces)) {
      // The piece before ends here too: its needle first, so a jump breaks the tip line.
      const double before = std::nextafter(t, -std::numeric_limits<double>::infinity());
      add_needle(comb, base, curve_derivatives(descriptor, before), samples.planar, length);
      comb.joint_arc_lengths.push_back(length);
    }
    add_needle(comb, base, curve_derivatives(descriptor, t), samples.planar, length);
  }
  comb.scale = factor * default_comb_scale(comb.curvature, curve_extent(curve));
  for (std::size_t i = 0; i < comb.tips.size(); ++i) {
    comb.tips[i] = comb.bases[i] + comb.scale * (comb.tips[i] - comb.bases[i]);
  }
  return comb;
}

std::vector<OverlayBatch> comb_overlay(const CurvatureComb& comb, const glm::vec3& color) {
  OverlayBatch needles;
  needles.primitive = OverlayBatch::Primitive::Lines;
  needles.color = color * 0.7f;
  OverlayBatch outline;
  outline.primitive = OverlayBatch::Primitive::LineStrip;
  outline.color = color;
  for (std::size_t i = 0; i < comb.bases.size(); ++i) {
    needles.positions.emplace_back(comb.bases[i]);
    needles.positions.emplace_back(comb.tips[i]);
    outline.positions.emplace_back(comb.tips[i]);
  }
  return {needles, outline};
}

std::vector<float> curvature_plot(const CurvatureComb& comb, int count) {
  SWEEP_EXPECTS(count >= 2, "count must be at least 2");
  std::vector<float> values;
  if (comb.arc_length.empty()) return values;
  const double total = comb.arc_length.back();
  std::size_t i = 0;
  for (int k = 0; k < count; ++k) {
    const double s = total * double(k) / double(count - 1);
    while (i + 1 < comb.arc_length.size() && comb.arc_length[i + 1] <= s) ++i;
    double value = comb.curvature[i];
    if (i + 1 < comb.arc_length.size() && comb.arc_length[i + 1] > comb.arc_length[i]) {
      const double u = (s - comb.arc_length[i]) / (comb.arc_length[i + 1] - comb.arc_length[i]);
      value += u * (comb.curvature[i + 1] - comb.curvature[i]);
    }
    values.push_back(float(value));
  }
  return values;
}

}  // namespace sweep::editor
