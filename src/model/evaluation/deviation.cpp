#include "model/evaluation/deviation.hpp"

#include "base/precondition.hpp"
#include "geometry/unit_vector.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace sweep {

double point_segment_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b) {
  const glm::dvec3 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  const double t = length2 > 0.0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return vector_length(p - (a + t * ab));
}

namespace {

/// The parameters between consecutive entries of `at`, `density` per interval, and the last one.
std::vector<double> refine(const std::vector<double>& at, int density) {
  std::vector<double> out;
  if (at.empty()) return out;
  out.reserve((at.size() - 1) * static_cast<std::size_t>(density) + 1);
  for (std::size_t i = 0; i + 1 < at.size(); ++i) {
    for (int k = 0; k < density; ++k) out.push_back(at[i] + (at[i + 1] - at[i]) * k / density);
  }
  out.push_back(at.back());
  return out;
}

/// Rings of the grid a curve's samples give: a closed curve's last sample is its first.
std::size_t ring_of(const CurveSamples& c) {
  return c.closed ? c.frames.size() - 1 : c.frames.size();
}

/// The largest distance of the reference points (density + 1)^2 per quad, given by `point(i, a,
/// j, b)` for profile segment i at step a and sweep (or turn) segment j at step b, from the mesh
/// quads (i, j) between grid rings ring_at(j, 0) and ring_at(j, 1); `skip(j)` leaves out sweep
/// segments.
template <typename Point, typename RingAt, typename Skip>
double grid_deviation(const Mesh& mesh, std::size_t ring, std::size_t profile_segments, std::size_t sweep_segments,
                      int density, Point point, RingAt ring_at, Skip skip) {
  double worst = 0.0;
  const auto vertex = [&](std::size_t k, std::size_t i) { return glm::dvec3(mesh.positions[k * ring + i % ring]); };
  for (std::size_t j = 0; j < sweep_segments; ++j) {
    if (skip(j)) continue;
    const std::size_t from = ring_at(j, 0), to = ring_at(j, 1);
    for (std::size_t i = 0; i < profile_segments; ++i) {
      const glm::dvec3 a = vertex(from, i), b = vertex(from, i + 1), c = vertex(to, i), d = vertex(to, i + 1);
      for (int u = 0; u <= density; ++u) {
        for (int v = 0; v <= density; ++v) {
          const glm::dvec3 p = point(i, u, j, v);
          worst = std::max(worst, std::min(point_triangle_distance(p, a, b, c), point_triangle_distance(p, b, d, c)));
        }
      }
    }
  }
  return worst;
}

}  // namespace

double point_triangle_distance(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return vector_length(ap);
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return vector_length(bp);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return point_segment_distance(p, a, b);
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return vector_length(cp);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return point_segment_distance(p, a, c);
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return point_segment_distance(p, b, c);
  const double sum = va + vb + vc;
  if (!(sum > 0.0)) return std::min({point_segment_distance(p, a, b), point_segment_distance(p, a, c)});
  return vector_length(p - (a + ab * (vb / sum) + ac * (vc / sum)));
}

double curve_deviation(const Object& curve, const CurveSamples& samples, int density) {
  SWEEP_EXPECTS(is_curve(curve.kind()), "samples came from evaluate_curve(curve, ...)");
  SWEEP_EXPECTS(density >= 1, "density >= 1");
  double worst = 0.0;
  const std::vector<double>& at = samples.parameters;
  for (std::size_t i = 0; i + 1 < samples.frames.size() && i + 1 < at.size(); ++i) {
    for (int k = 1; k < density; ++k) {
      const glm::dvec3 p = curve_position(curve, at[i] + (at[i + 1] - at[i]) * k / density);
      worst = std::max(worst, point_segment_distance(p, samples.frames[i].V, samples.frames[i + 1].V));
    }
  }
  return worst;
}

bool deviation_is_measured(const Object& surface) {
  if (surface.find<RevolutionSurface>()) return true;
  const auto* cylinder = surface.find<CylinderSurface>();
  return cylinder && cylinder->scale < 0 && cylinder->twist_curve < 0 && cylinder->twist == 0.0;
}

