// Adaptive sampling of surfaces (EvaluationOptions::tolerance): on every starter file, every
// surface stays within the tolerance of the exact surface (surface_deviation), and its mesh is
// the same clean grid as with STEPS: as many boundary edges as the grid's open sides imply (none
// for a closed profile swept along a closed curve or turned), no edge shared by more than two
// triangles, closed meshes watertight and consistently oriented, unit normals.
#include "geometry/curves/adaptive.hpp"
#include "geometry/mesh/mesh_topology.hpp"
#include "geometry/surfaces/surface.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/deviation.hpp"
#include "model/evaluation/scene.hpp"

#include "model/evaluation/curve_evaluation.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>

namespace {

/// Samples per ring (a closed curve's last sample is its first) and segments of a curve.
std::size_t ring_of(const sweep::CurveSamples& c) {
  return c.closed ? c.frames.size() - 1 : c.frames.size();
}
std::size_t segments_of(const sweep::CurveSamples& c) {
  return c.frames.size() - 1;
}

/// The boundary edges the grid of a surface's sampling has: each open side of the grid (an open
/// profile's two ends, an open sweep's two end rings) is a run of edges; closed sides have none.
/// A bevelled corner's strip has vertices of its own: its quads' four sides, and the two rings it
/// joins, are boundary edges by index (welded by position the tube is watertight, see below).
std::size_t grid_boundary_edges(const sweep::Object& surface, const sweep::SurfaceSampling& s, std::size_t bevels) {
  if (surface.kind() == sweep::ObjectKind::SurfaceOfRevolution) {
    // An open profile's end: a ring of edges, one a copy; at a pole (the end on the axis) the
    // fan's two sides a copy, since each copy of the pole is its own vertex (its own normal).
    std::size_t edges = 0;
    if (s.profile.closed) return edges;
    for (const sweep::Frame* end : {&s.profile.frames.front(), &s.profile.frames.back()}) {
      edges += (end->V.x == 0.0 ? 2 : 1) * static_cast<std::size_t>(s.copies);
    }
    return edges;
  }
  const std::size_t profile_ends = s.profile.closed ? 0 : 2;
  const std::size_t sweep_ends = s.sweep.closed ? 0 : 2;
  return profile_ends * segments_of(s.sweep) + sweep_ends * segments_of(s.profile) +
         6 * bevels * segments_of(s.profile);
}

/// The grid's vertices and each bevel's ring and strip.
std::size_t grid_vertices(const sweep::Object& surface, const sweep::SurfaceSampling& s, std::size_t bevels) {
  if (surface.kind() == sweep::ObjectKind::SurfaceOfRevolution) {
    return ring_of(s.profile) * static_cast<std::size_t>(s.copies);
  }
  return ring_of(s.profile) * (ring_of(s.sweep) + bevels) + 4 * bevels * segments_of(s.profile);
}

struct Topology {
  std::size_t boundary = 0;     // edges used by one triangle
  std::size_t overused = 0;     // edges used by more than two
  std::size_t unpaired = 0;     // directed edges not traversed once each way (closed meshes)
  std::size_t bad_normals = 0;  // not unit or not finite
};

Topology topology_of(const sweep::Mesh& mesh) {
  Topology t;
  for (const auto& [edge, uses] : sweep::test::edge_uses(mesh)) {
    if (uses == 1) ++t.boundary;
    if (uses > 2) ++t.overused;
  }
  const auto directed = sweep::test::directed_edge_uses(mesh);
  for (const auto& [edge, uses] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    if (uses != 1 || reverse == directed.end() || reverse->second != 1) ++t.unpaired;
  }
  for (const glm::vec3& n : mesh.normals) {
    if (!std::isfinite(n.x) || !std::isfinite(n.y) || !std::isfinite(n.z) || std::abs(glm::length(n) - 1.0f) > 1e-5f) {
      ++t.bad_normals;
    }
  }
  return t;
}

/// Expects the mesh of surface `index` to be the clean grid of its sampling.
void expect_clean_grid(const sweep::Document& doc, const sweep::Scene& scene, int index,
                       const sweep::EvaluationOptions& options, const std::string& what) {
  const sweep::Object& surface = doc.objects[static_cast<std::size_t>(index)];
  const sweep::Mesh& mesh = scene.objects[static_cast<std::size_t>(index)].mesh;
  const sweep::SurfaceSampling sampling = sweep::surface_sampling(doc, scene, index, options);
  const std::size_t bevels = surface.kind() == sweep::ObjectKind::GeneralizedCylinder
                                 ? sweep::bevel_count(sampling.sweep, options.mitre_limit)
                                 : 0;
  EXPECT_EQ(mesh.vertex_count(), grid_vertices(surface, sampling, bevels)) << what;
  EXPECT_EQ(mesh.normals.size(), mesh.vertex_count()) << what;
  for (const std::uint32_t v : mesh.indices) ASSERT_LT(v, mesh.vertex_count()) << what;
  const Topology t = topology_of(mesh);
  // Where a tube's rings are clipped together at a corner, the triangles of no area between them
  // are left out (add_quad_without_collapsed): the grid is then open by index and whole only
  // welded by position.
  const bool collapsed = surface.kind() == sweep::ObjectKind::GeneralizedCylinder &&
                         static_cast<std::int64_t>(mesh.triangle_count()) <
                             sweep::cylinder_triangle_count(static_cast<std::int64_t>(sampling.profile.frames.size()),
                                                            static_cast<std::int64_t>(sampling.sweep.frames.size()),
                                                            static_cast<std::int64_t>(bevels));
  if (!collapsed) {
    EXPECT_EQ(t.boundary, grid_boundary_edges(surface, sampling, bevels)) << what;
  }
  EXPECT_EQ(t.overused, 0u) << what;
  EXPECT_EQ(t.bad_normals, 0u) << what;
  const bool closed =
      sampling.profile.closed && (surface.kind() == sweep::ObjectKind::SurfaceOfRevolution || sampling.sweep.closed);
  if (closed && bevels == 0 && !collapsed) {
    EXPECT_EQ(t.unpaired, 0u) << what << ": not watertight";
  } else if (closed) {
    EXPECT_TRUE(sweep::mesh_topology(mesh).closed_manifold()) << what << ": not watertight";
  }
}

TEST(AdaptiveSurfaces, EveryStarterSurfaceStaysWithinTheToleranceAsACleanGrid) {
  const auto files = sweep::test::starter_files();
  ASSERT_FALSE(files.empty());
  int surfaces = 0;
  for (const auto& file : files) {
    const sweep::Document doc = sweep::io::load_swp_file(file);
    sweep::EvaluationOptions options;
    options.tolerance = 1e-3 * sweep::document_extent(doc);
    ASSERT_GT(options.tolerance, 0.0) << file;
    const sweep::Scene uniform = sweep::evaluate_document(doc);
    const sweep::Scene scene = sweep::evaluate_document(doc, options);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      if (!sweep::is_surface(doc.objects[i].kind())) continue;
      // Birail and controlled sweeps are outside the bound (deviation.hpp); caps add vertices
      // outside the grid (tests/core/caps_test.cpp checks them).
      if (!sweep::deviation_is_measured(doc.objects[i]) || doc.objects[i].as<sweep::CapsPart>().caps) continue;
      ++surfaces;
      const int index = static_cast<int>(i);
      const std::string what = file.filename().string() + " " + sweep::display_name(doc, index);
      EXPECT_FALSE(scene.objects[i].over_limit) << what;
      // The same grid rule holds for STEPS (so it is the rule the meshes had before) ...
      expect_clean_grid(doc, uniform, index, {}, what + " (uniform)");
      // ... and adaptively.
      expect_clean_grid(doc, scene, index, options, what);
      // A closed grid stays closed: adaptive sampling keeps curves closed.
      const sweep::SurfaceSampling a = sweep::surface_sampling(doc, scene, index, options);
      const sweep::SurfaceSampling u = sweep::surface_sampling(doc, uniform, index, {});
      EXPECT_EQ(a.profile.closed, u.profile.closed) << what;
      EXPECT_EQ(a.sweep.closed, u.sweep.closed) << what;
      EXPECT_EQ(a.profile.corners.size(), u.profile.corners.size()) << what;
      EXPECT_EQ(a.sweep.corners.size(), u.sweep.corners.size()) << what;
      // The bound, measured on a reference 4 x 4 times denser than the mesh's grid.
      EXPECT_LE(sweep::surface_deviation(doc, scene, index, options, 4), options.tolerance) << what;
    }
  }
  EXPECT_GE(surfaces, 15);
}

