// Converting a curve to another kind (issue 61, item 3): exactly where the shape allows (every
// control-point kind to Bezier through the cubic pieces it is evaluated from; to Hermite when
// every joint is C1), by a fit within a tolerance where it does not (to B-spline by least
// squares, to Catmull-Rom through points on the curve), the largest deviation measured.
#include "geometry/curves/bezier.hpp"
#include "model/edit/edit.hpp"
#include "model/edit/edit_support.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/deviation.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <vector>

namespace sweep {

using namespace edit_support;

namespace {

constexpr int kDenseSamples = 32;            // per piece, for measuring a deviation
constexpr std::size_t kMaxFitPoints = 4096;  // a fit refines until within tolerance or this many points

ObjectKind planar_or_not(const Object& curve, ObjectKind planar, ObjectKind spatial) {
  return is_planar_curve(curve.kind()) ? planar : spatial;
}

/// The new curve: `kind`, the source's name, place in the file, STEPS (1 for a polyline, whose
/// straight pieces one step samples exactly) and tolerance, with `points`.
Object converted(const Object& source, ObjectKind kind, std::vector<glm::dvec3> points) {
  Object out(kind);
  out.name = source.name;
  out.location = source.location;
  const auto* steps = source.find<StepsPart>();
  if (auto* target = out.find<StepsPart>()) target->steps = steps ? steps->steps : 1;
  if (const auto* tolerance = source.find<TolerancePart>()) {
    if (auto* target = out.find<TolerancePart>()) target->tolerance = tolerance->tolerance;
  }
  out.as<PointsPart>().points = std::move(points);
  return out;
}

std::vector<BezierPiece> pieces_of(const Object& curve) {
  return bezier_pieces(describe_curve(curve));
}

/// The pieces as one Bezier point list (J H H J H H ... J), closed exactly when the curve is.
std::vector<glm::dvec3> bezier_points(const Object& curve) {
  const std::vector<BezierPiece> pieces = pieces_of(curve);
  std::vector<glm::dvec3> points{pieces.front()[0]};
  for (const BezierPiece& p : pieces) points.insert(points.end(), {p[1], p[2], p[3]});
  if (is_closed(describe_curve(curve))) points.back() = points.front();
  return points;
}

/// Hermite points and tangents (p0 t0 p1 t1 ...) of the pieces, or the first joint where the
/// tangents on either side differ (then `corner` >= 0).
std::vector<glm::dvec3> hermite_points(const Object& curve, int& corner) {
  const std::vector<BezierPiece> pieces = pieces_of(curve);
  const bool closed = is_closed(describe_curve(curve));
  std::vector<glm::dvec3> points;
  corner = -1;
  for (std::size_t k = 0; k < pieces.size(); ++k) {
    const glm::dvec3 out = 3.0 * (pieces[k][1] - pieces[k][0]);
    if (k > 0 || closed) {
      const BezierPiece& before = pieces[k > 0 ? k - 1 : pieces.size() - 1];
      const glm::dvec3 in = 3.0 * (before[3] - before[2]);
      const double size = std::max({glm::length(in), glm::length(out), 1e-300});
      if (glm::length(in - out) > 1e-9 * size && corner < 0) corner = int(k);
    }
    points.insert(points.end(), {pieces[k][0], out});
  }
  const BezierPiece& last = pieces.back();
  points.insert(points.end(), {closed ? pieces.front()[0] : last[3], closed ? points[1] : 3.0 * (last[3] - last[2])});
  return points;
}

/// Dense points along a curve: `per_piece` per piece (a polyline's segments divided as finely).
std::vector<glm::dvec3> dense(const Object& curve, int per_piece = kDenseSamples) {
  Object copy = curve;
  if (auto* steps = copy.find<StepsPart>()) steps->steps = per_piece;
  if (auto* tolerance = copy.find<TolerancePart>()) tolerance->tolerance = 0.0;
  const CurveSamples samples = evaluate_curve(copy);
  const int between = copy.find<StepsPart>() ? 1 : per_piece;  // a polyline's samples are its points
  std::vector<glm::dvec3> out{samples.frames.front().V};
  for (std::size_t i = 1; i < samples.frames.size(); ++i) {
    for (int k = 1; k <= between; ++k) {
      const double t = double(k) / double(between);
      out.push_back((1.0 - t) * samples.frames[i - 1].V + t * samples.frames[i].V);
    }
  }
  return out;
}

double distance_to_polyline(const glm::dvec3& p, const std::vector<glm::dvec3>& line) {
  double best = glm::length(p - line.front());
  for (std::size_t i = 1; i < line.size(); ++i) best = std::min(best, point_segment_distance(p, line[i - 1], line[i]));
  return best;
}

/// The points of uniform cubic B-spline control points `count` (open: count - 3 pieces; closed:
/// `count` distinct points, as many pieces) that fit `targets` at curve parameters `at` (in
/// pieces) best in the least-squares sense, by the normal equations.
std::vector<glm::dvec3> least_squares_bspline(const std::vector<glm::dvec3>& targets, const std::vector<double>& at,
                                              std::size_t count, bool closed) {
  const std::size_t pieces = closed ? count : count - 3;
  std::vector<double> m(count * count, 0.0);
  std::vector<glm::dvec3> rhs(count, glm::dvec3(0.0));
  const glm::dmat4& basis = bspline_basis();
  for (std::size_t r = 0; r < targets.size(); ++r) {
    const std::size_t piece = std::min(std::size_t(at[r]), pieces - 1);
    const double t = at[r] - double(piece);
    const glm::dvec4 weights = basis * glm::dvec4(1.0, t, t * t, t * t * t);  // G B T: point j's is row j's
    std::array<double, 4> w{};
    std::array<std::size_t, 4> index{};
    for (int j = 0; j < 4; ++j) {
      w[std::size_t(j)] = weights[j];
      index[std::size_t(j)] = closed ? (piece + std::size_t(j)) % count : piece + std::size_t(j);
    }
    for (int a = 0; a < 4; ++a) {
      rhs[index[std::size_t(a)]] += w[std::size_t(a)] * targets[r];
      for (int b = 0; b < 4; ++b)
        m[index[std::size_t(a)] * count + index[std::size_t(b)]] += w[std::size_t(a)] * w[std::size_t(b)];
    }
  }
  // Gaussian elimination with partial pivoting (the system is symmetric, banded and small).
  for (std::size_t c = 0; c < count; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < count; ++r) {
      if (std::abs(m[r * count + c]) > std::abs(m[pivot * count + c])) pivot = r;
    }
    if (!(std::abs(m[pivot * count + c]) > 1e-300)) throw EditError("the fit has too few points on the curve");
    if (pivot != c) {
      for (std::size_t k = 0; k < count; ++k) std::swap(m[c * count + k], m[pivot * count + k]);
      std::swap(rhs[c], rhs[pivot]);
    }
    for (std::size_t r = c + 1; r < count; ++r) {
      const double f = m[r * count + c] / m[c * count + c];
      if (f == 0.0) continue;
      for (std::size_t k = c; k < count; ++k) m[r * count + k] -= f * m[c * count + k];
      rhs[r] -= f * rhs[c];
    }
  }
  std::vector<glm::dvec3> x(count);
  for (std::size_t c = count; c-- > 0;) {
    glm::dvec3 sum = rhs[c];
    for (std::size_t k = c + 1; k < count; ++k) sum -= m[c * count + k] * x[k];
    x[c] = sum / m[c * count + c];
  }
  if (closed) x.insert(x.end(), {x[0], x[1], x[2]});
  return x;
}

/// A B-spline fit of `source` with `groups` control points (distinct, when closed).
Object bspline_fit(const Object& source, std::size_t groups) {
  const bool closed = is_closed(describe_curve(source));
  // At least 8 samples per control point, so that every one of them is pinned down.
  const std::size_t source_pieces = std::max<std::size_t>(1, pieces_of(source).size());
  const int per_piece = std::max(kDenseSamples, int(8 * groups / source_pieces) + 1);
  const std::vector<glm::dvec3> targets = dense(source, per_piece);
  const std::size_t pieces = closed ? groups : groups - 3;
  std::vector<double> at(targets.size());
  for (std::size_t i = 0; i < at.size(); ++i) at[i] = double(pieces) * double(i) / double(at.size() - 1);
  return converted(source, planar_or_not(source, ObjectKind::BSpline2, ObjectKind::BSpline3),
                   least_squares_bspline(targets, at, groups, closed));
}

/// A Catmull-Rom fit of `source` through `groups` points spread evenly over its pieces.
Object catmull_rom_fit(const Object& source, std::size_t groups) {
  const bool closed = is_closed(describe_curve(source));
  const std::size_t source_pieces = std::max<std::size_t>(1, pieces_of(source).size());
  const std::vector<glm::dvec3> line = dense(source, std::max(kDenseSamples, int(4 * groups / source_pieces) + 1));
  std::vector<glm::dvec3> points;
  for (std::size_t i = 0; i < groups; ++i) {
    points.push_back(line[std::min(line.size() - 1, i * (line.size() - 1) / (groups - 1))]);
  }
  if (closed) points.back() = points.front();
  return converted(source, planar_or_not(source, ObjectKind::CatmullRom2, ObjectKind::CatmullRom3), std::move(points));
}

}  // namespace

