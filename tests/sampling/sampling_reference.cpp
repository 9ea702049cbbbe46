#include "sampling/sampling_reference.hpp"

#include "geometry/curves/adaptive.hpp"
#include "geometry/curves/bezier.hpp"
#include "geometry/curves/catmull_rom.hpp"
#include "geometry/curves/curve.hpp"
#include "geometry/curves/kochanek_bartels.hpp"
#include "geometry/curves/torus_knot.hpp"
#include "geometry/unit_vector.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/deviation.hpp"
#include "model/file_limits.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

namespace sweep::sampling {
namespace {

/// A curve as the ranges of its parameter whose ends must be samples (the cubic pieces, or the
/// whole of an analytic curve), with exact points (curve_position) and derivatives by the
/// curve parameter on each range.
class CurveRanges {
 public:
  explicit CurveRanges(const Object& curve) : curve_(curve) {
    const std::span<const glm::dvec3> points = points_of(curve);
    const auto count = static_cast<std::size_t>(piece_count(curve.kind(), static_cast<std::int64_t>(points.size())));
    switch (curve.kind()) {
      case ObjectKind::Bezier2:
      case ObjectKind::Bezier3:
        for (std::size_t k = 0; k < count; ++k) {
          pieces_.push_back({points[3 * k], points[3 * k + 1], points[3 * k + 2], points[3 * k + 3]});
        }
        break;
      case ObjectKind::BSpline2:
      case ObjectKind::BSpline3:
        for (std::size_t k = 0; k < count; ++k) {
          pieces_.push_back(bspline_piece_to_bezier({points[k], points[k + 1], points[k + 2], points[k + 3]}));
        }
        break;
      case ObjectKind::CatmullRom2:
      case ObjectKind::CatmullRom3: {
        const bool closed = is_closed_interpolating(points);
        for (std::size_t k = 0; k < count; ++k) {
          pieces_.push_back(catmull_rom_piece(points, k, closed, curve.as<sweep::AlphaPart>().alpha,
                                              curve.as<sweep::TensionPart>().tension));
        }
        break;
      }
      case ObjectKind::KochanekBartels2:
      case ObjectKind::KochanekBartels3: {
        const bool closed = is_closed_interpolating(points);
        const KochanekBartelsShape shape{curve.as<sweep::TensionPart>().tension,
                                         curve.as<sweep::ContinuityBiasPart>().continuity,
                                         curve.as<sweep::ContinuityBiasPart>().bias};
        for (std::size_t k = 0; k < count; ++k) pieces_.push_back(kochanek_bartels_piece(points, k, closed, shape));
        break;
      }
      case ObjectKind::Polyline2:
      case ObjectKind::Polyline3:
        for (std::size_t k = 0; k < count; ++k) {
          const glm::dvec3 step = (points[k + 1] - points[k]) / 3.0;
          pieces_.push_back({points[k], points[k] + step, points[k] + 2.0 * step, points[k + 1]});
        }
        break;
      case ObjectKind::Hermite2:
      case ObjectKind::Hermite3:
        for (std::size_t k = 0; k < count; ++k) {
          const glm::dvec3& p = points[2 * k];
          const glm::dvec3& q = points[2 * k + 2];
          pieces_.push_back({p, p + points[2 * k + 1] / 3.0, q - points[2 * k + 3] / 3.0, q});
        }
        break;
      case ObjectKind::Circle:
      case ObjectKind::TorusKnot:
        end_ = 1.0;
        break;
      case ObjectKind::Helix:
        end_ = curve.as<sweep::HelixCurve>().turns;
        break;
      case ObjectKind::SurfaceOfRevolution:
      case ObjectKind::GeneralizedCylinder:
      case ObjectKind::Birail:
      case ObjectKind::BezierPatch:
      case ObjectKind::BSplinePatch:
      case ObjectKind::PolygonMesh:
      case ObjectKind::Subdivision:
      case ObjectKind::Material:
      case ObjectKind::Rider:
        throw std::invalid_argument("not a curve");
    }
  }