double surface_deviation(const Document& doc, const Scene& scene, int index, const EvaluationOptions& options,
                         int density) {
  SWEEP_EXPECTS(scene.objects.size() == doc.objects.size(), "scene = evaluate_document(doc, options)");
  SWEEP_EXPECTS(index >= 0 && static_cast<std::size_t>(index) < doc.objects.size() &&
                    is_surface(doc.objects[static_cast<std::size_t>(index)].kind()),
                "index is a surface");
  SWEEP_EXPECTS(density >= 1, "density >= 1");
  const Object& surface = doc.objects[static_cast<std::size_t>(index)];
  if (!deviation_is_measured(surface)) return std::numeric_limits<double>::quiet_NaN();
  const Mesh& mesh = scene.objects[static_cast<std::size_t>(index)].mesh;
  const SurfaceSampling sampling = surface_sampling(doc, scene, index, options);
  const CurveSamples& profile = sampling.profile;
  const std::size_t ring = ring_of(profile);
  const std::size_t profile_segments = profile.closed ? ring : profile.frames.size() - 1;
  // The exact profile at the reference's parameters.
  const std::vector<double> profile_at = refine(profile.parameters, density);
  std::vector<glm::dvec3> shape(profile_at.size());
  const Object& profile_object = doc.objects[static_cast<std::size_t>(surface.as<ProfilePart>().profile)];
  for (std::size_t k = 0; k < shape.size(); ++k) shape[k] = curve_position(profile_object, profile_at[k]);
  const auto profile_point = [&](std::size_t i, int u) { return shape[i * static_cast<std::size_t>(density) + u]; };

  if (surface.kind() == ObjectKind::SurfaceOfRevolution) {
    const auto copies = static_cast<std::size_t>(sampling.copies);
    return grid_deviation(
        mesh, ring, profile_segments, copies, density,
        [&](std::size_t i, int u, std::size_t j, int v) {
          const glm::dvec3 q = profile_point(i, u);
          const double angle = 2.0 * std::numbers::pi * (static_cast<double>(j) + static_cast<double>(v) / density) /
                               static_cast<double>(copies);
          return glm::dvec3(q.x * std::cos(angle), q.y, -q.x * std::sin(angle));
        },
        [&](std::size_t j, std::size_t end) { return (j + end) % copies; }, [](std::size_t) { return false; });
  }
  const CurveSamples& sweep = sampling.sweep;
  const std::vector<double> sweep_at = refine(sweep.parameters, density);
  const CurveSamples exact = evaluate_curve_at(
      doc.objects[static_cast<std::size_t>(surface.as<CylinderSurface>().sweep)], sweep_at, options.frames);
  const std::size_t rings = ring_of(sweep);
  const std::size_t sweep_segments = sweep.closed ? rings : sweep.frames.size() - 1;
  // Where the tube folds over itself (kappa r >= 1 anywhere in a segment, the fold warning)
  // there is no surface to be close to.
  const double radius = profile_radius(profile);
  std::vector<bool> folded(sweep_segments, false);
  for (std::size_t k = 0; k < exact.curvature.size(); ++k) {
    if (exact.curvature[k] * radius < 1.0) continue;
    const std::size_t j = k / static_cast<std::size_t>(density);
    if (j < sweep_segments) folded[j] = true;
    if (k % static_cast<std::size_t>(density) == 0 && j > 0) folded[j - 1] = true;
  }
  // Rings the mitre of a corner reaches: those within r tan(half the turn) of it, which
  // clip_at_corners may move onto the mitre plane (the mitre limit caps the stretch, so the
  // reach). A bevelled corner adds a ring to the grid: the segment after it starts one on.
  std::vector<bool> near_corner(sweep.frames.size() + 1, false);
  std::vector<std::size_t> bevels_up_to(rings + 1, 0);  // bevelled corners at samples < j
  for (const Corner& c : sweep.corners) {
    if (c.sample >= sweep.frames.size()) continue;
    const Frame& at = sweep.frames[c.sample];
    if (c.sample < rings && bevels_corner(c.incoming, at.T, options.mitre_limit)) ++bevels_up_to[c.sample + 1];
    const double turn = std::atan2(vector_length(glm::cross(c.incoming, at.T)), glm::dot(c.incoming, at.T));
    const double reach = 1.05 * radius * std::min(std::tan(0.5 * turn), options.mitre_limit) + 1e-9 * radius;
    near_corner[c.sample] = true;
    for (std::size_t j = 0; j < sweep.frames.size(); ++j) {
      if (vector_length(sweep.frames[j].V - at.V) <= reach) near_corner[j] = true;
    }
  }
  for (std::size_t j = 1; j <= rings; ++j) bevels_up_to[j] += bevels_up_to[j - 1];
  const bool symmetric_seam = options.seam == SeamMode::Symmetric && sweep.closed;
  // Sample j's leaving ring is j + the bevels at samples <= j; its arriving ring, j + those < j.
  const auto ring_at = [&](std::size_t j, std::size_t end) {
    return end == 0 ? j + bevels_up_to[j + 1] : (j + 1) % rings + bevels_up_to[(j + 1) % rings];
  };
  return grid_deviation(
      mesh, ring, profile_segments, sweep_segments, density,
      [&](std::size_t i, int u, std::size_t j, int v) {
        const glm::dvec3 q = profile_point(i, u);
        const Frame& f = exact.frames[j * static_cast<std::size_t>(density) + static_cast<std::size_t>(v)];
        return f.V + q.x * f.N + q.y * f.B;
      },
      ring_at,
      [&](std::size_t j) {
        return folded[j] || near_corner[j] || near_corner[j + 1] || (symmetric_seam && j + 1 == sweep_segments);
      });
}

}  // namespace sweep
