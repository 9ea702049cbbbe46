// Adaptive sampling of cubic Bezier pieces for a distance tolerance (Buss, 3D Computer Graphics,
// ch. VII.3: recursive subdivision instead of a uniform step).
//
// A piece is cut into parts by de Casteljau subdivision (any part [a, b] of a Bezier piece is
// again a Bezier curve; its control points are blossoms, Farin, Curves and Surfaces for CAGD,
// ch. 4). A part is flat when
//  - its hodograph's control vectors q1 - q0, q2 - q1, q3 - q2, split once by de Casteljau into
//    five (TangentCone), are at most kMaxTurn apart: the hodograph is a quadratic Bezier curve,
//    so every tangent lies in their convex cone (and the largest angle between two vectors of
//    that cone is one between its edges), the tangent turns
//    at most kMaxTurn over the part, the chord (an average of tangents) lies in the cone too, and
//    the curve's projection onto the chord runs monotonically from q0 to q3 (its distance from
//    the chord segment is its distance from the chord's line). A sub-part's control vectors are
//    combinations of its parent's, so a sub-part of a flat part passes this test too;
//  - its exact distance from the chord's line is at most D. With c1, c2 the components of
//    q1 - q0 and q2 - q0 perpendicular to the chord, the curve's perpendicular offset is
//    3 s (1 - s) ((1 - s) c1 + s c2) (q0 and q3 have none), whose largest length is found from
//    the roots of a cubic (chord_deviation). This is the chord-height test on the control points
//    made exact, instead of the control polygon's height, which overstates an arc's by 4/3.
//
// Halving a failing part would overshoot by up to 2x on evenly curved pieces. Instead each cut
// is placed as far along as the flatness test allows (a search seeded by the previous part's
// length), so the piece needs about the fewest parts any sequence of flat parts can have (the
// turn test holds for sub-parts of a flat part; the distance test nearly so, since a sub-part's
// chord differs from its parent's). Where the last part came out short, a second pass from the
// piece's other end gives the earliest place of each cut, and halfway between the two keeps the
// parts even (no sliver at the piece's end) whenever those parts are flat too. The joints
// between pieces stay samples, so corners are kept exactly.
#include "geometry/curves/adaptive.hpp"

#include "base/number_text.hpp"
#include "base/precondition.hpp"
#include "geometry/unit_vector.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace sweep {
namespace {

using Piece = std::array<glm::dvec3, 4>;

/// cos(kMaxTurn): the largest angle between two tangents of a flat part.
const double kTurnCos = std::cos(kMaxTurn);

/// Parts shorter than this (in the piece's parameter) are accepted whatever they look like: the
/// depth limit, so cusps and coincident control points always end.
constexpr double kMinPart = 1e-7;

/// Control points closer together than this, relative to their coordinates, differ by rounding.
constexpr double kRounding = 1e-14;

glm::dvec3 lerp(const glm::dvec3& a, const glm::dvec3& b, double t) {
  return a + t * (b - a);
}

/// The real roots in (0, 1) of c0 + c1 s + c2 s^2 + c3 s^3 (at most 3), written to `roots`;
/// returns how many. The interval is cut at the roots of the derivative, and each cut with a sign
/// change is searched by Newton's method kept inside its bracket by bisection.
int unit_interval_roots(double c0, double c1, double c2, double c3, double (&roots)[3]) {
  int found = 0;
  const auto value = [&](double s) { return c0 + s * (c1 + s * (c2 + s * c3)); };
  const auto slope = [&](double s) { return c1 + s * (2.0 * c2 + 3.0 * s * c3); };
  double cuts[4] = {0.0, 0.0, 0.0, 1.0};
  int count = 1;
  // Roots of the derivative 3 c3 s^2 + 2 c2 s + c1.
  const double a = 3.0 * c3, b = 2.0 * c2;
  if (std::abs(a) > 1e-300) {
    const double disc = b * b - 4.0 * a * c1;
    if (disc >= 0.0) {
      const double q = -0.5 * (b + std::copysign(std::sqrt(disc), b));
      for (const double r : {q / a, q != 0.0 ? c1 / q : 0.0}) {
        if (r > 0.0 && r < 1.0) cuts[count++] = r;
      }
    }
  } else if (std::abs(b) > 1e-300) {
    const double r = -c1 / b;
    if (r > 0.0 && r < 1.0) cuts[count++] = r;
  }
  if (count == 3 && cuts[2] < cuts[1]) std::swap(cuts[1], cuts[2]);
  cuts[count] = 1.0;
  for (int i = 0; i < count; ++i) {
    double lo = cuts[i], hi = cuts[i + 1];
    double flo = value(lo), fhi = value(hi);
    if (flo == 0.0 && lo > 0.0) roots[found++] = lo;
    if (flo * fhi >= 0.0) continue;
    double s = 0.5 * (lo + hi);
    for (int iteration = 0; iteration < 60 && hi - lo > 1e-13; ++iteration) {
      const double f = value(s);
      if ((f < 0.0) == (flo < 0.0)) {
        lo = s;
        flo = f;
      } else {
        hi = s;
      }
      const double d = slope(s);
      const double newton = d != 0.0 ? s - f / d : lo;
      s = newton > lo && newton < hi ? newton : 0.5 * (lo + hi);
    }
    roots[found++] = s;
  }
  return found;
}

/// The part of p from `a` to `b` (either order: b < a gives the part reversed).
Piece part_between(const Piece& p, double a, double b) {
  return a < b ? bezier_part(p, a, b) : Piece{};
}

/// The hodograph of a part with control vectors d (q1 - q0, q2 - q1, q3 - q2) split once by de
/// Casteljau: five vectors whose convex cone holds every tangent of the part, tighter than the
/// cone of d alone where the middle vector sticks out. `used[i]` is false for vectors at
/// rounding level (no direction).
struct TangentCone {
  glm::dvec3 g[5];
  double size[5];
  bool used[5];

