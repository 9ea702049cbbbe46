// Surfaces of revolution (surface.hpp): the profile turned about +y, with smooth poles and cone
// tips on the axis.
#include "base/precondition.hpp"
#include "geometry/surfaces/end_caps.hpp"
#include "geometry/surfaces/surface.hpp"
#include "geometry/surfaces/surface_detail.hpp"
#include "geometry/unit_vector.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <utility>
#include <vector>

namespace sweep {

using surface_detail::segment_count;
using surface_detail::signed_area;

namespace {

/// A profile meets the axis at a right angle where its unit normal is within this of +-y in x.
constexpr double kSmoothPole = 1e-6;

/// An open profile's end on the axis at an angle is a cone point: its copies' vertices take the
/// mean normal of the (non-degenerate) triangles that use each, so the tip shades as its faces.
void cone_tip_normals(Mesh& mesh, const CurveSamples& profile, std::size_t copies, double on_axis) {
  if (profile.closed) return;
  const std::size_t ring = ring_size(profile);
  std::vector<std::size_t> ends;
  for (const std::size_t i : {std::size_t{0}, ring - 1}) {
    const Frame& f = profile.frames[i];
    if (std::abs(f.V.x) <= on_axis && std::abs(f.N.x) > kSmoothPole && std::abs(f.N.y) > 1e-12) ends.push_back(i);
  }
  if (ends.empty()) return;
  std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
  std::vector<char> tip(mesh.positions.size(), 0);
  for (const std::size_t i : ends) {
    for (std::size_t j = 0; j < copies; ++j) tip[j * ring + i] = 1;
  }
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    if (!tip[a] && !tip[b] && !tip[c]) continue;
    const glm::dvec3 pa(mesh.positions[a]);
    const glm::dvec3 n = glm::cross(glm::dvec3(mesh.positions[b]) - pa, glm::dvec3(mesh.positions[c]) - pa);
    if (vector_length(n) <= 0.0) continue;  // a sliver at a sample barely off the axis
    for (const std::uint32_t v : {a, b, c}) {
      if (tip[v]) sum[v] += unit_vector(n);
    }
  }
  for (std::size_t v = 0; v < sum.size(); ++v) {
    if (tip[v] && vector_length(sum[v]) > 0.0) mesh.normals[v] = glm::vec3(unit_vector(sum[v]));
  }
}

}  // namespace

Mesh build_surface_of_revolution(const CurveSamples& profile, int steps, bool caps, Mesh storage) {
  SWEEP_EXPECTS(profile.planar, "profile.planar");
  SWEEP_EXPECTS(profile.frames.size() >= 2, "profile has >= 2 samples");
  SWEEP_EXPECTS(steps >= 1, "steps >= 1");
  const std::size_t ring = ring_size(profile);
  const std::size_t segments = segment_count(profile);
  const std::size_t copies = static_cast<std::size_t>(steps);
  // Normals point out of the region the profile bounds (closed through the axis if open);
  // for the usual counterclockwise case that is the reversed profile normal.
  const double side = signed_area(profile, true) >= 0.0 ? -1.0 : 1.0;
  // Samples on the axis: where the profile meets the axis at a right angle (a smooth pole, its
  // normal +-y within kSmoothPole) every copy takes the pole normal along the axis, to the side
  // the profile normal leans to; a profile running along the axis has no such lean and takes the
  // side away from the profile's middle. Where it meets the axis at an angle (a cone's apex, a
  // spindle's tip) each copy's own vertex takes the normal of the faces that use it
  // (cone_tip_normals); where the profile crosses the axis, its turned profile normal.
  glm::dvec3 lo = profile.frames.front().V, hi = lo;
  for (const Frame& f : profile.frames) {
    lo = glm::min(lo, f.V);
    hi = glm::max(hi, f.V);
  }
  const double on_axis = 1e-6 * vector_length(hi - lo);
  const double middle_y = 0.5 * (lo.y + hi.y);
  const auto pole_normal = [&](const Frame& f, const glm::dvec3& n) {
    const double lean = std::abs(n.y) > 1e-12 ? n.y : f.V.y - middle_y;
    return glm::dvec3(0.0, lean >= 0.0 ? 1.0 : -1.0, 0.0);
  };

  Mesh mesh = emptied(std::move(storage));  // filled in order: no zero-fill of what is written next
  mesh.positions.reserve(ring * copies);
  mesh.normals.reserve(ring * copies);
  mesh.indices.reserve(6 * segments * copies);
  for (std::size_t j = 0; j < copies; ++j) {
    // Counterclockwise about +y seen from above: x -> x cos, z -> -x sin.
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(copies);
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    for (std::size_t i = 0; i < ring; ++i) {
      const Frame& f = profile.frames[i];
      const glm::dvec3 n = side * f.N;
      mesh.positions.emplace_back(glm::dvec3(f.V.x * c, f.V.y, -f.V.x * s));
      const bool pole = std::abs(f.V.x) <= on_axis && (std::abs(n.x) <= kSmoothPole || std::abs(n.y) <= 1e-12);
      mesh.normals.push_back(pole ? glm::vec3(pole_normal(f, n))
                                  : glm::vec3(unit_vector(glm::dvec3(n.x * c, n.y, -n.x * s))));
    }
  }
  for (std::size_t j = 0; j < copies; ++j) {
    const std::size_t jn = (j + 1) % copies;
    for (std::size_t i = 0; i < segments; ++i) {
      const std::size_t in = (i + 1) % ring;
      // (b - a) x (c - a) points along x * N for this layout, so the order depends on the side of
      // the axis this quad is on.
      const double x = profile.frames[i].V.x + profile.frames[in].V.x;
      const bool natural = (x < 0.0) == (side < 0.0);
      // At a pole (a sample on the axis) the quad is one triangle of the pole's fan.
      add_quad_unless_collapsed(mesh.indices, static_cast<std::uint32_t>(j * ring + i),
                                static_cast<std::uint32_t>(j * ring + in), static_cast<std::uint32_t>(jn * ring + i),
                                static_cast<std::uint32_t>(jn * ring + in), natural,
                                on_revolution_axis(profile.frames[i]), on_revolution_axis(profile.frames[in]));
    }
  }
  cone_tip_normals(mesh, profile, copies, on_axis);
  if (caps) add_revolution_caps(mesh, profile, copies, on_axis);
  return mesh;
}

}  // namespace sweep