  std::size_t size() const { return pieces_.empty() ? 1 : pieces_.size(); }
  /// The parameters where range k starts and ends.
  std::pair<double, double> range(std::size_t k) const {
    return pieces_.empty() ? std::pair{0.0, end_} : std::pair{static_cast<double>(k), static_cast<double>(k + 1)};
  }
  glm::dvec3 position(double u) const { return curve_position(curve_, u); }
  /// The Bezier control points of piece k (control-point curves only).
  const std::array<glm::dvec3, 4>& piece(std::size_t k) const { return pieces_[k]; }
  /// The derivative by the curve parameter at u, taken on range k (a joint's two sides differ).
  glm::dvec3 derivative(std::size_t k, double u) const {
    if (!pieces_.empty()) {
      glm::dvec3 d = evaluate_bezier_piece(pieces_[k], std::clamp(u - static_cast<double>(k), 0.0, 1.0)).d1;
      if (is_planar_curve(curve_.kind())) d.z = 0.0;
      return d;
    }
    const double turn = 2.0 * std::numbers::pi;
    if (curve_.kind() == ObjectKind::TorusKnot) {
      return turn * knot_point({curve_.as<sweep::TorusKnotCurve>().knot_p, curve_.as<sweep::TorusKnotCurve>().knot_q,
                                curve_.as<sweep::TorusKnotCurve>().major_radius, curve_.as<sweep::RadiusPart>().radius},
                               turn * u)
                        .d1;
    }
    const double pitch = curve_.kind() == ObjectKind::Helix ? curve_.as<sweep::HelixCurve>().pitch : 0.0;
    return glm::dvec3(-turn * curve_.as<sweep::RadiusPart>().radius * std::sin(turn * u),
                      turn * curve_.as<sweep::RadiusPart>().radius * std::cos(turn * u), pitch);
  }

 private:
  const Object& curve_;
  std::vector<std::array<glm::dvec3, 4>> pieces_;
  double end_ = 1.0;
};

constexpr double kNoTolerance = std::numeric_limits<double>::infinity();

double point_segment_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return vector_length(p - (a + t * ab));
}

/// True if the step [from, to] of range k may be a chord: no two of its tangents more than
/// kMaxTurn apart (the adaptive test's turn limit), every checked point within `tolerance` of it
/// (an infinite tolerance checks the tangents only).
bool step_passes(const CurveRanges& curve, std::size_t k, double from, double to, double tolerance) {
  const glm::dvec3 a = curve.position(from), b = curve.position(to);
  const double length = vector_length(b - a);
  // A hair wider than the adaptive test's limit, so that a step exactly at its edge (a circle's
  // 8 segments) passes here whatever the rounding.
  const double turn_cos = std::cos(kMaxTurn + 1e-9);
  const double h = to - from;
  std::array<glm::dvec3, kGreedyDensity + 1> tangents;
  std::size_t count = 0;
  for (int i = 0; i <= kGreedyDensity; ++i) {
    const double u = i == kGreedyDensity ? to : from + h * i / kGreedyDensity;
    const glm::dvec3 d = curve.derivative(k, u);
    const double speed = vector_length(d);
    // A vanishing derivative (a cusp) has no direction; the adaptive test skips it likewise.
    if (length > 0.0 && speed * h > 1e-12 * length) {
      const glm::dvec3 t = d / speed;
      for (std::size_t j = 0; j < count; ++j) {
        if (glm::dot(t, tangents[j]) < turn_cos) return false;
      }
      tangents[count++] = t;
    }
    if (i > 0 && i < kGreedyDensity && tolerance < kNoTolerance &&
        point_segment_distance(curve.position(u), a, b) > tolerance) {
      return false;
    }
  }
  return true;
}

/// The longest step from `from` within range k (ending at `end`) that passes.
double longest_step(const CurveRanges& curve, std::size_t k, double from, double end, double min_step,
                    double tolerance) {
  const double rest = end - from;
  if (rest <= min_step || step_passes(curve, k, from, end, tolerance)) return rest;
  double bad = rest, good = 0.0;
  for (double h = rest / 1.25; h >= min_step; h /= 1.25) {
    if (step_passes(curve, k, from, from + h, tolerance)) {
      good = h;
      break;
    }
    bad = h;
  }
  if (good == 0.0) return min_step;  // the depth limit, as the adaptive sampling's
  while (bad - good > 1e-9 * good) {
    const double mid = 0.5 * (good + bad);
    (step_passes(curve, k, from, from + mid, tolerance) ? good : bad) = mid;
  }
  return good;
}

/// The curve evaluated by `steps`, without its tolerance clause, and its measured deviation;
/// with `turn_limit`, infinite if a chord has a tangent more than kMaxTurn / 2 away.
double uniform_deviation(const Object& curve, int steps, bool turn_limit) {
  Object uniform = curve;
  uniform.as<sweep::StepsPart>().steps = steps;
  uniform.as<sweep::TolerancePart>().tolerance = 0.0;
  const CurveSamples samples = evaluate_curve(uniform);
  if (turn_limit) {
    const CurveRanges ranges(uniform);
    const std::vector<double>& at = samples.parameters;
    for (std::size_t i = 0; i + 1 < at.size(); ++i) {
      // Uniform samples include every joint: the chord lies within one range.
      const auto k =
          static_cast<std::size_t>(std::clamp(std::floor(at[i]), 0.0, static_cast<double>(ranges.size() - 1)));
      if (!step_passes(ranges, k, at[i], at[i + 1], kNoTolerance)) return kNoTolerance;
    }
  }
  return curve_deviation(uniform, samples, 64);
}

/// Largest STEPS a curve may have: the STEPS cap and the sample cap.
int max_steps(const Object& curve) {
  std::int64_t cap = limits::kMaxSteps;
  Object probe = curve;
  probe.as<sweep::StepsPart>().steps = 1;
  const std::int64_t per_step = std::max<std::int64_t>(curve_sample_count(probe) - 1, 1);
  cap = std::min(cap, (limits::kMaxCurveSamples - 1) / per_step);
  return static_cast<int>(std::max<std::int64_t>(cap, 1));
}

std::size_t sample_count(const Object& curve, int steps) {
  Object probe = curve;
  probe.as<sweep::StepsPart>().steps = steps;
  return static_cast<std::size_t>(curve_sample_count(probe));
}

}  // namespace