  TangentCone(const glm::dvec3 (&d)[3], double length) {
    g[0] = d[0];
    g[1] = 0.5 * (d[0] + d[1]);
    g[2] = 0.25 * (d[0] + 2.0 * d[1] + d[2]);
    g[3] = 0.5 * (d[1] + d[2]);
    g[4] = d[2];
    for (int i = 0; i < 5; ++i) {
      size[i] = vector_length(g[i]);
      used[i] = size[i] > 1e-12 * length;
    }
  }
  /// True if no two generators are more than kMaxTurn apart (then neither are two tangents).
  bool within_turn() const {
    for (int i = 0; i < 5; ++i) {
      for (int j = i + 1; j < 5; ++j) {
        if (used[i] && used[j] && glm::dot(g[i], g[j]) < kTurnCos * size[i] * size[j]) return false;
      }
    }
    return true;
  }
  /// 1 - cos(w / 2) for w the largest angle between two generators (a bound on the part's turn),
  /// from the smallest cosine c between them as 1 - sqrt((1 + c) / 2): no trigonometry.
  double half_turn_versine() const {
    double smallest = 1.0;
    for (int i = 0; i < 5; ++i) {
      for (int j = i + 1; j < 5; ++j) {
        if (used[i] && used[j]) smallest = std::min(smallest, glm::dot(g[i], g[j]) / (size[i] * size[j]));
      }
    }
    return 1.0 - std::sqrt(std::max(0.5 * (1.0 + smallest), 0.0));
  }
};

/// Searches from parameter `from` towards `to` (either direction) for the farthest point whose
/// part is flat, starting from the guess `step` (> 0, in the direction of travel). Returns the
/// step taken (at least kMinPart unless the rest is shorter).
double longest_flat_step(const Piece& p, double from, double to, double step, const AdaptiveTolerance& tolerance) {
  const double direction = to > from ? 1.0 : -1.0;
  const double rest = std::abs(to - from);
  const auto flat = [&](double h) {
    const double end = h >= rest ? to : from + direction * h;
    return is_flat(direction > 0.0 ? part_between(p, from, end) : part_between(p, end, from), tolerance);
  };
  double good = 0.0, bad = rest;
  double h = std::clamp(step, std::min(kMinPart, rest), rest);
  if (flat(h)) {
    good = h;
    while (good < rest) {  // grow until the part is no longer flat or reaches the end
      h = std::min(good * 1.5, rest);
      if (!flat(h)) {
        bad = h;
        break;
      }
      good = h;
    }
    if (good >= rest) return rest;
  } else {
    bad = h;
    for (h *= 0.5; h >= kMinPart; h *= 0.5) {
      if (flat(h)) break;
      bad = h;
    }
    if (h < kMinPart) return std::min(kMinPart, rest);  // the depth limit
    good = h;
  }
  // The distance test is not monotone: across an inflection the chord turns with the part and
  // a longer part can be flat again. Probe past the first failure, longest first.
  for (const double factor : {2.0, 1.6, 1.25}) {
    const double probe = bad * factor;
    if (probe >= rest) continue;
    if (flat(probe)) {
      good = probe;
      bad = std::min(probe * 1.25, rest);
      if (bad >= rest && flat(rest)) return rest;
      break;
    }
  }
  while (bad - good > 0.02 * good) {  // the cut to within 2 % of the part's length
    const double mid = 0.5 * (good + bad);
    if (flat(mid)) {
      good = mid;
    } else {
      bad = mid;
    }
  }
  return good;
}

/// The cuts of a piece walked from `from` (0 or 1) to the other end, in the order found.
bool walk(const Piece& p, double from, const AdaptiveTolerance& tolerance, std::size_t max_cuts,
          std::vector<double>& cuts) {
  const double to = 1.0 - from;
  double t = from;
  double step = 1.0;
  while (t != to) {
    if (cuts.size() > max_cuts) return false;
    step = longest_flat_step(p, t, to, step, tolerance);
    const double next = to > from ? t + step : t - step;
    t = std::abs(to - next) <= 1e-12 ? to : next;
    cuts.push_back(t);
  }
  return true;
}

}  // namespace

