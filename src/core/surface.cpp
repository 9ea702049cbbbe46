#include "core/surface.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>

namespace sweep {
namespace {

/// How many distinct samples a curve contributes to a ring: a closed curve's last sample is its
/// first, so the ring wraps around instead of repeating it.
std::size_t ring_size(const CurveSamples& c) { return c.closed ? c.frames.size() - 1 : c.frames.size(); }
/// How many segments join consecutive ring samples (a closed ring also joins last to first).
std::size_t segment_count(const CurveSamples& c) { return c.closed ? ring_size(c) : c.frames.size() - 1; }

/// Twice the signed area of the profile polygon (counterclockwise positive). If `through_axis`,
/// an open profile is closed through the y axis: its ends are joined by their projections.
double signed_area(const CurveSamples& profile, bool through_axis) {
  const auto& f = profile.frames;
  const std::size_t n = ring_size(profile);
  double area = 0.0;
  auto edge = [&area](const glm::dvec3& a, const glm::dvec3& b) { area += a.x * b.y - b.x * a.y; };
  for (std::size_t i = 0; i + 1 < n; ++i) edge(f[i].V, f[i + 1].V);
  const glm::dvec3 first = f.front().V;
  const glm::dvec3 last = f[n - 1].V;
  if (profile.closed || !through_axis) {
    edge(last, first);
  } else {
    const glm::dvec3 last_on_axis(0.0, last.y, 0.0);
    const glm::dvec3 first_on_axis(0.0, first.y, 0.0);
    edge(last, last_on_axis);
    edge(last_on_axis, first_on_axis);
    edge(first_on_axis, first);
  }
  return area;
}

/// Appends the two triangles of the quad (a, b, c, d) = ((i, j), (i+1, j), (i, j+1), (i+1, j+1)).
/// `natural` keeps the order whose geometric normal is (b - a) x (c - a); otherwise it is flipped.
inline void add_quad(std::vector<std::uint32_t>& out, std::uint32_t a, std::uint32_t b, std::uint32_t c,
                     std::uint32_t d, bool natural) {
  if (natural) {
    out.insert(out.end(), {a, b, c, b, d, c});
  } else {
    out.insert(out.end(), {a, c, b, b, c, d});
  }
}

}  // namespace

std::int64_t revolution_vertex_count(std::int64_t profile_samples, bool profile_closed, std::int64_t steps) {
  return (profile_closed ? profile_samples - 1 : profile_samples) * steps;
}

std::int64_t cylinder_vertex_count(std::int64_t profile_samples, bool profile_closed, std::int64_t sweep_samples,
                                   bool sweep_closed) {
  return (profile_closed ? profile_samples - 1 : profile_samples) * (sweep_closed ? sweep_samples - 1 : sweep_samples);
}

Mesh build_surface_of_revolution(const CurveSamples& profile, int steps) {
  const std::size_t ring = ring_size(profile);
  const std::size_t segments = segment_count(profile);
  const std::size_t copies = static_cast<std::size_t>(steps);
  // Normals point out of the region the profile bounds (closed through the axis if open);
  // for the usual counterclockwise case that is the reversed profile normal.
  const double side = signed_area(profile, true) >= 0.0 ? -1.0 : 1.0;

  Mesh mesh;
  mesh.positions.resize(ring * copies);
  mesh.normals.resize(ring * copies);
  mesh.indices.reserve(6 * segments * copies);
  for (std::size_t j = 0; j < copies; ++j) {
    // Counterclockwise about +y seen from above: x -> x cos, z -> -x sin.
    const double angle = 2.0 * std::numbers::pi * static_cast<double>(j) / static_cast<double>(copies);
    const double c = std::cos(angle);
    const double s = std::sin(angle);
    for (std::size_t i = 0; i < ring; ++i) {
      const Frame& f = profile.frames[i];
      const glm::dvec3 n = side * f.N;
      mesh.positions[j * ring + i] = glm::vec3(glm::dvec3(f.V.x * c, f.V.y, -f.V.x * s));
      mesh.normals[j * ring + i] = glm::vec3(glm::normalize(glm::dvec3(n.x * c, n.y, -n.x * s)));
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
      add_quad(mesh.indices, static_cast<std::uint32_t>(j * ring + i), static_cast<std::uint32_t>(j * ring + in),
               static_cast<std::uint32_t>(jn * ring + i), static_cast<std::uint32_t>(jn * ring + in), natural);
    }
  }
  return mesh;
}

Mesh build_generalized_cylinder(const CurveSamples& profile, const CurveSamples& sweep) {
  const std::size_t ring = ring_size(profile);
  const std::size_t segments = segment_count(profile);
  const std::size_t rings = ring_size(sweep);
  const std::size_t sweep_segments = segment_count(sweep);
  // Closed profiles: normals out of the enclosed region. Open: reversed, like the original tool.
  const double side = profile.closed && signed_area(profile, false) < 0.0 ? 1.0 : -1.0;

  Mesh mesh;
  mesh.positions.resize(ring * rings);
  mesh.normals.resize(ring * rings);
  mesh.indices.reserve(6 * segments * sweep_segments);
  for (std::size_t j = 0; j < rings; ++j) {
    const Frame& s = sweep.frames[j];
    for (std::size_t i = 0; i < ring; ++i) {
      const Frame& p = profile.frames[i];
      const glm::dvec3 n = side * p.N;
      mesh.positions[j * ring + i] = glm::vec3(s.V + p.V.x * s.N + p.V.y * s.B);
      mesh.normals[j * ring + i] = glm::vec3(glm::normalize(n.x * s.N + n.y * s.B));
    }
  }
  // With P = V + x N + y B, (b - a) x (c - a) points along -(profile normal), so the natural
  // order suits side = -1.
  const bool natural = side < 0.0;
  for (std::size_t j = 0; j < sweep_segments; ++j) {
    const std::size_t jn = (j + 1) % rings;
    for (std::size_t i = 0; i < segments; ++i) {
      const std::size_t in = (i + 1) % ring;
      add_quad(mesh.indices, static_cast<std::uint32_t>(j * ring + i), static_cast<std::uint32_t>(j * ring + in),
               static_cast<std::uint32_t>(jn * ring + i), static_cast<std::uint32_t>(jn * ring + in), natural);
    }
  }
  return mesh;
}

}  // namespace sweep