std::vector<double> greedy_parameters(const Object& curve, double tolerance) {
  const CurveRanges ranges(curve);
  std::vector<double> parameters{ranges.range(0).first};
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    const auto [begin, end] = ranges.range(k);
    const double min_step = 1e-7 * (end - begin);
    double t = begin;
    while (t < end) {
      const double step = longest_step(ranges, k, t, end, min_step, tolerance);
      t = end - (t + step) <= 1e-12 * (end - begin) ? end : t + step;
      parameters.push_back(t);
    }
  }
  return parameters;
}

std::size_t greedy_sample_count(const Object& curve, double tolerance) {
  return greedy_parameters(curve, tolerance).size();
}

UniformCurve best_uniform_steps(const Object& curve, double tolerance, bool turn_limit) {
  const int cap = max_steps(curve);
  std::map<int, double> measured;
  const auto deviation = [&](int steps) {
    const auto it = measured.find(steps);
    if (it != measured.end()) return it->second;
    return measured[steps] = uniform_deviation(curve, steps, turn_limit);
  };
  int fail = 0, pass = 1;
  while (deviation(pass) > tolerance) {
    if (pass == cap) return {cap, sample_count(curve, cap), deviation(cap), false};
    fail = pass;
    pass = static_cast<int>(std::min<std::int64_t>(2 * std::int64_t{pass}, cap));
  }
  while (pass - fail > 1) {
    const int mid = fail + (pass - fail) / 2;
    (deviation(mid) <= tolerance ? pass : fail) = mid;
  }
  // The deviation need not fall strictly with STEPS (a sample may land on a sharp turn): look
  // below the count found.
  for (int below = pass - 1, misses = 0; below >= 1 && misses < 8; --below) {
    if (deviation(below) <= tolerance) {
      pass = below;
      misses = 0;
    } else {
      ++misses;
    }
  }
  return {pass, sample_count(curve, pass), deviation(pass), true};
}