std::array<glm::dvec3, 4> bezier_part(const std::array<glm::dvec3, 4>& p, double a, double b) {
  SWEEP_EXPECTS(a >= 0.0 && a < b && b <= 1.0, "0 <= a < b <= 1");
  // First de Casteljau level at a and at b, then the blossoms with two and three arguments.
  const glm::dvec3 la[3] = {lerp(p[0], p[1], a), lerp(p[1], p[2], a), lerp(p[2], p[3], a)};
  const glm::dvec3 lb[3] = {lerp(p[0], p[1], b), lerp(p[1], p[2], b), lerp(p[2], p[3], b)};
  const glm::dvec3 aa[2] = {lerp(la[0], la[1], a), lerp(la[1], la[2], a)};
  const glm::dvec3 ab[2] = {lerp(la[0], la[1], b), lerp(la[1], la[2], b)};
  const glm::dvec3 bb[2] = {lerp(lb[0], lb[1], b), lerp(lb[1], lb[2], b)};
  return {lerp(aa[0], aa[1], a), lerp(aa[0], aa[1], b), lerp(ab[0], ab[1], b), lerp(bb[0], bb[1], b)};
}

double chord_deviation(const std::array<glm::dvec3, 4>& q) {
  const glm::dvec3 chord = q[3] - q[0];
  const double length = vector_length(chord);
  if (length == 0.0) return std::max({vector_length(q[1] - q[0]), vector_length(q[2] - q[0])});
  const glm::dvec3 u = chord / length;
  const auto perpendicular = [&](const glm::dvec3& v) { return v - glm::dot(v, u) * u; };
  const glm::dvec3 c1 = perpendicular(q[1] - q[0]);
  const glm::dvec3 c2 = perpendicular(q[2] - q[0]);
  // |offset|^2 = 9 s^2 (1-s)^2 rho(s), rho = A (1-s)^2 + 2 B s (1-s) + C s^2 = A + 2 e s + k s^2.
  const double A = glm::dot(c1, c1), B = glm::dot(c1, c2), C = glm::dot(c2, c2);
  const double e = B - A, k = A - 2.0 * B + C;
  const auto offset = [&](double s) {
    return 3.0 * s * (1.0 - s) * std::sqrt(std::max(A + s * (2.0 * e + s * k), 0.0));
  };
  // d/ds of s^2 (1-s)^2 rho = s (1-s) h(s), h(s) = 2 (1 - 2s) rho + s (1-s) rho'
  //   = 2A + (6e - 4A) s + (4k - 10e) s^2 - 6k s^3.
  double roots[3];
  const int count = unit_interval_roots(2.0 * A, 6.0 * e - 4.0 * A, 4.0 * k - 10.0 * e, -6.0 * k, roots);
  double largest = 0.0;
  for (int i = 0; i < count; ++i) largest = std::max(largest, offset(roots[i]));
  return largest;
}

