#pragma once
// Slow reference samplings that adaptive sampling (core/adaptive.hpp) is measured against: what a
// greedy sampler with the same constraints needs, and the best uniform STEPS for a curve or a
// surface. Used by tests/sampling and benchmarks/adaptive_report.cpp (docs/adaptive-sampling.md),
// never by the tool itself. Every distance is measured, not estimated: exact curve points
// (curve_position) against chords, and core/deviation.hpp for curves and meshes.
#include "model/document.hpp"
#include "model/evaluation/scene.hpp"

#include <cstddef>
#include <vector>

namespace sweep::sampling {

/// Exact points a greedy step is checked at: `kGreedyDensity` - 1 inside the step (and the
/// tangent at `kGreedyDensity` + 1 points, both ends included).
inline constexpr int kGreedyDensity = 64;

/// The number of samples (both ends included; a closed curve's last sample is counted as the
/// adaptive sampling counts it) that a greedy sampler needs for `curve` within `tolerance`:
/// from each sample it takes the longest step whose chord stays within `tolerance` of the curve
/// and whose tangents all stay within kMaxTurn / 2 of the chord, the constraints the adaptive
/// sampling keeps. Like it, every joint between cubic pieces is a sample (steps never cross one)
/// and steps shorter than 1e-7 of a piece are taken as they are (the depth limit at cusps);
/// circles, helices and torus knots are one range of their curve parameter (turns for a helix).
/// A step is checked at kGreedyDensity - 1 exact points inside it (distance from the chord
/// segment) and at kGreedyDensity + 1 tangents (tangents where the derivative vanishes are
/// skipped, as the adaptive test skips vanishing hodograph vectors); the cone is 1e-9 radians
/// wider than the adaptive test's, so that a step exactly at its edge (a circle's 8 segments) is
/// not lost to rounding. The longest step is the largest passing one of the steps rest / 1.25^k
/// (rest: to the end of the piece), refined by bisection to 1e-9 of its length: scanning from
/// the far end matters, since a step may pass while a shorter one fails (the cone is measured
/// against the chord, which turns as the step grows). Greedy steps are the fewest possible when
/// sub-steps of a passing step pass too; that holds nearly, so this is a near lower bound.
/// Cost: about 40 checks of up to 2 kGreedyDensity curve evaluations per sample (a check stops
/// at its first failing point): about a millisecond per hundred samples; tests and benchmarks only.
/// Preconditions: is_curve(curve.kind()), a valid curve; tolerance > 0.
std::size_t greedy_sample_count(const Object& curve, double tolerance);
/// The curve parameters (CurveSamples::parameters' units) of the greedy sampler's samples.
std::vector<double> greedy_parameters(const Object& curve, double tolerance);

/// The best uniform sampling of a curve for a tolerance.
struct UniformCurve {
  int steps = 0;            // STEPS (per piece; circle, knot: in all; helix: per turn)
  std::size_t samples = 0;  // samples it gives (curve_sample_count)
  double deviation = 0.0;   // its measured deviation (curve_deviation, density 64)
  bool found = false;       // false: even limits::kMaxSteps is not within the tolerance
};

/// The smallest STEPS whose uniform sampling (the curve evaluated by STEPS, its own tolerance
/// clause removed) has a measured deviation (curve_deviation, density 64) at most `tolerance`.
/// With `turn_limit`, also every tangent within kMaxTurn / 2 of its chord (checked at
/// kGreedyDensity + 1 tangents per chord), the adaptive sampling's other constraint; without it
/// (the default, the plain uniform reference) the uniform sampling may turn as far as it likes.
/// Found by doubling, bisection (the deviation falls with STEPS) and then a check of the 8
/// counts below the one found, continued downwards while one of them passes, so a mildly
/// non-monotonic deviation does not overstate the count.
/// Cost: about 2 log2(STEPS) + 8 evaluations, each of about 64 STEPS * pieces curve points.
/// Preconditions: is_curve(curve.kind()), a valid curve; tolerance > 0.
UniformCurve best_uniform_steps(const Object& curve, double tolerance, bool turn_limit = false);

/// The uniform STEPS Wang's formula gives for a control-point curve: a cubic Bezier piece
/// sampled at n even steps stays within (3 / 4) M / n^2 of its polyline, M the largest second
/// difference |P_i - 2 P_i+1 + P_i+2| of its control points (Wang 1984, in Goldman, Pyramid
/// Algorithms, 2003), so n = ceil(sqrt(3 M / (4 tolerance))); STEPS is the largest n over the
/// pieces (at least 1). A sufficient count, not the smallest: best_uniform_steps measures that.
/// 0 for circles, helices and torus knots. Cost: one pass over the pieces.
/// Preconditions: is_curve(curve.kind()), a valid curve; tolerance > 0.
int wang_uniform_steps(const Object& curve, double tolerance);

/// The best uniform sampling of a surface for a target deviation.
struct UniformSurface {
  int profile_steps = 0;      // the profile curve's STEPS
  int sweep_steps = 0;        // gcyl: the sweep curve's STEPS; srev: its STEPS (copies)
  std::size_t triangles = 0;  // triangles of that mesh
  double deviation = 0.0;     // its measured deviation (surface_deviation at `density`)
  int measured = 0;           // meshes the search built and measured
  bool found = false;         // false: no pair within the search's bounds met the target
};

/// A copy of the objects surface `index` needs (its profile, its sweep, itself, in that order)
/// sampled by STEPS: every tolerance clause removed, the profile's STEPS `profile_steps`, the
/// sweep's (gcyl) or the surface's own (srev) `sweep_steps`. The surface is the last object.
/// Preconditions: doc.objects[index] is a surface whose profile is not its sweep; steps >= 1.
Document uniform_surface_document(const Document& doc, int index, int profile_steps, int sweep_steps);

/// The pair (profile STEPS, sweep STEPS or srev copies), each chosen freely, whose uniform mesh
/// has the fewest triangles among those whose measured deviation (surface_deviation at
/// `density`, with `options` but no tolerance) is at most `target`. The search starts from
/// the best uniform counts of the profile and the sweep for target / 2 (the srev's turn: the
/// circle count of the profile's largest radius), grows both by 1.25 until the target is met,
/// then walks the profile STEPS down and up from there on a grid (ratio 1.06, at least 1) until
/// the triangles pass 1.3 times the best twice in a row (or nothing passes twice), and finally
/// tries every profile STEPS between the best grid point's neighbours. For each profile STEPS
/// the smallest passing sweep STEPS is found by growing from the previous one, bisection (the
/// deviation falls with it) and a look at the 4 counts below, continued while one passes. The
/// sweep STEPS are searched up to 4 times, the profile STEPS up to 4 times the start's (plus 4).
/// Checked against an exhaustive search on small meshes (sampling_comparison_test.cpp).
/// Cost: typically 30 to 200 meshes of about the uniform optimum's size, each measured at
/// (density + 1)^2 points per quad: well under a second at 1e-3 of a starter file's size,
/// about 10 s at 1e-4. Meshes over 20 million triangles are not built (treated as failing).
/// Preconditions: doc.objects[index] is a surface whose profile is not its sweep; target > 0;
/// density >= 1.
UniformSurface best_uniform_surface(const Document& doc, int index, double target, int density = 4,
                                    const EvaluationOptions& options = {});

/// A copy of `doc` sampled by STEPS with about the sample counts the adaptive evaluation with
/// `options` (options.tolerance > 0) gives: each curve's STEPS from the samples its surface's
/// sampling (surface_sampling) gives it (the largest if several surfaces use it; a curve no
/// surface uses: its own adaptive samples), each srev's STEPS from its adaptive copies, every
/// tolerance clause removed. For comparing the time of adaptive and uniform evaluation of the
/// same output size. Cost: one adaptive evaluation. Precondition: a valid document.
Document same_size_uniform_document(const Document& doc, const EvaluationOptions& options);

}  // namespace sweep::sampling
