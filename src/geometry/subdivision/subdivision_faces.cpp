// The Catmull-Clark limit of a uniform refinement, face by face. A vertex of refinement level L
// converges to the point of the limit surface at its parameters, which are dyadic (multiples of
// 2^-L on a quad of the cage, 2^-(L-1) on each quarter of another polygon), and a quad of level L
// is a cell of that grid. So nothing needs refining: the limit surface of each cage face
// (OpenSubdiv's Bfr, as its bfr_tutorial_1_1 evaluates it) is evaluated at the grid's points, and
// the faces are shared out among threads. Bfr refines around extraordinary vertices as deep as it
// is asked (L), so the grid's points are corners of its sub-patches, whose positions it gives
// exactly; only the tangent plane at an extraordinary point itself comes from an approximating
// (Gregory) patch, so the normal there is taken from Far's limit masks (extraordinary_normals).
// A regular face away from the boundary is the uniform bicubic B-spline of its 16 control points
// (Catmull and Clark 1978), evaluated here in closed form, by rows: most of the cage of a large
// smooth surface.
//
// The refined vertices and quads are numbered as Far's uniform refinement numbers them
// (subdivision_numbering.hpp). Each vertex is written by one face (a vertex or edge of the cage
// by its lowest-numbered face), so the result does not depend on how the faces were shared out.

#include "geometry/subdivision/subdivision_faces.hpp"

#include "geometry/subdivision/subdivision_limit.hpp"
#include "geometry/subdivision/subdivision_numbering.hpp"
#include "geometry/thread_pool.hpp"

#include <opensubdiv/bfr/refinerSurfaceFactory.h>
#include <opensubdiv/bfr/surface.h>
#include <opensubdiv/far/primvarRefiner.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

namespace sweep::subdivision_detail {
namespace {

using namespace OpenSubdiv;
using Far::ConstIndexArray;
using Far::Index;
using Factory = Bfr::RefinerSurfaceFactory<>;
using Surface = Bfr::Surface<double>;

static_assert(sizeof(glm::dvec3) == 3 * sizeof(double), "cage points are packed triples (Bfr reads them so)");

/// The uniform cubic B-spline's basis functions and derivatives at i / n, i = 0..n.
struct SplineBasis {
  std::vector<std::array<double, 4>> value, slope;

  explicit SplineBasis(int n) {
    for (int i = 0; i <= n; ++i) {
      const double t = static_cast<double>(i) / n, s = 1.0 - t;
      value.push_back({s * s * s / 6.0, (3.0 * t * t * t - 6.0 * t * t + 4.0) / 6.0,
                       (-3.0 * t * t * t + 3.0 * t * t + 3.0 * t + 1.0) / 6.0, t * t * t / 6.0});
      slope.push_back({-0.5 * s * s, 1.5 * t * t - 2.0 * t, -1.5 * t * t + t + 0.5, 0.5 * t * t});
    }
  }
};

/// What every face shares: the cage, its level-0 topology, the refinement's numbering.
struct Shared {
  const Cage& cage;
  const Far::TopologyLevel& base;
  Numbering numbering;
  std::unique_ptr<SplineBasis> quad_basis;  // at the 2^L grid of a regular quad
  // Unit limit normals at the extraordinary points (zero elsewhere): per cage vertex, and per
  // cage face for the centre of one that is not a quad (extraordinary_normals).
  std::vector<glm::dvec3> vertex_normals, face_normals;
  Mesh* mesh = nullptr;
  std::atomic<bool> give_up{false};