bool is_flat(const std::array<glm::dvec3, 4>& q, const AdaptiveTolerance& tolerance) {
  const double length = vector_length(q[3] - q[0]);
  const glm::dvec3 d[3] = {q[1] - q[0], q[2] - q[1], q[3] - q[2]};
  // A part whose control points differ only by rounding is a point (coincident control points
  // converted to Bezier form, e.g. (P + 4P + P) / 6, need not give P again): no turn to test.
  double reach = 0.0, magnitude = 0.0;
  for (const glm::dvec3& c : q) {
    reach = std::max(reach, vector_length(c - q[0]));
    magnitude = std::max({magnitude, std::abs(c.x), std::abs(c.y), std::abs(c.z)});
  }
  if (reach <= kRounding * magnitude) return true;
  // Any other part whose ends meet is a loop or a spike: its tangent turns by more than kMaxTurn,
  // so it is cut even if it is smaller than D (and the tube of a sweep turns with it).
  if (length == 0.0) return false;
  const TangentCone cone(d, length);
  if (!cone.within_turn()) return false;
  double deviation = chord_deviation(q);
  if (tolerance.offset > 0.0) deviation += tolerance.offset * cone.half_turn_versine();
  return deviation <= tolerance.distance;
}

bool adaptive_piece_parameters(const std::array<glm::dvec3, 4>& p, const AdaptiveTolerance& tolerance,
                               std::size_t max_samples, std::vector<double>& out) {
  SWEEP_EXPECTS(tolerance.adaptive(), "tolerance.adaptive()");
  const std::size_t room = max_samples > out.size() ? max_samples - out.size() : 0;
  std::vector<double> forward;
  if (!walk(p, 0.0, tolerance, room, forward)) return false;
  std::vector<double> backward;
  // Only a short last part (a sliver in a mesh) is worth the second walk.
  const std::size_t parts = forward.size();
  const bool sliver = parts > 1 && 1.0 - forward[parts - 2] < 0.5 * forward[parts - 2] / static_cast<double>(parts - 1);
  if (sliver && walk(p, 1.0, tolerance, parts, backward) && backward.size() == parts) {
    // backward holds the cuts from the end: cut i from the start is backward[n - 2 - i].
    const std::size_t n = forward.size();
    std::vector<double> even(n);
    for (std::size_t i = 0; i + 1 < n; ++i) even[i] = 0.5 * (forward[i] + backward[n - 2 - i]);
    even[n - 1] = 1.0;
    bool flat = true;
    for (std::size_t i = 0; i < n && flat; ++i) {
      const double a = i == 0 ? 0.0 : even[i - 1];
      flat = a < even[i] && is_flat(bezier_part(p, a, even[i]), tolerance);
    }
    if (flat) forward = std::move(even);
  }
  out.insert(out.end(), forward.begin(), forward.end());
  return out.size() <= max_samples;
}

int circle_segments(double radius, double tolerance) {
  SWEEP_EXPECTS(radius > 0.0 && tolerance > 0.0, "r > 0, D > 0");
  const double minimum = 2.0 * std::numbers::pi / kMaxTurn;
  const double angle = std::acos(std::clamp(1.0 - tolerance / radius, -1.0, 1.0));  // pi / n at most
  const double needed = angle > 0.0 ? std::ceil(std::numbers::pi / angle) : 1e9;
  return static_cast<int>(std::min(std::max(needed, minimum), 1e9));
}

std::string check_tolerance(double tolerance, double extent, const std::string& what) {
  if (!(tolerance > 0.0) || !std::isfinite(tolerance)) return "expected a tolerance > 0";
  if (tolerance < kMinRelativeTolerance * extent) {
    return "expected a tolerance of at least " + number_text(kMinRelativeTolerance) + " of " + what + "'s size (" +
           number_text(extent) + ")";
  }
  return "";
}

}  // namespace sweep
