// The limit of a uniform Catmull-Clark refinement's last level, read from the level before it.
// Every vertex of the last level is the child of a face, an edge or a vertex of the level before,
// and its ring (the vertices across its edges and opposite it in its quads) is made of the
// children of that component's neighbours, which the level before knows (it has full topology).
// The masks are OpenSubdiv's own (Sdc::Scheme::ComputeVertexLimitMask, as PrimvarRefiner::Limit
// applies them; Halstead et al. 1993, Biermann et al. 2000 at boundaries), so the result is the
// same, without the last level's edges and vertex-face relations, which cost more than all the
// rest of the refinement.
#include "geometry/subdivision/subdivision_limit.hpp"

#include "base/precondition.hpp"

#include <opensubdiv/far/topologyLevel.h>
#include <opensubdiv/sdc/catmarkScheme.h>
#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace sweep::subdivision_detail {
namespace {

using namespace OpenSubdiv;
using Far::ConstIndexArray;
using Far::Index;
using Rule = Sdc::Crease::Rule;

/// A vertex of the last level with its ring, in the order PrimvarRefiner::Limit reads rings:
/// counterclockwise, edge i the leading edge of quad i (quad i between edges i and i+1), and at a
/// boundary, edges 0 and `edges - 1` on the boundary.
struct Ring {
  Index center = 0;
  Rule rule = Rule::RULE_SMOOTH;
  int edges = 0;
  int faces = 0;
  std::vector<Index> across;     // per edge: the vertex at its other end
  std::vector<Index> opposite;   // per quad: its corner opposite the center
  std::vector<float> sharpness;  // per edge (infinite on a boundary)