  Shared(const Cage& c, const Far::TopologyLevel& level0) : cage(c), base(level0) {}
};

/// Whether subdivide_by_faces evaluates the cage of `refiner`: as catmark_limit_applies (manifold,
/// no semi-sharp creases), but points in no face are allowed (they stay where they are).
bool faces_apply(const Far::TopologyRefiner& refiner) {
  if (refiner.GetSchemeType() != Sdc::SCHEME_CATMARK) return false;
  const Far::TopologyLevel& cage = refiner.GetLevel(0);
  for (Index e = 0; e < cage.GetNumEdges(); ++e) {
    if (cage.IsEdgeNonManifold(e) || cage.IsEdgeSemiSharp(e)) return false;
  }
  for (Index v = 0; v < cage.GetNumVertices(); ++v) {
    if (cage.IsVertexSemiSharp(v) || (cage.IsVertexNonManifold(v) && cage.GetVertexFaces(v).size() > 0)) return false;
  }
  return true;
}

/// Whether the limit surface is a B-spline patch at cage vertex v for Bfr (a regular vertex:
/// only quads around it, four of them inside, three along a boundary, a corner's one), so that
/// its tangents there are exact.
bool regular_vertex(const Far::TopologyLevel& base, Index v) {
  const ConstIndexArray faces = base.GetVertexFaces(v);
  if (std::any_of(faces.begin(), faces.end(), [&](Index f) { return base.GetFaceVertices(f).size() != 4; })) {
    return false;
  }
  const int edges = base.GetVertexEdges(v).size();
  switch (base.GetVertexRule(v)) {
    case Sdc::Crease::RULE_SMOOTH:
      return edges == 4 && !base.IsVertexBoundary(v);
    case Sdc::Crease::RULE_CREASE:
      return edges == 3 && base.IsVertexBoundary(v);
    case Sdc::Crease::RULE_CORNER:
      return edges == 2 && base.IsVertexBoundary(v);
    case Sdc::Crease::RULE_DART:
    case Sdc::Crease::RULE_UNKNOWN:
      return false;
  }
  return false;
}

/// The unit limit normals at the extraordinary points, where Bfr's Gregory patches only
/// approximate the tangent plane (by some 1e-2 at level 1): the children of the irregular cage
/// vertices and of the faces that are not quads, which are extraordinary from level 1 on, and
/// whose tangent plane is the same at every level. From Far's limit masks at level 1
/// (PrimvarRefiner::Limit, as subdivide_by_refinement applies them at the last level); false
/// where those tangents are nearly parallel (its fallback's case).
bool extraordinary_normals(const Cage& cage, const SubdivisionOptions& options, Shared& shared) {
  const Far::TopologyLevel& base = shared.base;
  std::vector<Index> vertices, faces;
  for (Index v = 0; v < base.GetNumVertices(); ++v) {
    if (base.GetVertexFaces(v).size() > 0 && !regular_vertex(base, v)) vertices.push_back(v);
  }
  for (Index f = 0; f < base.GetNumFaces(); ++f) {
    if (base.GetFaceVertices(f).size() != 4) faces.push_back(f);
  }
  if (vertices.empty() && faces.empty()) return true;
  const std::unique_ptr<Far::TopologyRefiner> refiner = cage_refiner(cage, options);
  if (!refiner) return false;
  Far::TopologyRefiner::UniformOptions uniform(1);
  uniform.fullTopologyInLastLevel = true;  // PrimvarRefiner::Limit needs it
  refiner->RefineUniform(uniform);
  const auto count = static_cast<std::size_t>(refiner->GetLevel(1).GetNumVertices());
  std::vector<RefinedPoint> refined(count), limit(count), du(count), dv(count);
  std::vector<RefinedPoint> points(cage.points.size());
  for (std::size_t i = 0; i < cage.points.size(); ++i) points[i].p = cage.points[i];
  const Far::PrimvarRefinerReal<double> primvar(*refiner);
  const RefinedPoint* cage_level = points.data();
  RefinedPoint* level1 = refined.data();
  primvar.Interpolate(1, cage_level, level1);
  RefinedPoint *positions = limit.data(), *tangents_u = du.data(), *tangents_v = dv.data();
  primvar.Limit(refined.data(), positions, tangents_u, tangents_v);
  const auto normal_at = [&](std::size_t k, glm::dvec3& out) {
    const glm::dvec3 n = glm::cross(du[k].p, dv[k].p);
    const double squared = glm::dot(n, n);
    if (!(squared > 1e-12 * glm::dot(du[k].p, du[k].p) * glm::dot(dv[k].p, dv[k].p))) return false;
    out = n / std::sqrt(squared);
    return true;
  };
  shared.vertex_normals.assign(static_cast<std::size_t>(base.GetNumVertices()), glm::dvec3(0.0));
  shared.face_normals.assign(static_cast<std::size_t>(base.GetNumFaces()), glm::dvec3(0.0));
  // Level 1 keeps the cage's vertices' indices; the faces' children follow them.
  for (const Index v : vertices) {
    if (!normal_at(static_cast<std::size_t>(v), shared.vertex_normals[static_cast<std::size_t>(v)])) return false;
  }
  for (const Index f : faces) {
    const auto k = static_cast<std::size_t>(base.GetNumVertices() + f);
    if (!normal_at(k, shared.face_normals[static_cast<std::size_t>(f)])) return false;
  }
  return true;
}

/// One thread's factory and scratch.
class Worker {
 public:
  Worker(const Far::TopologyRefiner& refiner, const Shared& shared)
      : factory_(refiner, Factory::Options()
                              .SetApproxLevelSmooth(std::max(shared.numbering.levels, 2))
                              .SetApproxLevelSharp(std::max(shared.numbering.levels, 6))),
        shared_(shared) {}

