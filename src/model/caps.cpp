#include "model/caps.hpp"

#include "base/number_text.hpp"
#include "base/precondition.hpp"
#include "geometry/subdivision/subdivision.hpp"
#include "geometry/surfaces/birail.hpp"
#include "geometry/surfaces/patch.hpp"
#include "geometry/surfaces/surface.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/file_limits.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace sweep {
namespace {

std::string at_most(std::int64_t cap) {
  return "expected at most " + std::to_string(cap);
}

}  // namespace

std::string expected_samples_per_curve() {
  return at_most(limits::kMaxCurveSamples) + " samples per curve";
}

std::optional<CapBreach> CapTally::add_points(std::int64_t count, const char* what) {
  points_ += count;
  if (points_ <= limits::kMaxControlPoints) return std::nullopt;
  return CapBreach{true, at_most(limits::kMaxControlPoints) + " control points in the whole document",
                   std::string(what) + " brings the total to " + std::to_string(points_)};
}

std::optional<CapBreach> CapTally::add_face_corners(std::int64_t corners) {
  points_ += corners;
  if (points_ <= limits::kMaxControlPoints) return std::nullopt;
  return CapBreach{true, at_most(limits::kMaxControlPoints) + " points and face corners in the whole document", ""};
}

std::optional<CapBreach> CapTally::add_samples(std::int64_t samples, const std::string& cause) {
  if (samples > limits::kMaxCurveSamples) {
    return CapBreach{false, expected_samples_per_curve(), cause + " " + std::to_string(samples)};
  }
  samples_ += samples;
  if (samples_ <= 2 * limits::kMaxCurveSamples) return std::nullopt;
  return CapBreach{true, at_most(2 * limits::kMaxCurveSamples) + " curve samples in the whole document",
                   "this curve brings the total to " + std::to_string(samples_)};
}

std::optional<CapBreach> CapTally::add_vertices(std::int64_t vertices) {
  if (vertices > limits::kMaxMeshVertices) {
    return CapBreach{false, "expected a surface of at most " + std::to_string(limits::kMaxMeshVertices) + " vertices",
                     "this one would have " + std::to_string(vertices)};
  }
  vertices_ += vertices;
  if (vertices_ <= limits::kMaxMeshVertices) return std::nullopt;
  return CapBreach{true, at_most(limits::kMaxMeshVertices) + " surface vertices in the whole document",
                   "this surface brings the total to " + std::to_string(vertices_)};
}

std::int64_t subdivision_vertex_count(const SubdivisionSurface& subd, const Object& source,
                                      std::int64_t source_vertices) {
  if (source.kind() == ObjectKind::PolygonMesh) {
    const SubdivisionScheme scheme = subd.loop ? SubdivisionScheme::Loop : SubdivisionScheme::CatmullClark;
    return refined_counts(cage_of(source), subd.levels, scheme).vertices;
  }
  // A grid surface's cage has about as many faces as vertices and twice as many edges, so each
  // level multiplies its vertices by about 4.
  std::int64_t vertices = source_vertices;
  for (int level = 0; level < subd.levels && vertices <= limits::kMaxMeshVertices; ++level) vertices *= 4;
  return vertices;
}

ObjectCounts object_counts(const Object& o, const ObjectAt& object_at,
                           const std::function<std::int64_t(int index)>& vertices_of) {
  ObjectCounts counts;
  counts.points = static_cast<std::int64_t>(points_of(o).size());
  const auto samples = [&](int index) { return curve_sample_count(object_at(index)); };
  std::visit(Overloaded{
                 [&]<typename Kind>(const Kind& kind)
                   requires(Kind::traits.family == KindFamily::Curve)
                 {
                   counts.samples = curve_sample_count(o);
                   if constexpr (std::is_same_v<Kind, HelixCurve>) {
    counts.samples_cause = "STEPS " + std::to_string(kind.steps) + " and TURNS " + number_text(kind.turns) + " give";
                   } else if constexpr (std::is_base_of_v<StepsPart, Kind>) {
    counts.samples_cause = "STEPS " + std::to_string(kind.steps) + " gives";
                   } else {
    counts.samples_cause = std::to_string(counts.points) + " points give";
                   }
}
, [&](const RevolutionSurface& s) { counts.vertices = revolution_vertex_count(samples(s.profile), false, s.copies); },
    [&](const CylinderSurface& s) {
      counts.vertices = cylinder_vertex_count(samples(s.profile), false, samples(s.sweep), false);
    },
    [&](const BirailSurface& s) {
      counts.vertices = birail_vertex_count(samples(s.profile), samples(s.rail1), samples(s.rail2));
    },
    [&](const BezierPatchSurface& s) { counts.vertices = bezier_patch_vertex_count(counts.points / 16, s.steps); },
    [&](const BSplinePatchSurface& s) { counts.vertices = bspline_patch_vertex_count(s.rows, s.columns, s.steps); },
    [&](const PolygonMeshSurface& s) {
      counts.vertices = counts.points;
      counts.face_corners = static_cast<std::int64_t>(s.face_vertices.size());
    },
    [&](const SubdivisionSurface& s) {
      counts.vertices = subdivision_vertex_count(s, object_at(s.source), vertices_of(s.source));
    },
    [](const MaterialLook&) {}, [](const RiderObject&) {},  // draws its model where it rides: no vertices of its own
}  // namespace sweep
,
             o.data);
return counts;
}

std::optional<std::pair<int, CapBreach>> first_cap_breach(int count, const ObjectAt& object_at) {
  CapTally tally;
  std::vector<std::int64_t> vertices(static_cast<std::size_t>(std::max(count, 0)), 0);
  const auto vertices_of = [&](int index) { return vertices[static_cast<std::size_t>(index)]; };
  for (int i = 0; i < count; ++i) {
    const ObjectCounts counts = object_counts(object_at(i), object_at, vertices_of);
    vertices[static_cast<std::size_t>(i)] = counts.vertices;
    const bool curve = is_curve(object_at(i).kind());
    std::optional<CapBreach> breach = tally.add_points(counts.points, curve ? "this curve" : "this object");
    if (!breach && counts.face_corners > 0) breach = tally.add_face_corners(counts.face_corners);
    if (!breach && curve) breach = tally.add_samples(counts.samples, counts.samples_cause);
    if (!breach && counts.vertices > 0) breach = tally.add_vertices(counts.vertices);
    if (breach) return std::pair{i, std::move(*breach)};
  }
  return std::nullopt;
}

std::int64_t evaluation_work(const Document& doc, const std::vector<int>& indices) {
  const auto object_at = [&doc](int index) -> const Object& { return doc.objects[static_cast<std::size_t>(index)]; };
  // A subd's estimate needs its source's vertices, and so on back: one pass over the document.
  std::vector<std::int64_t> vertices(doc.objects.size(), 0);
  const auto vertices_of = [&vertices](int index) { return vertices[static_cast<std::size_t>(index)]; };
  std::vector<std::int64_t> work(doc.objects.size(), 0);
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const ObjectCounts counts = object_counts(doc.objects[i], object_at, vertices_of);
    vertices[i] = counts.vertices;
    work[i] = counts.points + counts.samples + counts.vertices;
  }
  std::int64_t total = 0;
  for (const int index : indices) {
    SWEEP_EXPECTS(index >= 0 && static_cast<std::size_t>(index) < doc.objects.size(), "indices are in range");
    total += work[static_cast<std::size_t>(index)];
  }
  return total;
}

}  // namespace sweep
