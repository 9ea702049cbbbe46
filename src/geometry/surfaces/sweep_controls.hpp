#pragma once
// What places a generalized cylinder's profile besides the sweep's frames: a scale and a twist
// along the sweep, each from a 2D curve read as a graph over the sweep's arc length (or, for the
// twist, growing linearly with it), and flat caps that close a tube into a solid.
#include "geometry/curves/curve.hpp"

#include <optional>
#include <string>
#include <vector>

namespace sweep {

/// A 2D curve's value at a fraction of the sweep's arc length: its samples' x, from the first to
/// the last sample, maps to the fraction 0..1 and y is read off linearly between samples. `slope`
/// is dy per unit fraction. A fraction outside 0..1 reads the end value. Precondition: at least
/// two samples; x should never decrease (check_graph), where it does the later samples are skipped.
struct GraphValue {
  double value = 0.0;
  double slope = 0.0;
};
GraphValue graph_at(const CurveSamples& graph, double fraction);

/// What a graph is for: a scale must stay > 0; a twist (degrees) may take any value.
enum class GraphRole { Scale, Twist };

/// A problem found in the curves a surface refers to, as the reader reports it: "expected ..."
/// at the token of the clause or reference `at`, with a note naming the sample.
struct CurveProblem {
  enum class At { Profile, Rail2, Scale, Twist } at = At::Profile;
  std::string expected;
  std::string note;
};

/// The problem with a graph's samples: x decreasing (naming the sample), x not growing overall,
/// or for a scale a value <= 0; nullopt if it reads as a function of x.
std::optional<CurveProblem> check_graph(const CurveSamples& graph, GraphRole role);

/// The default mitre limit: SVG's default stroke-miterlimit (corners turning more than about
/// 151 degrees are bevelled).
inline constexpr double kMitreLimit = 4.0;

/// The scale and twist of a generalized cylinder as evaluated curves (null: none), its caps and
/// how its sharp corners are joined.
struct SweepControls {
  const CurveSamples* scale = nullptr;        // nullptr: scale 1
  const CurveSamples* twist_curve = nullptr;  // nullptr: twist_degrees, linear in arc length
  double twist_degrees = 0.0;
  bool caps = false;  // a closed profile on an open sweep gets flat end caps
  /// A corner whose mitre would stretch the profile by more than this is bevelled (surface.hpp).
  double mitre_limit = kMitreLimit;

  /// True if the profile is placed other than by the frames alone.
  bool places() const { return scale || twist_curve || twist_degrees != 0.0; }
};

/// How the controls place the profile at one sweep sample: P = V + scale (x N' + y B'), with
/// (N', B') the frame's (N, B) turned by `twist` radians counterclockwise about T. The rates
/// are per unit of the sweep's arc length; `bend` is dT/ds there (the curvature vector).
struct Station {
  double scale = 1.0;
  double twist = 0.0;
  double scale_rate = 0.0;
  double twist_rate = 0.0;
  glm::dvec3 bend{0.0};
};

/// One station per frame of the sweep, at the fraction of its chord length (arc length of the
/// samples). Precondition: frames.size() >= 2.
std::vector<Station> sweep_stations(const std::vector<Frame>& frames, const SweepControls& controls);

/// Where profile point (x, y) goes at a station away from corners: V + scale (x N' + y B'),
/// with (N', B') the frame's (N, B) turned by the station's twist about T.
glm::dvec3 place_at_station(const Frame& frame, const Station& station, double x, double y);

/// The twist (degrees) the controls give at the sweep's end minus at its start.
double total_twist_degrees(const SweepControls& controls);

}  // namespace sweep
