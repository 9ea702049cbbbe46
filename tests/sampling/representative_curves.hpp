#pragma once
// A few curves of every kind, for comparing adaptive sampling with its references
// (sampling_comparison_test.cpp and benchmarks/adaptive_report.cpp). The ones marked `varying`
// have curvature that varies a lot along them: straight runs beside tight turns, near-cusps.
#include "io/swp/read.hpp"
#include "model/document.hpp"

#include <string>
#include <vector>

namespace sweep::sampling {

struct RepresentativeCurve {
  Object curve;
  bool varying = false;  // straight runs beside tight turns, or a near-cusp
};

/// The curves as an SWP document (each name says what it shows; `varying_` prefixes mark them).
inline const char* representative_curves_swp() {
  return R"(bez2 varying_hairpin 8 10
  [0 0] [3.333333 0] [6.666667 0] [10 0]
  [10.6 0] [10.6 0.5] [10 0.5]
  [6.666667 0.5] [3.333333 0.5] [0 0.5]
bez2 varying_near_cusp 8 13
  [-3 0] [-2 0] [-1 0] [0 0]
  [1 1] [0.01 1] [1 0]
  [2 0] [3 0] [4 0]
  [5 0] [6 0] [7 0]
bez3 twisted 8 7
  [-1 -2 0] [0 -1 1] [0 1 -1] [1 -2 0]
  [2 -3 1] [3 -1 0] [3 0 0]
bsp2 varying_cusp 8 12
  [0 0] [2 0] [4 0] [6 0] [8 0] [8 0] [8 1] [8 0] [10 0] [12 0] [14 0] [16 0]
bsp3 sweep 16 11
  [-1.427273 0.424545 0.929339] [-1.767273 -1.585455 0.371157] [0.912727 -1.585455 -0.278843]
  [1.922727 -0.255455 -0.080661] [1.582727 1.374545 -1.050661] [0.912727 2.034545 -0.760661]
  [0.242727 2.094545 -0.410661] [-1.097273 1.444545 0.259339] [-1.427273 0.424545 0.929339]
  [-1.767273 -1.585455 0.371157] [0.912727 -1.585455 -0.278843]
cr2 varying_zigzag 8 6 [0 0] [4 0] [4.2 0.3] [4.4 0] [8 0] [8 3]
cr3 wave 8 5 [0 0 0] [1 1 0] [2 0 1] [3 1 1] [4 0 0]
kb2 varying_corners 8 6 tension 0.3 continuity -0.5 [0 0] [3 0] [3 3] [3.2 3.2] [6 3] [6 0]
kb3 loop 8 6 bias 0.4 [0 0 0] [1 0 0.5] [1 1 1] [0 1 0.5] [0 0.2 0] [0.8 0.2 0.2]
circ circle 16 1
helix coil 32 1 0.6 6
knot trefoil 240 2 3 2 1
)";
}

/// The curves of representative_curves_swp().
inline std::vector<RepresentativeCurve> representative_curves() {
  std::vector<RepresentativeCurve> curves;
  for (Object& o : io::parse_swp(representative_curves_swp(), "representative.swp").objects) {
    const bool varying = o.name.rfind("varying_", 0) == 0;
    curves.push_back({std::move(o), varying});
  }
  return curves;
}

}  // namespace sweep::sampling