  /// Evaluates cage face f into the mesh; false if it gives up.
  bool face(Index f) {
    const Far::TopologyLevel& base = shared_.base;
    if (!factory_.InitVertexSurface(f, &surface_)) return false;
    const ConstIndexArray corners = base.GetFaceVertices(f);
    const ConstIndexArray edges = base.GetFaceEdges(f);
    const int n = corners.size();
    edges_.resize(static_cast<std::size_t>(n));
    corners_.resize(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      corners_[static_cast<std::size_t>(i)] = static_cast<std::uint32_t>(corners[i]);
      edges_[static_cast<std::size_t>(i)] = {static_cast<std::uint32_t>(edges[i]),
                                             base.GetEdgeVertices(edges[i])[0] == corners[i]};
    }
    const Numbering& numbering = shared_.numbering;
    std::uint32_t* indices = shared_.mesh->indices.data();
    const bool regular = n == 4 && surface_.IsRegular() && std::none_of(corners.begin(), corners.end(), [&](Index v) {
                           return base.IsVertexBoundary(v);
                         });
    if (!regular) {
      patch_points_.resize(static_cast<std::size_t>(3 * surface_.GetNumPatchPoints()));
      surface_.PreparePatchPoints(&shared_.cage.points[0].x, Surface::PointDescriptor(3), patch_points_.data(),
                                  Surface::PointDescriptor(3));
    }
    const auto face = static_cast<std::uint32_t>(f);
    if (n == 4) {  // one grid; the children turn as Far turns a quad's
      grid_.resize(1 << numbering.levels);
      const Quad quad = cage_quad(face, {corners_[0], corners_[1], corners_[2], corners_[3]},
                                  {edges_[0], edges_[1], edges_[2], edges_[3]}, grid_.size);
      number(numbering, quad, 0, numbering.face_offsets[face], indices, grid_);
      if (regular) {
        evaluate_regular();
      } else {
        evaluate_irregular(-1);
      }
      return store(f, -1, corners, edges);
    }
    // Another polygon: a grid per child quad (Bfr's sub-face at corner j), each numbered and
    // evaluated in turn.
    for (int j = 0; j < n; ++j) {
      grid_.resize(1 << (numbering.levels - 1));
      const Quad quad = polygon_child(numbering, face, corners_.data(), edges_.data(), n, j, grid_.size);
      number(numbering, quad, 1, 4 * quad.face, indices, grid_);
      evaluate_irregular(j);
      if (!store(f, j, corners, edges)) return false;
    }
    return true;
  }

