#include "geometry/surfaces/birail.hpp"

#include "base/precondition.hpp"
#include "geometry/unit_vector.hpp"

#include <glm/geometric.hpp>

#include <algorithm>

namespace sweep {
namespace {

struct RailPoint {
  glm::dvec3 position{0.0};
  glm::dvec3 tangent{0.0};
};

/// The rail's polyline at a fraction of its chord length, with its tangent interpolated.
RailPoint rail_at(const CurveSamples& rail, const std::vector<double>& length, double fraction) {
  const double s = fraction * length.back();
  const auto it = std::upper_bound(length.begin(), length.end(), s);
  const auto hi = static_cast<std::size_t>(
      std::clamp<std::ptrdiff_t>(it - length.begin(), 1, static_cast<std::ptrdiff_t>(length.size() - 1)));
  const std::size_t lo = hi - 1;
  const double span = length[hi] - length[lo];
  const double t = span > 0.0 ? std::clamp((s - length[lo]) / span, 0.0, 1.0) : 0.0;
  const Frame& a = rail.frames[lo];
  const Frame& b = rail.frames[hi];
  return {a.V + t * (b.V - a.V), (1.0 - t) * a.T + t * b.T};
}

/// The sorted fractions of arc length at which either rail has a sample.
std::vector<double> merged_fractions(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> all;
  all.reserve(a.size() + b.size());
  for (const std::vector<double>* length : {&a, &b}) {
    const double total = length->back();
    const double n = static_cast<double>(length->size() - 1);
    for (std::size_t i = 0; i < length->size(); ++i) {
      all.push_back(total > 0.0 ? (*length)[i] / total : static_cast<double>(i) / n);
    }
  }
  std::sort(all.begin(), all.end());
  std::vector<double> merged;
  merged.reserve(all.size());
  for (const double f : all) {
    if (merged.empty() || f - merged.back() > 1e-12) merged.push_back(f);
  }
  merged.back() = 1.0;  // both rails end together
  return merged;
}

/// Per vertex, the sum of the (area-weighted) normals of the triangles around it.
std::vector<glm::dvec3> face_normal_sums(const std::vector<glm::dvec3>& points,
                                         const std::vector<std::uint32_t>& indices) {
  std::vector<glm::dvec3> sums(points.size(), glm::dvec3(0.0));
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const glm::dvec3& a = points[indices[t]];
    const glm::dvec3 n = glm::cross(points[indices[t + 1]] - a, points[indices[t + 2]] - a);
    for (std::size_t k = 0; k < 3; ++k) sums[indices[t + k]] += n;
  }
  return sums;
}

/// True where the rails meet and the section is one point (without `height`).
bool at_one_point(const BirailStation& s) {
  return s.along_scale == 0.0 && s.up_scale == 0.0;
}

/// A unit vector perpendicular to unit `v`.
glm::dvec3 any_perpendicular(const glm::dvec3& v) {
  const glm::dvec3 axis = std::abs(v.x) < 0.9 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  return unit_vector(glm::cross(v, axis));
}

}  // namespace

ProfileChord profile_chord(const CurveSamples& profile) {
  SWEEP_EXPECTS(profile.frames.size() >= 2, "the profile has >= 2 samples");
  ProfileChord chord;
  chord.first = profile.frames.front().V;
  const glm::dvec3 e = profile.frames.back().V - chord.first;
  chord.length = vector_length(e);
  if (chord.length > 0.0) {
    chord.along = e / chord.length;
    chord.left = glm::dvec3(-chord.along.y, chord.along.x, 0.0);
  }
  return chord;
}

std::vector<BirailStation> birail_stations(const CurveSamples& rail1, const CurveSamples& rail2,
                                           const ProfileChord& chord, bool keep_height) {
  SWEEP_EXPECTS(rail1.frames.size() >= 2 && rail2.frames.size() >= 2, "both rails have >= 2 samples");
  SWEEP_EXPECTS(chord.length > 0.0, "chord.length > 0");
  const std::vector<double> length1 = chord_lengths(rail1.frames);
  const std::vector<double> length2 = chord_lengths(rail2.frames);
  const std::vector<double> fractions = merged_fractions(length1, length2);
  std::vector<BirailStation> stations(fractions.size());
  for (std::size_t k = 0; k < fractions.size(); ++k) {
    BirailStation& s = stations[k];
    const BirailStation* previous = k > 0 ? &stations[k - 1] : nullptr;
    s.fraction = fractions[k];
    const RailPoint a = rail_at(rail1, length1, s.fraction);
    const RailPoint b = rail_at(rail2, length2, s.fraction);
    s.origin = a.position;
    const glm::dvec3 chord_vector = b.position - a.position;
    const double span = vector_length(chord_vector);
    // Where the rails meet there is no chord: keep the previous station's directions.
    if (span > 0.0)
      s.across = chord_vector / span;
    else if (previous)
      s.across = previous->across;
    glm::dvec3 travel = a.tangent + b.tangent;
    if (vector_length(travel) < 1e-9) travel = a.tangent;
    glm::dvec3 normal = travel - glm::dot(travel, s.across) * s.across;
    if (vector_length(normal) > 1e-9 * std::max(vector_length(travel), 1e-300)) {
      s.travel = unit_vector(normal);
    } else {
      s.travel = previous ? previous->travel : any_perpendicular(s.across);
      s.travel = unit_vector(s.travel - glm::dot(s.travel, s.across) * s.across);
    }
    s.up = glm::cross(s.travel, s.across);
    s.along_scale = span / chord.length;
    s.up_scale = keep_height ? 1.0 : s.along_scale;
  }
  // Rails that start together (a bow) have no chord there: the first station with one lends its
  // directions to those before it.
  const auto first_chord =
      std::find_if(stations.begin(), stations.end(), [](const BirailStation& s) { return s.along_scale > 0.0; });
  for (auto it = stations.begin(); it != first_chord && first_chord != stations.end(); ++it) {
    it->across = first_chord->across;
    it->travel = first_chord->travel;
    it->up = first_chord->up;
  }
  return stations;
}

