#pragma once
// Measuring how far a sampling is from the exact curve or surface: against a reference denser
// than the sampling, at exact points (curve_position, evaluate_curve_at) between the samples.
// `sweep info --tolerance` prints it, the tests and benchmarks check the adaptive bound with it.
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/scene.hpp"

namespace sweep {

/// The largest distance of the curve from the polyline of its samples: at `density` - 1 evenly
/// spaced curve parameters inside each chord (so the reference is `density` times denser), the
/// distance of the exact curve point from that chord's segment.
/// Preconditions: `samples` came from evaluate_curve(curve, ...); density >= 1.
double curve_deviation(const Object& curve, const CurveSamples& samples, int density = 64);

/// The largest distance of surface `index` from its mesh: on a density x density grid of exact
/// surface points inside each quad of the mesh's grid (so the reference is density^2 times
/// denser), the distance of the point from the quad's two triangles. A generalized cylinder's
/// exact sweep frames are those of its sweep sampled at the reference's parameters. Skipped are
/// quads the mitre of a corner of the sweep reaches (within r tan(half the turn) of it: the
/// mitre and its clipping are no part of the exact surface), where the
/// tube folds over itself (curvature times profile radius >= 1: no surface to be close to) and
/// at the seam of the symmetric seam mode. Not measured (NaN; deviation_is_measured) for birail
/// surfaces and generalized cylinders with a scale or twist: their exact surface depends on arc
/// length, which the sampling only approximates, and the adaptive bound does not cover them.
/// Caps are flat and exact: they add nothing. Preconditions: scene = evaluate_document(doc,
/// options), index is a surface, density >= 1.
double surface_deviation(const Document& doc, const Scene& scene, int index, const EvaluationOptions& options,
                         int density = 8);

/// False for the surfaces surface_deviation does not measure.
bool deviation_is_measured(const Object& surface);

/// Distance from p to the segment from a to b (to a when they coincide).
double point_segment_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b);

/// Distance from p to the triangle (a, b, c) (Ericson, Real-Time Collision Detection, 5.1.5).
double point_triangle_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

}  // namespace sweep