 private:
  /// The regular face's bicubic B-spline (control point 4 r + c at row r along v, column c
  /// along u, the face's corner 0 at point 5), by rows: each of the 4 rows at every u first.
  void evaluate_regular() {
    std::array<Index, 16> indices{};
    surface_.GetControlPointIndices(indices.data());
    const SplineBasis& basis = *shared_.quad_basis;
    const int n = grid_.size;
    const auto count = static_cast<std::size_t>(n + 1);
    rows_.resize(4 * count);
    row_slopes_.resize(4 * count);
    for (std::size_t r = 0; r < 4; ++r) {
      const glm::dvec3& c0 = shared_.cage.points[static_cast<std::size_t>(indices[4 * r])];
      const glm::dvec3& c1 = shared_.cage.points[static_cast<std::size_t>(indices[4 * r + 1])];
      const glm::dvec3& c2 = shared_.cage.points[static_cast<std::size_t>(indices[4 * r + 2])];
      const glm::dvec3& c3 = shared_.cage.points[static_cast<std::size_t>(indices[4 * r + 3])];
      for (std::size_t a = 0; a < count; ++a) {
        const std::array<double, 4>& w = basis.value[a];
        const std::array<double, 4>& d = basis.slope[a];
        rows_[r * count + a] = (w[0] * c0 + w[1] * c1) + (w[2] * c2 + w[3] * c3);
        row_slopes_[r * count + a] = (d[0] * c0 + d[1] * c1) + (d[2] * c2 + d[3] * c3);
      }
    }
    for (std::size_t a = 0; a < count; ++a) {
      const glm::dvec3 &r0 = rows_[a], &r1 = rows_[count + a], &r2 = rows_[2 * count + a], &r3 = rows_[3 * count + a];
      const glm::dvec3 &s0 = row_slopes_[a], &s1 = row_slopes_[count + a], &s2 = row_slopes_[2 * count + a],
                       &s3 = row_slopes_[3 * count + a];
      for (std::size_t b = 0; b < count; ++b) {
        const std::array<double, 4>& w = basis.value[b];
        const std::array<double, 4>& d = basis.slope[b];
        const std::size_t k = a * count + b;
        grid_.position[k] = (w[0] * r0 + w[1] * r1) + (w[2] * r2 + w[3] * r3);
        grid_.du[k] = (w[0] * s0 + w[1] * s1) + (w[2] * s2 + w[3] * s3);
        grid_.dv[k] = (d[0] * r0 + d[1] * r1) + (d[2] * r2 + d[3] * r3);
      }
    }
  }

  /// Bfr's evaluation at every grid point: of the face (sub_face -1), or of its sub-face at
  /// corner sub_face, whose normalized (0, 0), (1, 0), (1, 1), (0, 1) are corner j, edge j's
  /// midpoint, the centre and edge j - 1's midpoint.
  void evaluate_irregular(int sub_face) {
    const Bfr::Parameterization parameterization = surface_.GetParameterization();
    const int n = grid_.size;
    for (int a = 0; a <= n; ++a) {
      for (int b = 0; b <= n; ++b) {
        const double local[2] = {static_cast<double>(a) / n, static_cast<double>(b) / n};
        double uv[2] = {local[0], local[1]};
        if (sub_face >= 0) parameterization.ConvertNormalizedSubFaceToCoord(sub_face, local, uv);
        const std::size_t k = grid_.at(a, b);
        surface_.Evaluate(uv, patch_points_.data(), Surface::PointDescriptor(3), &grid_.position[k].x, &grid_.du[k].x,
                          &grid_.dv[k].x);
      }
    }
  }