int wang_uniform_steps(const Object& curve, double tolerance) {
  if (!has_control_points(curve.kind())) return 0;
  const CurveRanges ranges(curve);
  double steps = 1.0;
  for (std::size_t k = 0; k < ranges.size(); ++k) {
    const std::array<glm::dvec3, 4>& p = ranges.piece(k);
    const double m = std::max(vector_length(p[0] - 2.0 * p[1] + p[2]), vector_length(p[1] - 2.0 * p[2] + p[3]));
    steps = std::max(steps, std::ceil(std::sqrt(0.75 * m / tolerance)));
  }
  return static_cast<int>(std::min(steps, static_cast<double>(limits::kMaxSteps)));
}

Document uniform_surface_document(const Document& doc, int index, int profile_steps, int sweep_steps) {
  const Object& surface = doc.objects[static_cast<std::size_t>(index)];
  const auto* cylinder = surface.find<sweep::CylinderSurface>();  // none for a srev
  if (cylinder && surface.as<sweep::ProfilePart>().profile == cylinder->sweep)
    throw std::invalid_argument("the profile is the sweep");
  Document out;
  Object profile = doc.objects[static_cast<std::size_t>(surface.as<sweep::ProfilePart>().profile)];
  profile.as<sweep::TolerancePart>().tolerance = 0.0;
  profile.as<sweep::StepsPart>().steps = profile_steps;
  out.objects.push_back(std::move(profile));
  Object copy = surface;
  copy.as<sweep::ProfilePart>().profile = 0;
  if (surface.kind() == ObjectKind::SurfaceOfRevolution) {
    copy.as<sweep::StepsPart>().steps = sweep_steps;
  } else {
    Object sweep = doc.objects[static_cast<std::size_t>(surface.as<sweep::CylinderSurface>().sweep)];
    sweep.as<sweep::TolerancePart>().tolerance = 0.0;
    sweep.as<sweep::StepsPart>().steps = sweep_steps;
    out.objects.push_back(std::move(sweep));
    copy.as<sweep::CylinderSurface>().sweep = 1;
  }
  out.objects.push_back(std::move(copy));
  return out;
}

namespace {

/// The STEPS that give a curve about `samples` samples (at least 1).
int steps_for_samples(const Object& curve, std::size_t samples) {
  const double segments = static_cast<double>(samples) - 1.0;
  double steps = segments;
  if (curve.kind() == ObjectKind::Helix) {
    steps = segments / curve.as<sweep::HelixCurve>().turns;
  } else if (has_control_points(curve.kind())) {
    steps = segments / static_cast<double>(piece_count(
                           curve.kind(), static_cast<std::int64_t>(curve.as<sweep::PointsPart>().points.size())));
  }
  return static_cast<int>(std::clamp(std::round(steps), 1.0, static_cast<double>(limits::kMaxSteps)));
}

}  // namespace

Document same_size_uniform_document(const Document& doc, const EvaluationOptions& options) {
  const Scene scene = evaluate_document(doc, options);
  Document uniform = doc;
  std::vector<std::size_t> samples(doc.objects.size(), 0);
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const Object& o = doc.objects[i];
    if (is_curve(o.kind())) continue;
    const SurfaceSampling s = surface_sampling(doc, scene, static_cast<int>(i), options);
    const auto profile = static_cast<std::size_t>(o.as<sweep::ProfilePart>().profile);
    samples[profile] = std::max(samples[profile], s.profile.frames.size());
    if (o.kind() == ObjectKind::SurfaceOfRevolution) {
      uniform.objects[i].as<sweep::CopiesPart>().copies = std::max(s.copies, 1);
    } else {
      const auto sweep = static_cast<std::size_t>(o.as<sweep::CylinderSurface>().sweep);
      samples[sweep] = std::max(samples[sweep], s.sweep.frames.size());
    }
  }
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    Object& o = uniform.objects[i];
    if (!is_curve(o.kind())) continue;
    const std::size_t n = samples[i] != 0 ? samples[i] : scene.objects[i].curve.frames.size();
    o.as<sweep::StepsPart>().steps = steps_for_samples(o, n);
    o.as<sweep::TolerancePart>().tolerance = 0.0;
  }
  return uniform;
}

