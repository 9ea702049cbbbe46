#pragma once
// Subdivision surfaces through OpenSubdiv (Far): a polygon cage refined LEVELS times by
// Catmull-Clark or Loop, with positions and normals on the limit surface. Also the cages
// themselves: a `mesh` object's polygons, or the quad grid of a surface built on a grid.
#include "geometry/mesh/mesh.hpp"

#include <glm/vec3.hpp>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sweep {

/// A polygon mesh: face f has face_sizes[f] corners, listed in face_vertices after those of the
/// faces before it (0-based indices into points, counterclockwise seen from outside).
struct Cage {
  std::vector<glm::dvec3> points;
  std::vector<int> face_sizes;
  std::vector<int> face_vertices;
};

enum class SubdivisionScheme : std::uint8_t { CatmullClark, Loop };

struct SubdivisionOptions {
  int levels = 0;  // 0 to kMaxSubdivisionLevel
  SubdivisionScheme scheme = SubdivisionScheme::CatmullClark;
  bool smooth_boundary = false;  // false: boundary corners are kept (sharp)
};

inline constexpr int kMaxSubdivisionLevel = 6;

/// Vertices, edges and faces of a cage or of one refinement level.
struct CageCounts {
  std::int64_t vertices = 0;
  std::int64_t edges = 0;
  std::int64_t faces = 0;
};

/// What is wrong with a cage's faces, if anything: `face` is the 0-based face the message is
/// about, `expected` the message ("expected ..."; other faces named in it are 1-based, as in
/// SWP and OBJ messages).
struct CageProblem {
  int face = 0;
  std::string expected;
};

/// Checks a cage's faces: at least 3 corners each, indices in range, no corner repeated, and
/// manifold (every edge in at most two faces, once each way).
std::optional<CageProblem> check_cage(const Cage& cage);

/// Counts of a cage that passes check_cage (edges counted once each).
CageCounts cage_counts(const Cage& cage);

/// The counts after `levels` uniform refinements, known before refining (for the caps): a face
/// of n corners becomes n quads (Catmull-Clark) or 4 triangles (Loop), an edge 2 edges plus those
/// inside the faces, and a new vertex is added per face (Catmull-Clark) and per edge.
CageCounts refined_counts(const Cage& cage, int levels, SubdivisionScheme scheme);

/// The refined level's counts and mesh: positions and normals (dP/du x dP/dv of OpenSubdiv's
/// limit tangents, outward for a counterclockwise cage) of the limit surface at the refined
/// vertices, each refined face as triangles. A large Catmull-Clark refinement runs on
/// worker_count() threads (thread_pool.hpp); the result is the same whatever their number.
/// Preconditions: check_cage passes; Loop needs triangles only; levels in [0, kMaxSubdivisionLevel].
struct Subdivided {
  Mesh mesh;
  CageCounts counts;
};
Subdivided subdivide(const Cage& cage, const SubdivisionOptions& options);

/// The quads of a mesh built as a grid (add_quad's triangle pairs, with `quads`; other
/// triangles, and all of them without, stay triangles), welded (welded_cage).
Cage grid_cage(const Mesh& mesh, bool quads = true);

/// The cage with positions within 1e-9 of its size welded (seams) and faces that welding
/// collapsed reduced (a quad at a pole becomes a triangle) or dropped.
Cage welded_cage(const Cage& cage);

/// The cage shaded: one vertex per point with the area-weighted normal of its faces, each face a
/// triangle fan, and the polygons kept for export (Mesh::polygon_sizes).
Mesh cage_mesh(const Cage& cage);

/// Every edge of the cage once, as pairs of positions (for drawing).
std::vector<glm::vec3> cage_edge_lines(const Cage& cage);

}  // namespace sweep