  /// Whether this face writes its grid point (a, b): points inside the face always; on a cage
  /// edge or at a cage vertex, the lowest-numbered face there does. A polygon's sub-face j
  /// leaves its row b = size (edge j - 1's midpoint to the centre) to sub-face j - 1, whose column
  /// a = size it is, except the centre, which sub-face 0 writes.
  bool owns(Index f, int sub_face, int a, int b, const ConstIndexArray& corners, const ConstIndexArray& edges) const {
    const int n = grid_.size;
    const auto lowest = [f](const ConstIndexArray& faces) {
      return *std::min_element(faces.begin(), faces.end()) == f;
    };
    const auto owns_vertex = [&](int corner) { return lowest(shared_.base.GetVertexFaces(corners[corner])); };
    const auto owns_edge = [&](int side) { return lowest(shared_.base.GetEdgeFaces(edges[side])); };
    if (sub_face < 0) {
      const bool low_a = a == 0, high_a = a == n, low_b = b == 0, high_b = b == n;
      if (low_b) return low_a ? owns_vertex(0) : high_a ? owns_vertex(1) : owns_edge(0);
      if (high_b) return low_a ? owns_vertex(3) : high_a ? owns_vertex(2) : owns_edge(2);
      if (low_a) return owns_edge(3);
      if (high_a) return owns_edge(1);
      return true;
    }
    const int sides = corners.size();
    if (b == n) return a == n && sub_face == 0;
    if (b == 0) return a == 0 ? owns_vertex(sub_face) : owns_edge(sub_face);
    if (a == 0) return owns_edge((sub_face + sides - 1) % sides);
    return true;
  }

  /// The normal extraordinary_normals found for grid point (a, b), if it is an extraordinary
  /// point (a corner of the grid at an irregular cage vertex, or a polygon's centre); else zero.
  glm::dvec3 extraordinary_normal(Index f, int sub_face, int a, int b, const ConstIndexArray& corners) const {
    if (shared_.vertex_normals.empty()) return glm::dvec3(0.0);
    const int n = grid_.size;
    int corner = -1;
    if (sub_face >= 0) {
      if (a == n && b == n) return shared_.face_normals[static_cast<std::size_t>(f)];
      if (a == 0 && b == 0) corner = sub_face;
    } else if (b == 0 && (a == 0 || a == n)) {
      corner = a == 0 ? 0 : 1;
    } else if (b == n && (a == 0 || a == n)) {
      corner = a == 0 ? 3 : 2;
    }
    return corner < 0 ? glm::dvec3(0.0) : shared_.vertex_normals[static_cast<std::size_t>(corners[corner])];
  }

  /// Writes the grid's points this face owns into the mesh: float positions, unit normals
  /// du x dv; false (nothing decided here) where the tangents are nearly parallel or their
  /// normal is against the grid's quads around the point.
  bool store(Index f, int sub_face, const ConstIndexArray& corners, const ConstIndexArray& edges) {
    const int n = grid_.size;
    for (int a = 0; a < n; ++a) {
      for (int b = 0; b < n; ++b) {
        grid_.cells[static_cast<std::size_t>(a * n + b)] =
            glm::cross(grid_.position[grid_.at(a + 1, b + 1)] - grid_.position[grid_.at(a, b)],
                       grid_.position[grid_.at(a, b + 1)] - grid_.position[grid_.at(a + 1, b)]);
      }
    }
    Mesh& mesh = *shared_.mesh;
    for (int a = 0; a <= n; ++a) {
      for (int b = 0; b <= n; ++b) {
        if ((a == 0 || a == n || b == 0 || b == n) && !owns(f, sub_face, a, b, corners, edges)) continue;
        const std::size_t k = grid_.at(a, b);
        glm::dvec3 normal = extraordinary_normal(f, sub_face, a, b, corners);
        if (normal == glm::dvec3(0.0)) {
          const glm::dvec3& du = grid_.du[k];
          const glm::dvec3& dv = grid_.dv[k];
          normal = glm::cross(du, dv);
          const double squared = glm::dot(normal, normal);
          if (!(squared > 1e-12 * glm::dot(du, du) * glm::dot(dv, dv))) return false;
          normal /= std::sqrt(squared);
        }
        glm::dvec3 quads(0.0);
        for (int ca = std::max(a - 1, 0); ca < std::min(a + 1, n); ++ca) {
          for (int cb = std::max(b - 1, 0); cb < std::min(b + 1, n); ++cb) {
            quads += grid_.cells[static_cast<std::size_t>(ca * n + cb)];
          }
        }
        if (!(glm::dot(normal, quads) > 0.0)) return false;
        const std::uint32_t v = grid_.vertex[k];
        mesh.positions[v] = glm::vec3(grid_.position[k]);
        mesh.normals[v] = glm::vec3(normal);
      }
    }
    return true;
  }