namespace {

int grow(int n, double ratio) {
  return static_cast<int>(std::min<double>(std::max(std::ceil(n * ratio), n + 1.0), limits::kMaxSteps));
}

/// The state of best_uniform_surface's search: every mesh measured once.
class SurfaceSearch {
 public:
  SurfaceSearch(const Document& doc, int index, double target, int density, const EvaluationOptions& options)
      : doc_(doc), index_(index), target_(target), density_(density), options_(options) {
    options_.tolerance = 0.0;
  }

  struct Measure {
    double deviation = 0.0;
    std::size_t triangles = 0;
  };

  Measure measure(int profile_steps, int sweep_steps) {
    const auto key = std::pair{profile_steps, sweep_steps};
    const auto it = cache_.find(key);
    if (it != cache_.end()) return it->second;
    const Document uniform = uniform_surface_document(doc_, index_, profile_steps, sweep_steps);
    const int surface = static_cast<int>(uniform.objects.size()) - 1;
    // Rough triangle count first: meshes past the bound are not built.
    const double profile_samples = static_cast<double>(curve_sample_count(uniform.objects[0]));
    const double sweep_samples = uniform.objects.size() == 3
                                     ? static_cast<double>(curve_sample_count(uniform.objects[1]))
                                     : static_cast<double>(sweep_steps) + 1.0;
    Measure m;
    if (2.0 * (profile_samples - 1.0) * (sweep_samples - 1.0) > kMaxTriangles) {
      m.deviation = std::numeric_limits<double>::infinity();
      m.triangles = std::numeric_limits<std::size_t>::max();
    } else {
      const Scene scene = evaluate_document(uniform, options_);
      m.triangles = scene.objects.back().mesh.triangle_count();
      m.deviation = surface_deviation(uniform, scene, surface, options_, density_);
      ++measured_;
    }
    return cache_[key] = m;
  }

  bool passes(int profile_steps, int sweep_steps) { return measure(profile_steps, sweep_steps).deviation <= target_; }

  /// The smallest sweep STEPS that passes with this profile STEPS, or 0 if none up to `cap`
  /// does: from `hint`, grown by 1.25 until one passes, then bisection below it (the
  /// deviation falls with the sweep STEPS), then the 4 counts below the one found, continued
  /// downwards while one passes (the deviation need not fall strictly).
  int smallest_sweep(int profile_steps, int hint, int cap) {
    int hi = std::clamp(hint, 1, cap), lo = 0;  // lo fails (0: none known)
    while (!passes(profile_steps, hi)) {
      if (hi == cap) return 0;
      lo = hi;
      hi = std::min(grow(hi, 1.25), cap);
    }
    if (lo == 0 && hi > 1) {
      // hint passed: find a failing count below it.
      for (lo = hi; lo > 1;) {
        lo = std::max(lo / 2, 1);
        if (!passes(profile_steps, lo)) break;
        hi = lo;
      }
      if (passes(profile_steps, lo)) return lo;  // lo = 1 passes
    }
    while (hi - lo > 1) {
      const int mid = lo + (hi - lo) / 2;
      (passes(profile_steps, mid) ? hi : lo) = mid;
    }
    for (int below = hi - 1, misses = 0; below >= 1 && misses < 4; --below) {
      if (passes(profile_steps, below)) {
        hi = below;
        misses = 0;
      } else {
        ++misses;
      }
    }
    return hi;
  }

  int measured() const { return measured_; }

 private:
  static constexpr double kMaxTriangles = 2e7;
  const Document& doc_;
  int index_;
  double target_;
  int density_;
  EvaluationOptions options_;
  std::map<std::pair<int, int>, Measure> cache_;
  int measured_ = 0;
};

}  // namespace

