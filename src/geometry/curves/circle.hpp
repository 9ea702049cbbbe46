#pragma once
// The circle basis (circle.cpp): a counterclockwise circle about the origin in the xy-plane,
// always closed. evaluate_circle is declared in curve.hpp.

namespace sweep {

struct CurveBasis;
extern const CurveBasis kCircleBasis;

}  // namespace sweep