  Factory factory_;
  const Shared& shared_;
  Surface surface_;
  std::vector<double> patch_points_;
  std::vector<std::uint32_t> corners_;  // the face's, from its corner 0
  std::vector<EdgeRef> edges_;          // the face's, from its corner 0
  std::vector<glm::dvec3> rows_, row_slopes_;
  Grid grid_;
};

}  // namespace

int subdivision_threads(const Cage& cage, const SubdivisionOptions& options) {
  if (options.scheme != SubdivisionScheme::CatmullClark || options.levels < 1) return 1;
  // About 5 microseconds of work per 64 refined quads (a cage quad at level 3) against some 50
  // to start a thread: threads from 8192 refined quads on.
  const std::int64_t quads = static_cast<std::int64_t>(cage.face_vertices.size()) << (2 * (options.levels - 1));
  return quads >= 8192 ? worker_count() : 1;
}

std::optional<Subdivided> subdivide_by_faces(const Cage& cage, const SubdivisionOptions& options, int threads) {
  if (options.scheme != SubdivisionScheme::CatmullClark || options.levels < 1 || cage.face_sizes.empty()) {
    return std::nullopt;
  }
  const std::unique_ptr<Far::TopologyRefiner> refiner = cage_refiner(cage, options);
  if (!refiner || !faces_apply(*refiner)) return std::nullopt;
  const Far::TopologyLevel& base = refiner->GetLevel(0);
  Shared shared(cage, base);
  shared.numbering = number_levels(base.GetNumVertices(), base.GetNumEdges(), cage.face_sizes, options.levels);
  const std::int64_t vertices = shared.numbering.vertices, faces = shared.numbering.faces;
  if (vertices >= (std::int64_t{1} << 32) || 6 * faces >= (std::int64_t{1} << 32)) {
    return std::nullopt;  // 32-bit indices: far past the caps (limits.hpp)
  }
  shared.quad_basis = std::make_unique<SplineBasis>(1 << options.levels);
  if (!extraordinary_normals(cage, options, shared)) return std::nullopt;

  Subdivided out;
  out.counts = {vertices, shared.numbering.edges, faces};
  out.mesh.positions.resize(static_cast<std::size_t>(vertices));
  out.mesh.normals.resize(static_cast<std::size_t>(vertices));
  out.mesh.indices.resize(6 * static_cast<std::size_t>(faces));
  shared.mesh = &out.mesh;
  // A cage point in no face stays where it is, its normal +z (as subdivide_by_refinement's).
  for (Index v = 0; v < base.GetNumVertices(); ++v) {
    if (base.GetVertexFaces(v).size() > 0) continue;
    out.mesh.positions[static_cast<std::size_t>(v)] = glm::vec3(cage.points[static_cast<std::size_t>(v)]);
    out.mesh.normals[static_cast<std::size_t>(v)] = glm::vec3(0.0f, 0.0f, 1.0f);
  }

  const auto face_count = static_cast<std::size_t>(base.GetNumFaces());
  threads = std::max(threads, 1);
  // Chunks of about 4096 refined quads, several per thread, handed out as threads come free.
  const std::size_t per_face = static_cast<std::size_t>(faces) / face_count + 1;
  const std::size_t chunk =
      std::clamp<std::size_t>(4096 / per_face, 1, face_count / static_cast<std::size_t>(threads) + 1);
  std::vector<std::unique_ptr<Worker>> workers(static_cast<std::size_t>(threads));
  parallel_chunks(face_count, chunk, threads, [&](std::size_t begin, std::size_t end, int worker_index) {
    std::unique_ptr<Worker>& worker = workers[static_cast<std::size_t>(worker_index)];
    if (!worker) worker = std::make_unique<Worker>(*refiner, shared);
    for (std::size_t f = begin; f < end && !shared.give_up.load(std::memory_order_relaxed); ++f) {
      if (!worker->face(static_cast<Index>(f))) shared.give_up = true;
    }
  });
  if (shared.give_up) return std::nullopt;
  return out;
}

}  // namespace sweep::subdivision_detail