glm::dvec3 place_on_station(const BirailStation& station, const ProfileChord& chord, const glm::dvec3& p) {
  const glm::dvec3 d = p - chord.first;
  const double u = d.x * chord.along.x + d.y * chord.along.y;
  const double w = d.x * chord.left.x + d.y * chord.left.y;
  return station.origin + (u * station.along_scale) * station.across + (w * station.up_scale) * station.up;
}

Mesh build_birail(const CurveSamples& profile, const CurveSamples& rail1, const CurveSamples& rail2, bool keep_height) {
  SWEEP_EXPECTS(profile.planar, "profile.planar");
  SWEEP_EXPECTS(profile.frames.size() >= 2 && profile.frames.front().V != profile.frames.back().V,
                "the profile's ends apart");
  SWEEP_EXPECTS(rail1.frames.size() >= 2 && rail2.frames.size() >= 2, "both rails have >= 2 samples");
  const ProfileChord chord = profile_chord(profile);
  const std::vector<BirailStation> stations = birail_stations(rail1, rail2, chord, keep_height);
  const bool closed = rail1.closed && rail2.closed && stations.size() > 2;
  const std::size_t ring = profile.frames.size();
  const std::size_t rings = closed ? stations.size() - 1 : stations.size();
  Mesh mesh;
  mesh.positions.resize(ring * rings);
  mesh.normals.resize(ring * rings);
  mesh.indices.reserve(6 * (ring - 1) * (closed ? rings : rings - 1));
  std::vector<glm::dvec3> placed(ring * rings);
  for (std::size_t j = 0; j < rings; ++j) {
    for (std::size_t i = 0; i < ring; ++i)
      placed[j * ring + i] = place_on_station(stations[j], chord, profile.frames[i].V);
  }
  for (std::size_t v = 0; v < placed.size(); ++v) mesh.positions[v] = glm::vec3(placed[v]);
  // (b - a) x (c - a) is du x dv, the normal's side: the natural order. Where the rails meet, a
  // station's ring is one point: the triangles with a side there have no area and are left out.
  const std::size_t segments = closed ? rings : rings - 1;
  for (std::size_t j = 0; j < segments; ++j) {
    const std::size_t jn = (j + 1) % rings;
    const bool tip = at_one_point(stations[j]) || at_one_point(stations[jn]);
    for (std::size_t i = 0; i + 1 < ring; ++i) {
      const auto a = static_cast<std::uint32_t>(j * ring + i), b = static_cast<std::uint32_t>(j * ring + i + 1);
      const auto c = static_cast<std::uint32_t>(jn * ring + i), d = static_cast<std::uint32_t>(jn * ring + i + 1);
      if (tip) {
        add_quad_without_collapsed(mesh.indices, mesh.positions, a, b, c, d, true);
      } else {
        add_quad(mesh.indices, a, b, c, d, true);
      }
    }
  }
  const std::vector<glm::dvec3> faces = face_normal_sums(placed, mesh.indices);
  for (std::size_t j = 0; j < rings; ++j) {
    const BirailStation& s = stations[j];
    // Along the rails: central differences of the placed points (one-sided at open ends).
    const std::size_t before = j > 0 ? j - 1 : (closed ? rings - 1 : j);
    const std::size_t after = j + 1 < rings ? j + 1 : (closed ? 0 : j);
    for (std::size_t i = 0; i < ring; ++i) {
      const std::size_t v = j * ring + i;
      const glm::dvec3& t = profile.frames[i].T;
      // Across: the profile's tangent carried by the station's (anisotropic) placement.
      const glm::dvec3 du = (s.along_scale * glm::dot(t, chord.along)) * s.across +
                            (s.up_scale * (t.x * chord.left.x + t.y * chord.left.y)) * s.up;
      const glm::dvec3 n = glm::cross(du, placed[after * ring + i] - placed[before * ring + i]);
      // Where the section collapses (the rails meet, so du vanishes) or folds, the faces around
      // the vertex say which way is out.
      const bool usable = s.along_scale > 1e-6 * s.up_scale && glm::dot(n, faces[v]) > 0.0;
      const glm::dvec3 chosen = usable ? n : faces[v];
      mesh.normals[v] = glm::vec3(vector_length(chosen) > 0.0 ? unit_vector(chosen) : s.travel);
    }
  }
  return mesh;
}

}  // namespace sweep