TEST(AdaptiveSurfaces, EveryStarterSurfaceKeepsCoarserAndFinerTolerances) {
  // 1e-2 and 1e-4 of the scene's size (1e-3 above); the issue asks for 1e-2 to 1e-5, and 1e-5
  // is left to the benchmarks (docs/adaptive-sampling.md) to keep the unit tests fast.
  for (const auto& file : sweep::test::starter_files()) {
    const sweep::Document doc = sweep::io::load_swp_file(file);
    for (const double share : {1e-2, 1e-4}) {
      sweep::EvaluationOptions options;
      options.tolerance = share * sweep::document_extent(doc);
      const sweep::Scene scene = sweep::evaluate_document(doc, options);
      for (std::size_t i = 0; i < doc.objects.size(); ++i) {
        if (!sweep::is_surface(doc.objects[i].kind()) || !sweep::deviation_is_measured(doc.objects[i])) continue;
        const int index = static_cast<int>(i);
        const std::string what = file.filename().string() + " " + sweep::display_name(doc, index);
        EXPECT_FALSE(scene.objects[i].over_limit) << what;
        EXPECT_LE(sweep::surface_deviation(doc, scene, index, options, 4), options.tolerance)
            << what << " at " << share << " of the scene's size";
      }
    }
  }
}

TEST(AdaptiveSurfaces, SymmetricSeamStaysWatertight) {
  // Closed profiles along closed sweeps with the symmetric seam (the last ring joins the first
  // turned by the profile's symmetry): still watertight when sampled adaptively.
  int closed = 0;
  for (const char* name : {"tor.swp", "florus.swp", "gentorus.swp", "knots.swp", "corners.swp"}) {
    const sweep::Document doc = sweep::test::load_starter(name);
    sweep::EvaluationOptions options;
    options.seam = sweep::SeamMode::Symmetric;
    options.tolerance = 1e-3 * sweep::document_extent(doc);
    const sweep::Scene scene = sweep::evaluate_document(doc, options);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      if (doc.objects[i].kind() != sweep::ObjectKind::GeneralizedCylinder) continue;
      const int index = static_cast<int>(i);
      const sweep::SurfaceSampling s = sweep::surface_sampling(doc, scene, index, options);
      if (!s.profile.closed || !s.sweep.closed) continue;
      ++closed;
      const Topology t = topology_of(scene.objects[i].mesh);
      const std::string what = std::string(name) + " " + sweep::display_name(doc, index);
      EXPECT_EQ(t.boundary, 0u) << what;
      EXPECT_EQ(t.overused, 0u) << what;
      EXPECT_EQ(t.unpaired, 0u) << what;
      EXPECT_EQ(t.bad_normals, 0u) << what;
    }
  }
  EXPECT_GE(closed, 4);
}

}  // namespace
