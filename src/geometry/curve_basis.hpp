#pragma once
// How a curve is defined, as geometry sees it (curve.hpp): the kinds of the document name theirs.
#include <cstdint>

namespace sweep {

/// The ways a curve is defined: by control points and a basis, or analytically.
enum class CurveBasis : std::uint8_t {
  Bezier,
  BSpline,
  CatmullRom,
  KochanekBartels,
  Circle,
  Helix,
  TorusKnot,
  Polyline,  // straight segments through the points (polyline.hpp): steps and tolerance do not apply
};

}  // namespace sweep