  void reset(Index vertex, Rule vertex_rule, int edge_count, int face_count) {
    center = vertex;
    rule = vertex_rule;
    edges = edge_count;
    faces = face_count;
    const auto size = static_cast<std::size_t>(std::max(edges, faces));
    if (across.size() < size) {  // grows to the largest valence once, then is reused
      across.resize(size);
      opposite.resize(size);
      sharpness.resize(size);
    }
    std::fill_n(sharpness.begin(), edges, 0.0f);
  }
};

/// Where the vertex of a ring comes from: the child of a face, an edge or a vertex of the level
/// before the last.
enum class Parent : unsigned char { Face, Edge, Vertex };

/// The ring of the child of `parent`'s face f. Child quad k of f is (child of corner k, child of
/// edge k, center, child of edge k - 1), so around the center: edge k - 1's child, quad k with
/// corner k's child opposite, edge k's child.
void face_child_ring(const Far::TopologyLevel& parent, Index f, Ring& ring) {
  const ConstIndexArray corners = parent.GetFaceVertices(f);
  const ConstIndexArray edges = parent.GetFaceEdges(f);
  const int n = corners.size();
  ring.reset(parent.GetFaceChildVertex(f), Rule::RULE_SMOOTH, n, n);
  for (int k = 0; k < n; ++k) {
    ring.across[k] = parent.GetEdgeChildVertex(edges[(k + n - 1) % n]);
    ring.opposite[k] = parent.GetVertexChildVertex(corners[k]);
  }
}

/// The ring of the child of `parent`'s edge e. In a face where e is edge k (corner k to k + 1),
/// around the center: corner k + 1's child, quad k + 1 (edge k + 1's child opposite), the face's
/// child, quad k (edge k - 1's child opposite), corner k's child; the next face (an interior
/// edge) runs e the other way and closes the ring.
void edge_child_ring(const Far::TopologyLevel& parent, Index e, Ring& ring) {
  const ConstIndexArray faces = parent.GetEdgeFaces(e);
  const Far::ConstLocalIndexArray in_face = parent.GetEdgeFaceLocalIndices(e);
  const bool boundary = faces.size() == 1;
  ring.reset(parent.GetEdgeChildVertex(e), boundary ? Rule::RULE_CREASE : Rule::RULE_SMOOTH, boundary ? 3 : 4,
             faces.size() * 2);
  for (int i = 0; i < faces.size(); ++i) {
    const ConstIndexArray corners = parent.GetFaceVertices(faces[i]);
    const ConstIndexArray edges = parent.GetFaceEdges(faces[i]);
    const int n = corners.size();
    const int k = in_face[i];
    const int next = (k + 1) % n;
    ring.across[2 * i] = parent.GetVertexChildVertex(corners[next]);
    ring.across[2 * i + 1] = parent.GetFaceChildVertex(faces[i]);
    ring.opposite[2 * i] = parent.GetEdgeChildVertex(edges[next]);
    ring.opposite[2 * i + 1] = parent.GetEdgeChildVertex(edges[(k + n - 1) % n]);
    if (boundary) ring.across[2] = parent.GetVertexChildVertex(corners[k]);
  }
  if (boundary) ring.sharpness[0] = ring.sharpness[2] = parent.GetEdgeSharpness(e);
}

/// The ring of the child of `parent`'s vertex v: the children of v's edges and faces, in v's
/// order (a face's child is opposite v's child in the child quad at v), with v's rule (without
/// semi-sharp creases the rule stays from level to level).
void vertex_child_ring(const Far::TopologyLevel& parent, Index v, Ring& ring) {
  const ConstIndexArray edges = parent.GetVertexEdges(v);
  const ConstIndexArray faces = parent.GetVertexFaces(v);
  ring.reset(parent.GetVertexChildVertex(v), parent.GetVertexRule(v), edges.size(), faces.size());
  for (int i = 0; i < edges.size(); ++i) {
    ring.across[i] = parent.GetEdgeChildVertex(edges[i]);
    ring.sharpness[i] = parent.GetEdgeSharpness(edges[i]);
  }
  for (int i = 0; i < faces.size(); ++i) ring.opposite[i] = parent.GetFaceChildVertex(faces[i]);
}

using RingOf = void (*)(const Far::TopologyLevel&, Index, Ring&);

RingOf ring_of(Parent kind) {
  switch (kind) {
    case Parent::Face:
      return face_child_ring;
    case Parent::Edge:
      return edge_child_ring;
    case Parent::Vertex:
      return vertex_child_ring;
  }
  return vertex_child_ring;
}

/// What Sdc::Scheme's limit masks ask of a vertex.
class RingVertex {
 public:
  explicit RingVertex(const Ring& ring) : ring_(ring) {}
  int GetNumEdges() const { return ring_.edges; }
  int GetNumFaces() const { return ring_.faces; }
  float* GetSharpnessPerEdge(float* out) const {
    std::copy_n(ring_.sharpness.begin(), ring_.edges, out);
    return out;
  }

 private:
  const Ring& ring_;
};

/// A limit mask as Sdc::Scheme writes it: weights of the center, of the vertices across its edges
/// and of those opposite it in its quads.
class Mask {
 public:
  using Weight = double;

  int GetNumVertexWeights() const { return 1; }
  int GetNumEdgeWeights() const { return edge_count_; }
  int GetNumFaceWeights() const { return face_count_; }
  void SetNumVertexWeights(int) {}
  void SetNumEdgeWeights(int count) { edge_count_ = grow(edge_, count); }
  void SetNumFaceWeights(int count) { face_count_ = grow(face_, count); }
  Weight& VertexWeight(int) { return vertex_; }
  Weight& EdgeWeight(int i) { return edge_[static_cast<std::size_t>(i)]; }
  Weight& FaceWeight(int i) { return face_[static_cast<std::size_t>(i)]; }
  Weight VertexWeight(int) const { return vertex_; }
  Weight EdgeWeight(int i) const { return edge_[static_cast<std::size_t>(i)]; }
  Weight FaceWeight(int i) const { return face_[static_cast<std::size_t>(i)]; }
  // Limit masks weigh the opposite corners, not face centres (PrimvarRefiner::Limit ignores it).
  bool AreFaceWeightsForFaceCenters() const { return false; }
  void SetFaceWeightsForFaceCenters(bool) {}

