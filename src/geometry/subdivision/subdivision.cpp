// Subdivision through OpenSubdiv. Catmull-Clark from level 1 on evaluates each cage face's limit
// surface on every core (subdivision_faces.hpp) and gives the mesh Far's refinement would. The
// rest (Loop, level 0, non-manifold cages, and the normals the limit tangents leave to a
// fallback) goes through the Far layer, in the shape of its far_tutorial_1_1 (a
// TopologyDescriptor for the cage, uniform refinement, PrimvarRefiner to carry positions down the
// levels in one buffer) and far_tutorial_2_1 (PrimvarRefiner::Limit for limit positions and
// tangents; for Catmull-Clark, the same masks through subdivision_limit.hpp).
// Catmull-Clark: Catmull and Clark 1978; Loop: Loop 1987; limit evaluation: Stam 1998.
#include "geometry/subdivision/subdivision.hpp"

#include "base/precondition.hpp"
#include "geometry/mesh/weld.hpp"
#include "geometry/subdivision/subdivision_faces.hpp"
#include "geometry/subdivision/subdivision_limit.hpp"

#include <opensubdiv/far/primvarRefiner.h>
#include <opensubdiv/far/topologyDescriptor.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <memory>
#include <numeric>
#include <optional>
#include <unordered_map>

