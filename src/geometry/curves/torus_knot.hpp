#pragma once
// Torus knots, evaluated exactly (torus_knot.cpp).
#include "geometry/curves/curve.hpp"

namespace sweep {

/// The torus knot basis (torus_knot.cpp): always closed.
extern const CurveBasis kTorusKnotBasis;

/// Shape of a (P, Q) torus knot on the torus of radii R (centre to tube centre) and r (tube).
struct TorusKnotShape {
  int p = 2;                  // turns about the torus axis (+z)
  int q = 3;                  // turns through the hole
  double major_radius = 2.0;  // R
  double minor_radius = 1.0;  // r
};

/// The (P, Q) torus knot x = (R + r cos Qt) cos Pt, y = (R + r cos Qt) sin Pt, z = r sin Qt,
/// t in [0, 2 pi]: steps + 1 samples, the last exactly the first, closed. Tangents and curvature
/// come from the analytic derivatives; the frames are the 3D frames of compute_frames, the seam
/// closed by close_frames when options.close_seam.
/// Preconditions: steps >= 1; P, Q >= 1 (coprime for a knot); 0 < r < R <= limits::kMaxCoordinate.
CurveSamples evaluate_torus_knot(const TorusKnotShape& shape, int steps, const FrameOptions& options = {});

/// A point of the knot c(t), t in [0, 2 pi], with its first two derivatives.
struct KnotPoint {
  glm::dvec3 position;
  glm::dvec3 d1;  // dc/dt
  glm::dvec3 d2;  // d^2c/dt^2
};
KnotPoint knot_point(const TorusKnotShape& shape, double t);

/// The curve parameters (0..1, first 0, last 1) of the knot's adaptive samples: chords within
/// tolerance.distance of the knot (and of a tube of radius tolerance.offset about it), turning at
/// most kMaxTurn. Empty if there would be more than max_samples. Precondition: tolerance.adaptive().
std::vector<double> torus_knot_parameters(const TorusKnotShape& shape, const AdaptiveTolerance& tolerance,
                                          std::size_t max_samples);

}  // namespace sweep