  /// The weighted sum over a ring, smaller weights first (faces, edges, center) as
  /// PrimvarRefiner::Limit sums them, for the same rounding.
  glm::dvec3 apply(const Ring& ring, const RefinedPoint* points) const {
    glm::dvec3 sum(0.0);
    for (int i = 0; i < face_count_; ++i) sum += face_[i] * points[ring.opposite[i]].p;
    for (int i = 0; i < edge_count_; ++i) sum += edge_[i] * points[ring.across[i]].p;
    return sum + vertex_ * points[ring.center].p;
  }

 private:
  static int grow(std::vector<Weight>& weights, int count) {
    if (weights.size() < static_cast<std::size_t>(count)) weights.resize(static_cast<std::size_t>(count));
    return count;
  }

  Weight vertex_ = 0.0;
  std::vector<Weight> edge_, face_;
  int edge_count_ = 0, face_count_ = 0;
};

/// Position and tangents at the center of a ring, and twice the area vector of its quads (the
/// refined surface's orientation there).
struct LimitFrame {
  glm::dvec3 position, du, dv, quads;
};

/// The limit of a regular vertex (smooth, four quads; in a cage refined a few times nearly every
/// vertex is one) in closed form: Sdc's valence-4 masks (catmarkScheme.h), the uniform bicubic
/// B-spline's, position 4/9 center + 1/9 each edge + 1/36 each quad; tangents 4 (e0 - e2) +
/// f0 - f1 - f2 + f3 and its quarter turn 4 (e1 - e3) + f0 + f1 - f2 - f3. Summed in pairs rather
/// than mask entry by entry, which multiplies by the masks' zeros and chains every addition.
LimitFrame regular_limit(const Ring& ring, const RefinedPoint* points) {
  const auto at = [points](Index v) -> const glm::dvec3& { return points[v].p; };
  const glm::dvec3& c = at(ring.center);
  const glm::dvec3 &e0 = at(ring.across[0]), &e1 = at(ring.across[1]), &e2 = at(ring.across[2]),
                   &e3 = at(ring.across[3]);
  const glm::dvec3 &f0 = at(ring.opposite[0]), &f1 = at(ring.opposite[1]), &f2 = at(ring.opposite[2]),
                   &f3 = at(ring.opposite[3]);
  const glm::dvec3 f02 = f0 - f2, f13 = f1 - f3;
  LimitFrame out;
  out.position = (4.0 / 9.0) * c + (1.0 / 9.0) * ((e0 + e2) + (e1 + e3)) + (1.0 / 36.0) * ((f0 + f2) + (f1 + f3));
  out.du = 4.0 * (e0 - e2) + (f02 - f13);
  out.dv = 4.0 * (e1 - e3) + (f02 + f13);
  out.quads = (glm::cross(f0 - c, e1 - e0) + glm::cross(f1 - c, e2 - e1)) +
              (glm::cross(f2 - c, e3 - e2) + glm::cross(f3 - c, e0 - e3));
  return out;
}

/// Twice the area vector of a ring's quads (each quad's diagonals crossed), from `at(vertex)`.
template <class Position>
glm::dvec3 quads_normal(const Ring& ring, Position at) {
  const glm::dvec3 center = at(ring.center);
  glm::dvec3 sum(0.0);
  for (int i = 0; i < ring.faces; ++i) {
    const Index next = ring.across[i + 1 < ring.edges ? i + 1 : 0];
    sum += glm::cross(at(ring.opposite[i]) - center, at(next) - at(ring.across[i]));
  }
  return sum;
}

/// Evaluates the limit at the centers of rings into a mesh.
class Limiter {
 public:
  Limiter(const Far::TopologyRefiner& refiner, const RefinedPoint* refined, Mesh& mesh)
      : scheme_(refiner.GetSchemeOptions()), refined_(refined), mesh_(mesh) {}

  /// Stores the limit position and normal at ring.center; false if the normal is left to
  /// store_fallback (the tangents parallel, or their normal against the refined quads').
  bool store(const Ring& ring) {
    const LimitFrame limit = ring.rule == Rule::RULE_SMOOTH && ring.edges == 4 && ring.faces == 4
                                 ? regular_limit(ring, refined_)
                                 : irregular_limit(ring);
    const auto at = static_cast<std::size_t>(ring.center);
    mesh_.positions[at] = glm::vec3(limit.position);
    const glm::dvec3 n = glm::cross(limit.du, limit.dv);
    const double squared = glm::dot(n, n);  // squares compared: no square roots for the test
    if (!(squared > 1e-18 * glm::dot(limit.du, limit.du) * glm::dot(limit.dv, limit.dv))) return false;
    if (glm::dot(n, limit.quads) < 0.0) return false;
    mesh_.normals[at] = glm::vec3(n / std::sqrt(squared));
    return true;
  }

