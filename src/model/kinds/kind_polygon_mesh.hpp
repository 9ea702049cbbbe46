#pragma once
// The polygon mesh (a control cage), mesh. One kind, declared in one place (object.hpp lists the kinds).
#include "model/kinds/kind_fields.hpp"

namespace sweep {

/// A polygon control cage: face f has face_sizes[f] vertices, listed in face_vertices after
/// those of the faces before it (0-based indices into `points`, counterclockwise seen from
/// outside).
struct PolygonMeshSurface : PointsPart, MaterialPart {
  static constexpr KindTraits traits{.keyword = "mesh",
                                     .family = KindFamily::Surface,
                                     .planar = false,
                                     .points = point_layouts::kNet,
                                     .interpolating = false,
                                     .steps = false,
                                     .label = "polygon mesh",
                                     .phrase = "a polygon mesh"};
  std::vector<int> face_sizes;
  std::vector<int> face_vertices;
  static void fields(auto& self, auto& f) { f.custom(self); }
  bool operator==(const PolygonMeshSurface&) const = default;
};
template <>
inline constexpr std::span<const SwpClause> kind_clauses<PolygonMeshSurface> = swp_clause_checks::kNetSurface;

}  // namespace sweep