UniformSurface best_uniform_surface(const Document& doc, int index, double target, int density,
                                    const EvaluationOptions& options) {
  const Object& surface = doc.objects[static_cast<std::size_t>(index)];
  const Object& profile = doc.objects[static_cast<std::size_t>(surface.as<sweep::ProfilePart>().profile)];
  SurfaceSearch search(doc, index, target, density, options);

  // Start: each curve's best uniform count for half the target.
  int p1 = best_uniform_steps(profile, 0.5 * target).steps;
  int s1 = 1;
  if (surface.kind() == ObjectKind::SurfaceOfRevolution) {
    Object uniform = profile;
    uniform.as<sweep::StepsPart>().steps = p1;
    uniform.as<sweep::TolerancePart>().tolerance = 0.0;
    double radius = 0.0;
    for (const Frame& f : evaluate_curve(uniform).frames) radius = std::max(radius, std::abs(f.V.x));
    s1 = circle_segments(radius + 0.5 * target, 0.5 * target);
  } else {
    s1 = best_uniform_steps(doc.objects[static_cast<std::size_t>(surface.as<sweep::CylinderSurface>().sweep)],
                            0.5 * target)
             .steps;
  }
  for (int i = 0; !search.passes(p1, s1); ++i) {
    if (i == 30 || (p1 == limits::kMaxSteps && s1 == limits::kMaxSteps))
      return {0, 0, 0, 0.0, search.measured(), false};
    p1 = grow(p1, 1.25);
    s1 = grow(s1, 1.25);
  }

  struct Point {
    int profile_steps;
    int sweep_steps;
    std::size_t triangles;
  };
  std::vector<Point> grid;
  const auto best = [&] {
    return *std::min_element(grid.begin(), grid.end(),
                             [](const Point& a, const Point& b) { return a.triangles < b.triangles; });
  };
  const int sweep_cap = std::min(4 * s1 + 4, static_cast<int>(limits::kMaxSteps));
  const int profile_cap = std::min(4 * p1 + 4, static_cast<int>(limits::kMaxSteps));
  const auto try_profile = [&](int p, int hint) {
    const int found = search.smallest_sweep(p, hint, sweep_cap);
    if (found != 0) grid.push_back({p, found, search.measure(p, found).triangles});
    return found;
  };
  s1 = try_profile(p1, s1);  // the smallest sweep STEPS for the start's profile STEPS
  // Walk the profile STEPS down (the sweep needs more) and up (it needs fewer) on a grid of ratio
  // 1.06 until the triangles pass 1.3 times the best twice in a row or nothing passes twice.
  for (const int direction : {-1, 1}) {
    for (int p = p1, hint = s1, over = 0, failed = 0; over < 2 && failed < 2;) {
      p = direction < 0 ? std::min(static_cast<int>(std::floor(p / 1.06)), p - 1) : grow(p, 1.06);
      if (p < 1 || p > profile_cap) break;
      const int found = try_profile(p, hint);
      failed = found == 0 ? failed + 1 : 0;
      if (found == 0) continue;
      hint = found;
      const bool worse = static_cast<double>(grid.back().triangles) > 1.3 * static_cast<double>(best().triangles);
      over = worse ? over + 1 : 0;
    }
  }
  // Every profile STEPS between the best grid point's neighbours.
  std::sort(grid.begin(), grid.end(), [](const Point& a, const Point& b) { return a.profile_steps < b.profile_steps; });
  const Point centre = best();
  const auto at =
      std::find_if(grid.begin(), grid.end(), [&](const Point& g) { return g.profile_steps == centre.profile_steps; });
  const int from = at == grid.begin() ? centre.profile_steps : (at - 1)->profile_steps;
  const int to = at + 1 == grid.end() ? centre.profile_steps : (at + 1)->profile_steps;
  for (int p = from + 1; p < to; ++p) {
    if (p != centre.profile_steps) try_profile(p, centre.sweep_steps);
  }
  const Point chosen = best();
  return {chosen.profile_steps, chosen.sweep_steps,
          chosen.triangles,     search.measure(chosen.profile_steps, chosen.sweep_steps).deviation,
          search.measured(),    true};
}

}  // namespace sweep::sampling