namespace sweep {
namespace {

using namespace OpenSubdiv;
using subdivision_detail::catmark_limit_applies;
using subdivision_detail::RefinedPoint;

std::uint64_t edge_key(int a, int b) {
  const auto lo = static_cast<std::uint64_t>(std::min(a, b));
  const auto hi = static_cast<std::uint64_t>(std::max(a, b));
  return (hi << 32) | lo;
}

/// Every level's positions in one buffer, level after level (as far_tutorial_1_1 keeps them):
/// the cage's carried down. Not zero-filled first: each level is written before it is read.
struct RefinedLevels {
  std::unique_ptr<RefinedPoint[]> points;
  const RefinedPoint* last = nullptr;  // the last level's
};

RefinedLevels refined_points(const Far::TopologyRefiner& refiner, const Cage& cage) {
  RefinedLevels out;
  out.points = std::make_unique_for_overwrite<RefinedPoint[]>(static_cast<std::size_t>(refiner.GetNumVerticesTotal()));
  RefinedPoint* current = out.points.get();
  for (std::size_t i = 0; i < cage.points.size(); ++i) current[i].p = cage.points[i];
  const Far::PrimvarRefinerReal<double> primvar(refiner);
  for (int level = 1; level <= refiner.GetMaxLevel(); ++level) {
    RefinedPoint* next = current + refiner.GetLevel(level - 1).GetNumVertices();
    primvar.Interpolate(level, current, next);
    current = next;
  }
  out.last = current;
  return out;
}

/// Each face of `level` as triangles: a quad as add_quad's pair (so grid_cage finds it again),
/// other polygons as fans.
void add_faces(const Far::TopologyLevel& level, Mesh& mesh) {
  const int triangles = level.GetNumFaceVertices() - 2 * level.GetNumFaces();
  mesh.indices.reserve(3 * static_cast<std::size_t>(triangles));
  for (int f = 0; f < level.GetNumFaces(); ++f) {
    const Far::ConstIndexArray v = level.GetFaceVertices(f);
    const auto at = [&v](int i) { return static_cast<std::uint32_t>(v[i]); };
    if (v.size() == 4) {
      add_quad(mesh.indices, at(0), at(1), at(3), at(2), true);
      continue;
    }
    for (int i = 1; i + 1 < v.size(); ++i) mesh.indices.insert(mesh.indices.end(), {at(0), at(i), at(i + 1)});
  }
}

/// Area-weighted face normals summed at each vertex: the fallback where the limit tangents are
/// parallel (an extraordinary point of a degenerate cage).
std::vector<glm::dvec3> face_normal_sums(const Mesh& mesh, const RefinedPoint* positions, std::size_t count) {
  std::vector<glm::dvec3> sums(count, glm::dvec3(0.0));
  for (std::size_t t = 0; t + 2 < mesh.indices.size(); t += 3) {
    const std::uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
    const glm::dvec3 n = glm::cross(positions[b].p - positions[a].p, positions[c].p - positions[a].p);
    sums[a] += n;
    sums[b] += n;
    sums[c] += n;
  }
  return sums;
}

/// Limit positions and normals of the first `count` vertices of the last level through
/// PrimvarRefiner::Limit (which needs fullTopologyInLastLevel), face normals where its tangents
/// fail; the mesh's indices already added.
void primvar_limit(const Far::TopologyRefiner& refiner, const RefinedPoint* refined, std::size_t count, Mesh& mesh) {
  const auto all = static_cast<std::size_t>(refiner.GetLevel(refiner.GetMaxLevel()).GetNumVertices());
  const auto limit = std::make_unique_for_overwrite<RefinedPoint[]>(all);
  const auto du = std::make_unique_for_overwrite<RefinedPoint[]>(all);
  const auto dv = std::make_unique_for_overwrite<RefinedPoint[]>(all);
  RefinedPoint* positions = limit.get();
  RefinedPoint* tangents_u = du.get();
  RefinedPoint* tangents_v = dv.get();
  Far::PrimvarRefinerReal<double>(refiner).Limit(refined, positions, tangents_u, tangents_v);
  const std::vector<glm::dvec3> fallback = face_normal_sums(mesh, positions, count);
  mesh.positions.reserve(count);
  mesh.normals.reserve(count);
  for (std::size_t i = 0; i < count; ++i) {
    mesh.positions.emplace_back(limit[i].p);
    glm::dvec3 n = glm::cross(du[i].p, dv[i].p);
    const double scale = glm::length(du[i].p) * glm::length(dv[i].p);
    if (!(glm::length(n) > 1e-9 * scale) || glm::dot(n, fallback[i]) < 0.0) n = fallback[i];
    const double length = glm::length(n);
    mesh.normals.emplace_back(length > 0.0 ? n / length : glm::dvec3(0.0, 0.0, 1.0));
  }
}

}  // namespace

std::optional<CageProblem> check_cage(const Cage& cage) {
  // Per undirected edge: the face that used it each way (-1: none yet).
  struct Uses {
    int forward = -1;   // from the smaller index to the larger
    int backward = -1;  // the other way
  };
  std::unordered_map<std::uint64_t, Uses> edges;
  const auto count = static_cast<int>(cage.points.size());
  std::size_t corner = 0;
  for (std::size_t f = 0; f < cage.face_sizes.size(); ++f) {
    const int face = static_cast<int>(f);
    const std::string which = "face " + std::to_string(face + 1);
    const int n = cage.face_sizes[f];
    if (n < 3) return CageProblem{face, "expected at least 3 vertices in " + which + ", found " + std::to_string(n)};
    const int* v = cage.face_vertices.data() + corner;
    corner += static_cast<std::size_t>(n);
    for (int i = 0; i < n; ++i) {
      if (v[i] < 0 || v[i] >= count) {
        return CageProblem{face, "expected a vertex index from 0 to " + std::to_string(count - 1) + " in " + which +
                                     ", found " + std::to_string(v[i])};
      }
      if (std::find(v, v + i, v[i]) != v + i) {
        return CageProblem{
            face, "expected distinct vertices in " + which + ", found vertex " + std::to_string(v[i]) + " twice"};
      }
    }
    for (int i = 0; i < n; ++i) {
      const int a = v[i];
      const int b = v[(i + 1) % n];
      Uses& uses = edges[edge_key(a, b)];
      int& slot = a < b ? uses.forward : uses.backward;
      const int other = a < b ? uses.backward : uses.forward;
      const std::string edge = "edge " + std::to_string(a) + "-" + std::to_string(b);
      if (slot >= 0 && other >= 0) {
        return CageProblem{face, "expected a manifold cage, found " + edge + " in a third face, " +
                                     std::to_string(face + 1) + " (after faces " +
                                     std::to_string(std::min(slot, other) + 1) + " and " +
                                     std::to_string(std::max(slot, other) + 1) + ")"};
      }
      if (slot >= 0) {
        return CageProblem{face, "expected a manifold cage, found " + edge + " running the same way in faces " +
                                     std::to_string(slot + 1) + " and " + std::to_string(face + 1) +
                                     " (neighbouring faces must turn the same way)"};
      }
      slot = face;
    }
  }
  return std::nullopt;
}

CageCounts cage_counts(const Cage& cage) {
  std::unordered_map<std::uint64_t, char> edges;
  edges.reserve(cage.face_vertices.size());
  std::size_t corner = 0;
  for (const int n : cage.face_sizes) {
    const int* v = cage.face_vertices.data() + corner;
    for (int i = 0; i < n; ++i) edges.emplace(edge_key(v[i], v[(i + 1) % n]), 0);
    corner += static_cast<std::size_t>(n);
  }
  return {static_cast<std::int64_t>(cage.points.size()), static_cast<std::int64_t>(edges.size()),
          static_cast<std::int64_t>(cage.face_sizes.size())};
}

CageCounts refined_counts(const Cage& cage, int levels, SubdivisionScheme scheme) {
  CageCounts c = cage_counts(cage);
  std::int64_t corners = static_cast<std::int64_t>(cage.face_vertices.size());
  for (int level = 0; level < levels; ++level) {
    if (scheme == SubdivisionScheme::Loop) {
      c = {c.vertices + c.edges, 2 * c.edges + 3 * c.faces, 4 * c.faces};
    } else {
      c = {c.vertices + c.edges + c.faces, 2 * c.edges + corners, corners};
      corners = 4 * c.faces;
    }
  }
  return c;
}

Subdivided subdivide(const Cage& cage, const SubdivisionOptions& options) {
  SWEEP_EXPECTS(options.levels >= 0 && options.levels <= kMaxSubdivisionLevel, "levels in [0, kMaxSubdivisionLevel]");
  SWEEP_EXPECTS(options.scheme != SubdivisionScheme::Loop ||
                    std::all_of(cage.face_sizes.begin(), cage.face_sizes.end(), [](int n) { return n == 3; }),
                "Loop needs triangles only");
  SWEEP_EXPECTS(
      std::all_of(cage.face_sizes.begin(), cage.face_sizes.end(), [](int n) { return n >= 3; }) &&
          std::accumulate(cage.face_sizes.begin(), cage.face_sizes.end(), std::size_t{0}) == cage.face_vertices.size(),
      "check_cage passes: faces of at least 3 corners, as many corners as listed");
  SWEEP_EXPECTS(std::all_of(cage.face_vertices.begin(), cage.face_vertices.end(),
                            [&](int v) { return v >= 0 && static_cast<std::size_t>(v) < cage.points.size(); }),
                "check_cage passes: indices in range");
  // A grid surface collapsed to nothing (a profile on the axis) leaves no face: nothing to refine,
  // and Far would say so on stderr.
  if (cage.face_sizes.empty()) return {};
  // Catmull-Clark from level 1 on: each face's limit surface, on every core (subdivision_faces.hpp).
  if (std::optional<Subdivided> by_faces = subdivision_detail::subdivide_by_faces(
          cage, options, subdivision_detail::subdivision_threads(cage, options))) {
    return std::move(*by_faces);
  }
  return subdivision_detail::subdivide_by_refinement(cage, options);
}

namespace subdivision_detail {

std::unique_ptr<Far::TopologyRefiner> cage_refiner(const Cage& cage, const SubdivisionOptions& options) {
  Far::TopologyDescriptor desc;
  desc.numVertices = static_cast<int>(cage.points.size());
  desc.numFaces = static_cast<int>(cage.face_sizes.size());
  desc.numVertsPerFace = cage.face_sizes.data();
  desc.vertIndicesPerFace = cage.face_vertices.data();
  Sdc::Options sdc;
  sdc.SetVtxBoundaryInterpolation(options.smooth_boundary ? Sdc::Options::VTX_BOUNDARY_EDGE_ONLY
                                                          : Sdc::Options::VTX_BOUNDARY_EDGE_AND_CORNER);
  const Sdc::SchemeType type = options.scheme == SubdivisionScheme::Loop ? Sdc::SCHEME_LOOP : Sdc::SCHEME_CATMARK;
  using Factory = Far::TopologyRefinerFactory<Far::TopologyDescriptor>;
  return std::unique_ptr<Far::TopologyRefiner>(Factory::Create(desc, Factory::Options(type, sdc)));
}

Subdivided subdivide_by_refinement(const Cage& cage, const SubdivisionOptions& options) {
  Subdivided out;
  if (cage.face_sizes.empty()) return out;
  // Far's limit masks at a vertex assume quads around it (Catmull-Clark) or triangles (Loop).
  // Level 0 of a Catmull-Clark cage with other faces is therefore taken one level down: the
  // cage's vertices keep their indices in every level, and their limit is the same.
  const bool all_quads = std::all_of(cage.face_sizes.begin(), cage.face_sizes.end(), [](int n) { return n == 4; });
  const bool one_down = options.levels == 0 && options.scheme == SubdivisionScheme::CatmullClark && !all_quads;
  SubdivisionOptions refine = options;
  if (one_down) refine.levels = 1;
  const std::unique_ptr<Far::TopologyRefiner> refiner = cage_refiner(cage, refine);
  if (!refiner) return out;
  // Catmull-Clark refined at least once reads its limit from the level before the last, which
  // saves the last level's full topology (more than half of the refinement's time). One level
  // down keeps PrimvarRefiner::Limit: its mesh is the cage, not the last level.
  const bool from_parent = refine.levels > 0 && !one_down && catmark_limit_applies(*refiner);
  if (refine.levels > 0) {
    Far::TopologyRefiner::UniformOptions uniform(refine.levels);
    uniform.fullTopologyInLastLevel = !from_parent;  // PrimvarRefiner::Limit needs it
    refiner->RefineUniform(uniform);
  }
  const RefinedLevels refined = refined_points(*refiner, cage);
  const Far::TopologyLevel& last = refiner->GetLevel(one_down ? 0 : refiner->GetMaxLevel());
  out.counts = {last.GetNumVertices(), last.GetNumEdges(), last.GetNumFaces()};
  add_faces(last, out.mesh);
  if (from_parent) {
    catmark_limit(*refiner, refined.last, out.mesh);
  } else {
    primvar_limit(*refiner, refined.last, static_cast<std::size_t>(last.GetNumVertices()), out.mesh);
  }
  return out;
}

}  // namespace subdivision_detail

Cage grid_cage(const Mesh& mesh, bool quads) {
  Cage cage;
  cage.points.assign(mesh.positions.begin(), mesh.positions.end());
  std::vector<int> corners;  // before welding, the faces' corners
  const auto& t = mesh.indices;
  for (std::size_t i = 0; i + 2 < t.size();) {
    const bool pair = quads && i + 5 < t.size();
    if (pair && t[i + 3] == t[i + 1] && t[i + 5] == t[i + 2]) {  // add_quad natural: a b c, b d c
      cage.face_sizes.push_back(4);
      corners.insert(corners.end(), {int(t[i]), int(t[i + 1]), int(t[i + 4]), int(t[i + 2])});
      i += 6;
    } else if (pair && t[i + 3] == t[i + 2] && t[i + 4] == t[i + 1]) {  // flipped: a c b, b c d
      cage.face_sizes.push_back(4);
      corners.insert(corners.end(), {int(t[i]), int(t[i + 1]), int(t[i + 5]), int(t[i + 2])});
      i += 6;
    } else {
      cage.face_sizes.push_back(3);
      corners.insert(corners.end(), {int(t[i]), int(t[i + 1]), int(t[i + 2])});
      i += 3;
    }
  }
  cage.face_vertices = std::move(corners);
  return welded_cage(cage);
}

Cage welded_cage(const Cage& cage) {
  const std::vector<int>& corners = cage.face_vertices;
  // Weld, then renumber the distinct points and drop repeated corners.
  const std::vector<std::uint32_t> first =
      weld_points(cage.points, std::max(points_extent(cage.points) * 1e-9, 1e-300));
  std::vector<int> compact(cage.points.size(), -1);
  std::vector<glm::dvec3> points;
  for (std::size_t i = 0; i < cage.points.size(); ++i) {
    if (first[i] != i) continue;
    compact[i] = static_cast<int>(points.size());
    points.push_back(cage.points[i]);
  }
  Cage out;
  out.points = std::move(points);
  std::vector<int> face;
  std::size_t corner = 0;
  for (const int n : cage.face_sizes) {
    face.clear();
    for (int k = 0; k < n; ++k) {
      const int v = compact[first[static_cast<std::size_t>(corners[corner + static_cast<std::size_t>(k)])]];
      if (std::find(face.begin(), face.end(), v) == face.end()) face.push_back(v);
    }
    corner += static_cast<std::size_t>(n);
    if (face.size() < 3) continue;
    out.face_sizes.push_back(static_cast<int>(face.size()));
    out.face_vertices.insert(out.face_vertices.end(), face.begin(), face.end());
  }
  return out;
}

Mesh cage_mesh(const Cage& cage) {
  Mesh mesh;
  std::vector<glm::dvec3> normals(cage.points.size(), glm::dvec3(0.0));
  std::size_t corner = 0;
  for (const int n : cage.face_sizes) {
    const int* v = cage.face_vertices.data() + corner;
    corner += static_cast<std::size_t>(n);
    glm::dvec3 newell(0.0);  // twice the area times the unit normal, for any polygon
    for (int i = 0; i < n; ++i) {
      newell += glm::cross(cage.points[static_cast<std::size_t>(v[i])],
                           cage.points[static_cast<std::size_t>(v[(i + 1) % n])]);
    }
    mesh.polygon_sizes.push_back(static_cast<std::uint32_t>(n));
    for (int i = 0; i < n; ++i) {
      normals[static_cast<std::size_t>(v[i])] += newell;
      mesh.polygon_indices.push_back(static_cast<std::uint32_t>(v[i]));
      if (i >= 1 && i + 1 < n) {
        mesh.indices.insert(mesh.indices.end(), {static_cast<std::uint32_t>(v[0]), static_cast<std::uint32_t>(v[i]),
                                                 static_cast<std::uint32_t>(v[i + 1])});
      }
    }
  }
  mesh.positions.assign(cage.points.begin(), cage.points.end());
  mesh.normals.reserve(normals.size());
  for (const glm::dvec3& n : normals) {
    const double length = glm::length(n);
    mesh.normals.emplace_back(length > 0.0 ? n / length : glm::dvec3(0.0, 0.0, 1.0));
  }
  return mesh;
}

std::vector<glm::vec3> cage_edge_lines(const Cage& cage) {
  std::vector<glm::vec3> lines;
  std::unordered_map<std::uint64_t, char> seen;
  std::size_t corner = 0;
  for (const int n : cage.face_sizes) {
    const int* v = cage.face_vertices.data() + corner;
    corner += static_cast<std::size_t>(n);
    for (int i = 0; i < n; ++i) {
      const int a = v[i], b = v[(i + 1) % n];
      if (!seen.emplace(edge_key(a, b), 0).second) continue;
      lines.emplace_back(cage.points[static_cast<std::size_t>(a)]);
      lines.emplace_back(cage.points[static_cast<std::size_t>(b)]);
    }
  }
  return lines;
}

}  // namespace sweep
