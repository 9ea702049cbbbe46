#pragma once
// The curvature of a curve from its exact derivatives, for curvature combs: the curvature vector
// kappa n (n the principal normal, towards the centre of the osculating circle) and, for curves
// in the xy-plane, the signed curvature.
#include "geometry/curves/bezier.hpp"

#include <glm/vec3.hpp>

namespace sweep {

/// The curvature vector (c' x c'') x c' / |c'|^4 of a point with derivatives `d`: length kappa
/// (1/r on a circle of radius r), pointing to the centre of the osculating circle; zero where
/// c' vanishes (|c'| <= 1e-300: no direction) or the curve is straight there.
glm::dvec3 curvature_vector(const PieceDerivatives& d);

/// The signed curvature of a curve in the xy-plane, (x'y'' - y'x'') / |c'|^3: positive where it
/// turns left (towards N = +z x T, Sweep's 2D normal), so kappa N is its curvature vector. Zero
/// where c' vanishes.
double signed_curvature(const PieceDerivatives& d);

}  // namespace sweep