  /// The normal at ring.center from its quads on the limit surface (every position stored).
  void store_fallback(const Ring& ring) {
    const glm::dvec3 n = quads_normal(ring, [this](Index v) { return glm::dvec3(mesh_.positions[v]); });
    const double length = glm::length(n);
    mesh_.normals[static_cast<std::size_t>(ring.center)] = length > 0.0 ? glm::vec3(n / length) : glm::vec3(0, 0, 1);
  }

 private:
  LimitFrame irregular_limit(const Ring& ring) {
    LimitFrame out;
    out.quads = quads_normal(ring, [this](Index v) { return refined_[v].p; });
    if (ring.edges == 0) {  // a cage point in no face stays where it is (as in Far)
      out.position = refined_[ring.center].p;
      out.du = out.dv = glm::dvec3(0.0);
      return out;
    }
    scheme_.ComputeVertexLimitMask(RingVertex(ring), masks_[0], masks_[1], masks_[2], ring.rule);
    out.position = masks_[0].apply(ring, refined_);
    out.du = masks_[1].apply(ring, refined_);
    out.dv = masks_[2].apply(ring, refined_);
    return out;
  }

  Sdc::Scheme<Sdc::SCHEME_CATMARK> scheme_;
  std::array<Mask, 3> masks_;  // position, tangent u, tangent v: scratch for irregular rings
  const RefinedPoint* refined_;
  Mesh& mesh_;
};

}  // namespace

bool catmark_limit_applies(const Far::TopologyRefiner& refiner) {
  if (refiner.GetSchemeType() != Sdc::SCHEME_CATMARK) return false;
  // Non-manifold and semi-sharp features stay so in every level: the cage tells.
  const Far::TopologyLevel& cage = refiner.GetLevel(0);
  for (Index e = 0; e < cage.GetNumEdges(); ++e) {
    if (cage.IsEdgeNonManifold(e) || cage.IsEdgeSemiSharp(e)) return false;
  }
  for (Index v = 0; v < cage.GetNumVertices(); ++v) {
    if (cage.IsVertexNonManifold(v) || cage.IsVertexSemiSharp(v)) return false;
  }
  return true;
}

void catmark_limit(const Far::TopologyRefiner& refiner, const RefinedPoint* refined, Mesh& mesh) {
  SWEEP_EXPECTS(catmark_limit_applies(refiner), "catmark_limit_applies(refiner)");
  SWEEP_EXPECTS(refiner.IsUniform() && refiner.GetMaxLevel() >= 1, "refined uniformly at least once");
  const Far::TopologyLevel& parent = refiner.GetLevel(refiner.GetMaxLevel() - 1);
  const auto count = static_cast<std::size_t>(refiner.GetLevel(refiner.GetMaxLevel()).GetNumVertices());
  mesh.positions.resize(count);
  mesh.normals.resize(count);
  Limiter limiter(refiner, refined, mesh);
  Ring ring;
  struct Deferred {
    Parent kind;
    Index index;
  };
  std::vector<Deferred> fallback;  // the normals that need every limit position first
  const auto each = [&](Parent kind, int n) {
    const RingOf ring_of_kind = ring_of(kind);
    for (Index i = 0; i < n; ++i) {
      ring_of_kind(parent, i, ring);
      if (!limiter.store(ring)) fallback.push_back({kind, i});
    }
  };
  each(Parent::Face, parent.GetNumFaces());
  each(Parent::Edge, parent.GetNumEdges());
  each(Parent::Vertex, parent.GetNumVertices());
  for (const Deferred& d : fallback) {
    ring_of(d.kind)(parent, d.index, ring);
    limiter.store_fallback(ring);
  }
}

}  // namespace sweep::subdivision_detail
