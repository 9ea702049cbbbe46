#include "geometry/surfaces/surface_corners.hpp"

#include "base/precondition.hpp"
#include "geometry/surfaces/surface.hpp"
#include "geometry/unit_vector.hpp"

#include <glm/geometric.hpp>

#include <algorithm>

namespace sweep {

namespace {

/// Below this length the two tangents' sum has no direction: the sweep turns back on itself.
constexpr double kReversal = 1e-6;
/// Float positions this close (relative to their size, a few units in the last place) are one.
constexpr float kSamePlace = 1e-6f;

/// The rotation that turns unit `from` onto unit `to` about the axis perpendicular to both (the
/// minimal rotation), applied to v. Precondition: dot(from, to) > -1.
glm::dvec3 minimal_rotation(const glm::dvec3& from, const glm::dvec3& to, const glm::dvec3& v) {
  const glm::dvec3 axis = glm::cross(from, to);
  const glm::dvec3 av = glm::cross(axis, v);
  return v + av + glm::cross(axis, av) / (1.0 + glm::dot(from, to));
}

}  // namespace

bool bevels_corner(const glm::dvec3& incoming, const glm::dvec3& leaving, double limit) {
  const glm::dvec3 bisector = incoming + leaving;
  if (vector_length(bisector) < kReversal) return true;
  // The mitre's stretch is 1 / cos(half the turn) = 1 / (m . leaving).
  return glm::dot(unit_vector(bisector), leaving) * limit < 1.0;
}

std::size_t bevel_count(const CurveSamples& sweep, double limit) {
  const std::size_t rings = ring_size(sweep);
  return static_cast<std::size_t>(std::count_if(sweep.corners.begin(), sweep.corners.end(), [&](const Corner& c) {
    return c.sample < rings && bevels_corner(c.incoming, sweep.frames[c.sample].T, limit);
  }));
}

namespace surface_detail {

glm::dvec3 Placement::offset(double x, double y) const {
  const glm::dvec3 q = x * frame.N + y * frame.B;
  return q + (stretch - 1.0) * glm::dot(q, across) * across;
}

glm::dvec3 Placement::normal(double x, double y) const {
  glm::dvec3 n = x * frame.N + y * frame.B;
  n += (1.0 / stretch - 1.0) * glm::dot(n, across) * across;
  return unit_vector(n);
}

namespace {

/// Mitre placement at a corner: the frame (which carries the leaving tangent) is turned back by
/// half the corner's turn so the profile lies in the plane that bisects the two tube segments,
/// and stretched across the bend by 1 / cos(half turn) so both segments keep their width and meet
/// in a clean mitre, as a picture frame's corner. This keeps one ring per joint and, unlike
/// duplicating the joint with each tangent, leaves no overlapping wedge on the inside of the bend.
/// Precondition: !bevels_corner(incoming, frame.T, limit) for some finite limit.
Placement mitre_placement(const Placement& leaving, const glm::dvec3& incoming) {
  Placement placement = leaving;
  const Frame& frame = leaving.frame;
  const glm::dvec3 m = unit_vector(incoming + frame.T);
  placement.frame.T = m;
  placement.frame.N = unit_vector(minimal_rotation(frame.T, m, frame.N));
  placement.frame.B = unit_vector(glm::cross(m, placement.frame.N));
  const glm::dvec3 across = frame.T - incoming;
  if (vector_length(across) > 1e-300) placement.across = unit_vector(across - glm::dot(across, m) * m);
  placement.stretch = 1.0 / std::max(glm::dot(m, frame.T), 1e-300);
  return placement;
}

/// The arriving segment's end at a bevelled corner: the leaving frame turned back onto the
/// arriving tangent by the minimal rotation (about the bend's axis, so profile points on that
/// axis stay where they are); at a reversal, turned half a turn about N.
Placement arriving_placement(const Placement& leaving, const glm::dvec3& incoming) {
  Placement placement = leaving;
  const Frame& frame = leaving.frame;
  placement.frame.T = incoming;
  const glm::dvec3 n = vector_length(incoming + frame.T) < kReversal ? frame.N - glm::dot(frame.N, incoming) * incoming
                                                                     : minimal_rotation(frame.T, incoming, frame.N);
  placement.frame.N = unit_vector(n);
  placement.frame.B = unit_vector(glm::cross(incoming, placement.frame.N));
  return placement;
}

}  // namespace

TubeRings corner_rings(std::vector<Placement> by_sample, const std::vector<Corner>& corners, double limit) {
  SWEEP_EXPECTS(limit >= 1.0, "limit >= 1");
  const std::size_t samples = by_sample.size();
  std::vector<const Corner*> corner_at(samples, nullptr);
  for (const Corner& corner : corners) {
    if (corner.sample < samples) corner_at[corner.sample] = &corner;
  }
  TubeRings tube;
  tube.rings.reserve(samples);
  tube.sample.reserve(samples);
  tube.arrive.resize(samples);
  tube.leave.resize(samples);
  for (std::size_t j = 0; j < samples; ++j) {
    const Corner* corner = corner_at[j];
    const bool bevel = corner && bevels_corner(corner->incoming, by_sample[j].frame.T, limit);
    tube.arrive[j] = tube.rings.size();
    if (bevel) {
      tube.rings.push_back(arriving_placement(by_sample[j], corner->incoming));
      tube.sample.push_back(j);
      ++tube.bevels;
    }
    tube.leave[j] = tube.rings.size();
    tube.rings.push_back(corner && !bevel ? mitre_placement(by_sample[j], corner->incoming) : by_sample[j]);
    tube.sample.push_back(j);
  }
  return tube;
}

std::vector<bool> clip_at_corners(Mesh& mesh, std::size_t ring, const std::vector<Frame>& frames, const TubeRings& tube,
                                  const std::vector<Corner>& corners) {
  const std::size_t samples = tube.arrive.size();
  std::vector<bool> moved(tube.rings.size(), false);
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const std::size_t c = corners[k].sample;
    if (c >= samples) continue;
    const Placement& end = tube.rings[tube.arrive[c]];  // the plane the arriving segment ends in
    const Placement& start = tube.rings[tube.leave[c]];
    if (!tube.bevelled(c) && end.stretch == 1.0) continue;
    const glm::dvec3 origin = end.frame.V;
    const std::size_t before = k > 0 ? corners[k - 1].sample : 0;
    const std::size_t after = k + 1 < corners.size() ? std::min(corners[k + 1].sample, samples - 1) : samples - 1;
    // side +1: rings before the corner must stay behind the end plane; -1: rings after it in
    // front of the start plane.
    // `toward`: the grid ring next to this one on the corner's side. A point slid onto the plane
    // where that ring's point already is (both on one line along a straight segment) takes its
    // position exactly, so the triangles between them have two corners at one place and are left
    // out (add_quad_without_collapsed) instead of staying as slivers a float apart.
    const auto clip_ring = [&](std::size_t j, std::size_t grid_ring, std::size_t toward, const glm::dvec3& m,
                               double side) {
      const glm::dvec3& t = frames[j].T;
      const double along = glm::dot(t, m);
      if (along < 0.1) return false;  // the ring is not heading through this corner
      bool clipped = false;
      for (std::size_t i = 0; i < ring; ++i) {
        glm::vec3& position = mesh.positions[grid_ring * ring + i];
        const glm::dvec3 p(position);
        const double h = glm::dot(p - origin, m);
        if (side * h > 0.0) {
          position = glm::vec3(p - (h / along) * t);
          clipped = true;
        }
        // (Also a point that reaches the plane by itself, the last ring a walk looks at.)
        const glm::vec3& neighbour = mesh.positions[toward * ring + i];
        if (glm::length(position - neighbour) <= kSamePlace * std::max(1.0f, glm::length(neighbour))) {
          position = neighbour;
          moved[grid_ring] = true;
        }
      }
      if (clipped) moved[grid_ring] = true;
      return clipped;
    };
    for (std::size_t j = c; j-- > before;) {
      if (!clip_ring(j, tube.leave[j], j + 1 == c ? tube.arrive[c] : tube.leave[j + 1], end.frame.T, 1.0)) break;
    }
    for (std::size_t j = c + 1; j <= after && j > c; ++j) {
      if (!clip_ring(j, tube.arrive[j], j - 1 == c ? tube.leave[c] : tube.arrive[j - 1], start.frame.T, -1.0)) break;
    }
  }
  return moved;
}

void add_bevel_strips(Mesh& mesh, std::size_t ring, std::size_t segments, const TubeRings& tube, bool natural) {
  SWEEP_EXPECTS(mesh.positions.size() >= tube.rings.size() * ring, "the mesh holds the grid first");
  mesh.positions.reserve(mesh.positions.size() + 4 * segments * tube.bevels);
  mesh.normals.reserve(mesh.normals.size() + 4 * segments * tube.bevels);
  for (std::size_t j = 0; j < tube.arrive.size(); ++j) {
    if (!tube.bevelled(j)) continue;
    const std::size_t from = tube.arrive[j] * ring, to = tube.leave[j] * ring;
    for (std::size_t i = 0; i < segments; ++i) {
      const std::size_t in = (i + 1) % ring;
      // add_quad's (a, b, c, d): the arriving ring's segment, then the leaving ring's.
      const std::size_t corner[4] = {from + i, from + in, to + i, to + in};
      const glm::dvec3 a(mesh.positions[corner[0]]), b(mesh.positions[corner[1]]);
      const glm::dvec3 c(mesh.positions[corner[2]]), d(mesh.positions[corner[3]]);
      // The diagonals' cross product is twice the quad's area vector, (b - a) x (c - a) for a
      // flat one. A quad folded to nothing (the profile on the bend's axis) takes the tube's.
      glm::dvec3 n = glm::cross(d - a, c - b);
      if (!natural) n = -n;
      const double size = vector_length(d - a) * vector_length(c - b);
      const glm::vec3 flat = vector_length(n) > 1e-9 * size ? glm::vec3(unit_vector(n)) : mesh.normals[corner[0]];
      const auto first = static_cast<std::uint32_t>(mesh.positions.size());
      for (const std::size_t v : corner) {
        mesh.positions.push_back(mesh.positions[v]);
        mesh.normals.push_back(flat);
      }
      // Profile points on the bend's axis are on both rings: such a triangle has no area.
      add_quad_without_collapsed(mesh.indices, mesh.positions, first, first + 1, first + 2, first + 3, natural);
    }
  }
}

}  // namespace surface_detail
}  // namespace sweep
