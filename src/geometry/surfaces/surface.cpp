#include "geometry/surfaces/surface.hpp"

#include "base/precondition.hpp"
#include "geometry/surfaces/end_caps.hpp"
#include "geometry/surfaces/surface_corners.hpp"
#include "geometry/surfaces/surface_detail.hpp"
#include "geometry/surfaces/tube_quads.hpp"
#include "geometry/thread_pool.hpp"
#include "geometry/unit_vector.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <utility>

namespace sweep {

std::size_t ring_size(const CurveSamples& c) {
  return c.closed ? c.frames.size() - 1 : c.frames.size();
}

namespace surface_detail {

std::size_t segment_count(const CurveSamples& c) {
  return c.closed ? ring_size(c) : c.frames.size() - 1;
}

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

}  // namespace surface_detail

namespace {

using surface_detail::Placement;
using surface_detail::segment_count;
using surface_detail::signed_area;
using surface_detail::TubeRings;

/// Curve parameter (in pieces) of sweep sample j.
double parameter_of(const CurveSamples& sweep, std::size_t j) {
  if (j < sweep.parameters.size()) return sweep.parameters[j];
  return static_cast<double>(j) / static_cast<double>(std::max(sweep.steps, 1));
}

/// Writes ring `at` (vertices at * ring..) of a tube whose profile the controls scale and twist
/// (the twist is in the placement's frame already). The normal is the profile's, tilted along T so
/// it is normal to the surface's derivative along the sweep: dP/ds = T (1 - q . bend) + (scale
/// rate / s) q + (twist rate) T x q for the offset q, whose T component only the tilt can cancel.
void place_controlled_ring(Mesh& mesh, std::size_t at, const CurveSamples& profile, const Placement& place,
                           const Station& station, double side) {
  const glm::dvec3& t = place.frame.T;
  const std::size_t ring = ring_size(profile);
  for (std::size_t i = 0; i < ring; ++i) {
    const Frame& p = profile.frames[i];
    const glm::dvec3 q = place.offset(station.scale * p.V.x, station.scale * p.V.y);
    glm::dvec3 n = place.normal(side * p.N.x, side * p.N.y);
    glm::dvec3 along = glm::cross(t, q) * station.twist_rate;
    if (station.scale > 0.0) along += (station.scale_rate / station.scale) * q;
    const double forward = std::max(1.0 - glm::dot(q, station.bend), 0.05);
    n = unit_vector(n - (glm::dot(n, along) / forward) * t);
    mesh.positions[at * ring + i] = place.frame.V + q;
    mesh.normals[at * ring + i] = n;
  }
}

/// Writes ring `at` (vertices at * ring..) of a tube the controls leave alone.
void place_ring(Mesh& mesh, std::size_t at, const CurveSamples& profile, const Placement& place, double side) {
  const std::size_t ring = ring_size(profile);
  for (std::size_t i = 0; i < ring; ++i) {
    const Frame& p = profile.frames[i];
    const glm::dvec3 n = side * p.N;
    if (place.stretch == 1.0) {
      mesh.positions[at * ring + i] = place.frame.V + p.V.x * place.frame.N + p.V.y * place.frame.B;
      mesh.normals[at * ring + i] = unit_vector(n.x * place.frame.N + n.y * place.frame.B);
    } else {
      mesh.positions[at * ring + i] = place.frame.V + place.offset(p.V.x, p.V.y);
      mesh.normals[at * ring + i] = place.normal(n.x, n.y);
    }
  }
}

/// Vertices below which a tube's rings are placed on the calling thread (a drag's re-mesh of a
/// small tube costs less than starting threads).
constexpr std::size_t kParallelVertices = 1 << 16;

/// The seam shift of a closed sweep once the twist's whole symmetry turns are added (the reader
/// refuses a twist that is not a whole number of them; a partial one is rounded).
std::size_t twisted_seam_shift(const CurveSamples& profile, const SweepControls& controls, std::size_t shift,
                               std::size_t ring) {
  const double twist = total_twist_degrees(controls) * std::numbers::pi / 180.0;
  if (twist == 0.0) return shift;
  const ProfileSymmetry symmetry = profile_symmetry(profile);
  const double turns = std::round(twist / (2.0 * std::numbers::pi / symmetry.order));
  const auto r = static_cast<long long>(ring);
  const long long total = static_cast<long long>(shift) + static_cast<long long>(turns) * symmetry.shift;
  return static_cast<std::size_t>(((total % r) + r) % r);
}

}  // namespace

double profile_radius(const CurveSamples& profile) {
  double radius = 0.0;
  for (const Frame& f : profile.frames) radius = std::max(radius, vector_length(f.V));
  return radius;
}

ProfileSymmetry profile_symmetry(const CurveSamples& profile) {
  ProfileSymmetry symmetry;
  if (!profile.closed || profile.frames.size() < 4) return symmetry;
  const auto ring = static_cast<int>(ring_size(profile));
  const double radius = profile_radius(profile);
  if (radius <= 0.0) return symmetry;
  // Files give coordinates to about 6 digits; circles are exact to rounding.
  const double tolerance = 1e-5 * radius;
  const auto maps_onto_itself = [&](int k, int shift) {
    const double angle = 2.0 * std::numbers::pi / k;
    const double c = std::cos(angle), s = std::sin(angle);
    for (int i = 0; i < ring; ++i) {
      const glm::dvec3& p = profile.frames[static_cast<std::size_t>(i)].V;
      const glm::dvec3 turned(c * p.x - s * p.y, s * p.x + c * p.y, 0.0);
      const int partner = ((i + shift) % ring + ring) % ring;
      if (vector_length(turned - profile.frames[static_cast<std::size_t>(partner)].V) > tolerance) return false;
    }
    return true;
  };
  for (int k = ring; k >= 2; --k) {
    if (ring % k != 0) continue;
    const int step = ring / k;
    // A counterclockwise profile advances by `step` samples per turn, a clockwise one goes back.
    for (const int shift : {step, -step}) {
      if (maps_onto_itself(k, shift)) return {k, shift};
    }
  }
  return symmetry;
}

std::int64_t revolution_vertex_count(std::int64_t profile_samples, bool profile_closed, std::int64_t steps) {
  return (profile_closed ? profile_samples - 1 : profile_samples) * steps;
}

bool on_revolution_axis(const Frame& sample) {
  return static_cast<float>(sample.V.x) == 0.0f;
}

std::int64_t revolution_triangle_count(const CurveSamples& profile, std::int64_t steps) {
  const std::size_t ring = ring_size(profile);
  const std::size_t segments = surface_detail::segment_count(profile);
  std::int64_t per_copy = 0;
  for (std::size_t i = 0; i < segments; ++i) {
    const int poles =
        (on_revolution_axis(profile.frames[i]) ? 1 : 0) + (on_revolution_axis(profile.frames[(i + 1) % ring]) ? 1 : 0);
    per_copy += std::max(0, 2 - poles);
  }
  return per_copy * steps;
}

std::int64_t cylinder_vertex_count(std::int64_t profile_samples, bool profile_closed, std::int64_t sweep_samples,
                                   bool sweep_closed, std::int64_t bevels) {
  const std::int64_t ring = profile_closed ? profile_samples - 1 : profile_samples;
  const std::int64_t strip = 4 * (profile_closed ? ring : ring - 1);
  return ring * (sweep_closed ? sweep_samples - 1 : sweep_samples) + bevels * (ring + strip);
}

std::int64_t cylinder_triangle_count(std::int64_t profile_samples, std::int64_t sweep_samples, std::int64_t bevels) {
  return 2 * (profile_samples - 1) * (sweep_samples - 1 + bevels);
}

namespace {

bool is_point_sweep(const CurveSamples& sweep) {
  return std::all_of(sweep.frames.begin(), sweep.frames.end(),
                     [&](const Frame& f) { return f.V == sweep.frames.front().V; });
}

double profile_mean_x(const CurveSamples& profile) {
  const std::size_t ring = ring_size(profile);
  double sum = 0.0;
  for (std::size_t i = 0; i < ring; ++i) sum += profile.frames[i].V.x;
  return sum / static_cast<double>(ring);
}

}  // namespace

Mesh build_generalized_cylinder(const CurveSamples& profile, const CurveSamples& sweep, SeamMode seam,
                                SweepDiagnostics* diagnostics, const SweepControls& controls, Mesh storage) {
  SWEEP_EXPECTS(profile.planar, "profile.planar");
  SWEEP_EXPECTS(profile.frames.size() >= 2 && sweep.frames.size() >= 2, "both have >= 2 samples");
  const std::size_t ring = ring_size(profile);
  const std::size_t segments = segment_count(profile);
  const std::size_t rings = ring_size(sweep);
  const std::size_t sweep_segments = segment_count(sweep);
  // Closed profiles: normals out of the enclosed region. Open: reversed, like the original tool.
  double side = profile.closed && signed_area(profile, false) < 0.0 ? 1.0 : -1.0;
  // Along a sweep of zero length (a circle of radius 0) the profile only turns with the frames,
  // and a point at profile x > 0 moves along -T rather than T: a profile on that side is turned
  // over (normals and winding) so the solid it makes about B still faces out.
  if (is_point_sweep(sweep) && profile_mean_x(profile) > 0.0) side = -side;

  // The sweep's frames as the tube uses them. With a symmetric seam, the part of the closure
  // rotation that is a whole number of the profile's symmetry turns is given back: frame j turns
  // by beta * s_j / L, so the end frame is the start frame turned by beta and the last ring joins
  // the first one `seam_shift` samples on.
  std::vector<Frame> frames(sweep.frames);
  double spread = sweep.seam_angle;
  std::size_t seam_shift = 0;
  if (seam == SeamMode::Symmetric && sweep.closed && sweep.seam_angle != 0.0) {
    const ProfileSymmetry symmetry = profile_symmetry(profile);
    const double turn = 2.0 * std::numbers::pi / symmetry.order;
    const double whole_turns = std::round(sweep.seam_angle / turn);
    if (symmetry.order > 1 && whole_turns != 0.0) {
      const double beta = whole_turns * turn;
      spread = sweep.seam_angle - beta;
      const std::vector<double> length = chord_lengths(frames);
      for (std::size_t j = 1; j < frames.size(); ++j) rotate_about_tangent(frames[j], beta * length[j] / length.back());
      const auto r = static_cast<long long>(ring);
      const long long shift = static_cast<long long>(whole_turns) * symmetry.shift;
      seam_shift = static_cast<std::size_t>(((shift % r) + r) % r);
    }
  }

  // The controls turn each placement's frame by the twist there and scale the profile.
  const bool placed = controls.places();
  const std::vector<Station> stations = placed ? sweep_stations(frames, controls) : std::vector<Station>{};
  if (placed && sweep.closed) seam_shift = twisted_seam_shift(profile, controls, seam_shift, ring);
  std::vector<Placement> by_sample(rings);
  for (std::size_t j = 0; j < rings; ++j) {
    by_sample[j].frame = frames[j];
    if (placed) rotate_about_tangent(by_sample[j].frame, stations[j].twist);
  }
  const TubeRings tube = surface_detail::corner_rings(std::move(by_sample), sweep.corners, controls.mitre_limit);
  const std::size_t grid_rings = tube.rings.size();

  // Each ring written in its place, the rings on the worker threads (the same mesh at any thread
  // count); the strips and caps come after.
  // Room for the caps too (a copy of each end ring, n - 2 triangles each): no reallocation.
  const bool capped = controls.caps && profile.closed && !sweep.closed && ring >= 3;
  const std::size_t cap_vertices = capped ? 2 * ring : 0;
  Mesh mesh = emptied(std::move(storage));
  mesh.positions.reserve(ring * grid_rings + cap_vertices);
  mesh.normals.reserve(ring * grid_rings + cap_vertices);
  mesh.indices.reserve(6 * segments * (sweep_segments + tube.bevels) + (capped ? 6 * ring : 0));
  const int threads = ring * grid_rings < kParallelVertices ? 1 : worker_count();
  // A large grid's three arrays are sized side by side (each zero-filled, and its fresh memory
  // faulted in, by one thread), the indices for the quads to be written in place.
  const std::size_t grid_indices = threads > 1 ? 6 * segments * sweep_segments : 0;
  run_side_by_side({[&] { mesh.indices.resize(grid_indices); }, [&] { mesh.positions.resize(ring * grid_rings); },
                    [&] { mesh.normals.resize(ring * grid_rings); }},
                   threads);
  parallel_chunks(grid_rings, std::max<std::size_t>(1, kParallelVertices / 4 / ring), threads,
                  [&](std::size_t begin, std::size_t end, int) {
                    for (std::size_t k = begin; k < end; ++k) {
                      if (placed) {
                        place_controlled_ring(mesh, k, profile, tube.rings[k], stations[tube.sample[k]], side);
                      } else {
                        place_ring(mesh, k, profile, tube.rings[k], side);
                      }
                    }
                  });
  const std::vector<bool> moved = surface_detail::clip_at_corners(mesh, ring, frames, tube, sweep.corners);
  // With P = V + x N + y B, (b - a) x (c - a) points along -(profile normal), so the natural
  // order suits side = -1.
  const bool natural = side < 0.0;
  // The quads in bands of kBandQuads columns, each band row after row: a GPU's vertex cache (16
  // entries) then holds a band's last row while its next one is drawn, so each vertex is read
  // about once (ACMR ~0.6 against 1.0 row by row) and the glb writer need not reorder the grid.
  const surface_detail::TubeGrid grid{ring, segments, rings, sweep_segments, seam_shift, &tube, &moved};
  surface_detail::add_tube_quads(mesh, grid, natural, grid_indices > 0, threads);
  surface_detail::add_bevel_strips(mesh, ring, segments, tube, natural);

  if (capped) {
    std::vector<glm::dvec2> polygon(ring);
    for (std::size_t i = 0; i < ring; ++i) polygon[i] = glm::dvec2(profile.frames[i].V);
    add_tube_caps(mesh, polygon, grid_rings, -tube.rings.front().frame.T, tube.rings.back().frame.T);
  }
  if (diagnostics) {
    SweepDiagnostics& d = *diagnostics;
    d = {};
    d.closed = sweep.closed;
    d.seam_angle = spread;
    d.bevels = tube.bevels;
    for (std::size_t j = 0; j + 1 < frames.size(); ++j) {
      const Frame reference = transport_rotation_minimizing(frames[j], frames[j + 1]);
      d.total_twist += std::abs(angle_about(frames[j + 1].T, reference.N, frames[j + 1].N));
    }
    const double radius = profile_radius(profile);
    const std::size_t samples = std::min(sweep.closed ? rings : frames.size(), sweep.curvature.size());
    for (std::size_t j = 0; j < samples; ++j) {
      if (sweep.curvature[j] * radius < 1.0) continue;
      if (!d.folds.empty() && d.folds.back().last_sample + 1 == static_cast<int>(j)) {
        d.folds.back().last_sample = static_cast<int>(j);
        d.folds.back().t_end = parameter_of(sweep, j);
      } else {
        d.folds.push_back({static_cast<int>(j), static_cast<int>(j), parameter_of(sweep, j), parameter_of(sweep, j)});
      }
    }
  }
  return mesh;
}

}  // namespace sweep