double curve_deviation_between(const Object& a, const Object& b) {
  const std::vector<glm::dvec3> p = dense(a);
  const std::vector<glm::dvec3> q = dense(b);
  double worst = 0.0;
  for (const glm::dvec3& x : p) worst = std::max(worst, distance_to_polyline(x, q));
  for (const glm::dvec3& x : q) worst = std::max(worst, distance_to_polyline(x, p));
  return worst;
}

Conversion convert_curve(const Object& curve, ObjectKind to, double tolerance) {
  if (!has_editable_points(curve.kind()) || !is_curve(curve.kind())) {
    throw EditError("'" + curve.name + "' (" + std::string(keyword(curve.kind())) +
                    ") has no control points to convert: expected a bez, bsp, cr, kb, poly or herm curve");
  }
  const bool planar = is_planar_curve(curve.kind());
  if (is_planar_curve(to) != planar) {
    throw EditError(std::string("expected a ") + (planar ? "2D" : "3D") + " kind for '" + curve.name + "' (" +
                    std::string(keyword(curve.kind())) + "), found " + std::string(keyword(to)));
  }
  if (to == curve.kind()) throw EditError("'" + curve.name + "' is a " + std::string(keyword(to)) + " already");
  const auto is = [to](ObjectKind in_2d, ObjectKind in_3d) { return to == in_2d || to == in_3d; };
  if (is(ObjectKind::Bezier2, ObjectKind::Bezier3)) return {converted(curve, to, bezier_points(curve)), 0.0, true};
  if (is(ObjectKind::Hermite2, ObjectKind::Hermite3)) {
    int corner = -1;
    std::vector<glm::dvec3> points = hermite_points(curve, corner);
    if (corner >= 0) {
      throw EditError("'" + curve.name + "' has a corner at its joint " + std::to_string(corner) +
                      ": a Hermite curve has one tangent at each point (make the joint smooth and symmetric first)");
    }
    return {converted(curve, to, std::move(points)), 0.0, true};
  }
  const bool bspline = is(ObjectKind::BSpline2, ObjectKind::BSpline3);
  if (!bspline && !is(ObjectKind::CatmullRom2, ObjectKind::CatmullRom3)) {
    throw EditError("a curve converts to bez, herm, bsp or cr, not " + std::string(keyword(to)));
  }
  if (!(tolerance > 0.0)) throw EditError("a fit needs a tolerance > 0");
  const bool closed = is_closed(describe_curve(curve));
  std::size_t groups = std::max<std::size_t>(pieces_of(curve).size() + (closed ? 0 : 3), 4);
  for (;;) {
    Object fit = bspline ? bspline_fit(curve, groups) : catmull_rom_fit(curve, groups + (closed ? 1 : 0));
    const double deviation = curve_deviation_between(curve, fit);
    if (deviation <= tolerance || groups * 2 > kMaxFitPoints) return {std::move(fit), deviation, false};
    groups *= 2;
  }
}

Change convert_curve(Document& doc, int object, ObjectKind to, double tolerance, Conversion* result) {
  check_object_index(doc, object);
  Conversion conversion = convert_curve(doc.objects[to_size(object)], to, tolerance);
  Object replacement = conversion.curve;
  if (result) *result = std::move(conversion);
  return commit(doc, object, std::move(replacement));
}

}  // namespace sweep
