#include "model/evaluation/scene.hpp"

#include "base/precondition.hpp"
#include "geometry/subdivision/subdivision.hpp"
#include "geometry/surfaces/birail.hpp"
#include "geometry/surfaces/patch.hpp"
#include "geometry/surfaces/texture_coordinates.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/deviation.hpp"
#include "model/file_limits.hpp"
#include "model/material.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <optional>
#include <utility>

namespace sweep {
namespace {

/// Revisions come from one counter so that no two evaluations, even of different scenes, share one.
std::uint64_t next_revision() {
  static std::atomic<std::uint64_t> counter{0};
  return ++counter;
}

/// A curve by its STEPS whatever its tolerance clause says.
CurveSamples evaluate_by_steps(const Object& curve, const FrameOptions& frames) {
  CurveDescriptor descriptor = describe_curve(curve);
  descriptor.tolerance = 0.0;
  return evaluate_curve(descriptor, frames);
}

/// The curves of a scene a surface's controls refer to, and the options' mitre limit.
SweepControls controls_of(const Scene& scene, const Object& object, const EvaluationOptions& options) {
  const CylinderSurface& cylinder = object.as<CylinderSurface>();
  SweepControls controls;
  controls.mitre_limit = options.mitre_limit;
  if (cylinder.scale >= 0) controls.scale = &scene.objects[static_cast<std::size_t>(cylinder.scale)].curve;
  if (cylinder.twist_curve >= 0)
    controls.twist_curve = &scene.objects[static_cast<std::size_t>(cylinder.twist_curve)].curve;
  controls.twist_degrees = cylinder.twist;
  controls.caps = cylinder.caps;
  return controls;
}

/// True if `surface` gets texture coordinates under `options` (TextureCoordinates).
bool wants_uvs(const Document& doc, const Object& surface, const EvaluationOptions& options) {
  return options.texture_coordinates == TextureCoordinates::Everywhere || puts_image_on(doc, surface);
}

/// Texture coordinates of a swept surface's grid (texture_coordinates.hpp), if it wants them.
void add_swept_uvs(Mesh& mesh, const Document& doc, const Object& object, const CurveSamples& profile,
                   const CurveSamples& sweep, const CurveSamples& rail2, int copies,
                   const SweepDiagnostics& diagnostics, const EvaluationOptions& options) {
  if (!wants_uvs(doc, object, options)) return;
  GridLayout grid;
  grid.profile_closed = profile.closed;
  if (object.kind() == ObjectKind::SurfaceOfRevolution) {
    grid.ring = ring_size(profile);
    grid.rings = static_cast<std::size_t>(copies);
    grid.sweep_closed = true;
  } else if (object.kind() == ObjectKind::Birail) {
    grid.ring = profile.frames.size();  // a birail repeats a closed profile's seam
    grid.profile_closed = false;
    grid.rings = grid.ring > 0 ? mesh.positions.size() / grid.ring : 0;
    grid.sweep_closed = sweep.closed && rail2.closed;
  } else {
    grid.ring = ring_size(profile);
    grid.rings = ring_size(sweep) + diagnostics.bevels;  // a bevel's second ring is in the grid
    grid.sweep_closed = sweep.closed;
  }
  add_grid_texture_coordinates(mesh, grid, puts_image_on(doc, object));
}

/// The mesh of a surface from its curves as sampled for it, in the buffers of `storage` (srev and
/// gcyl: the ones a drag re-meshes at size; a birail's is built anew).
Mesh build_surface(const Scene& scene, const Object& object, const CurveSamples& profile, const CurveSamples& sweep,
                   const CurveSamples& rail2, int copies, const EvaluationOptions& options,
                   SweepDiagnostics& diagnostics, Mesh storage) {
  if (const auto* revolution = object.find<RevolutionSurface>()) {
    return build_surface_of_revolution(profile, copies, revolution->caps, std::move(storage));
  }
  if (const auto* birail = object.find<BirailSurface>()) return build_birail(profile, sweep, rail2, birail->height);
  return build_generalized_cylinder(profile, sweep, options.seam, &diagnostics, controls_of(scene, object, options),
                                    std::move(storage));
}

/// The cage a subd refines: a mesh's polygons, a patch's sample grid, or the quads of a grid
/// surface (triangles only for Loop).
Cage source_cage(const Object& source, const Mesh& mesh, SubdivisionScheme scheme) {
  if (source.find<PolygonMeshSurface>()) return cage_of(source);
  if (const auto* patches = source.find<BezierPatchSurface>())
    return bezier_patch_cage(patches->points, patches->steps);
  if (const auto* patch = source.find<BSplinePatchSurface>()) {
    return bspline_patch_cage(patch->points, patch->rows, patch->columns, patch->steps);
  }
  return grid_cage(mesh, scheme == SubdivisionScheme::CatmullClark);
}

/// Patches, meshes and subdivision surfaces: built from points (no curves, no tolerance).
void evaluate_net_object(const Scene& scene, const Document& doc, const Object& object, EvaluatedObject& out) {
  using Role = EvaluatedObject::NetRole;
  if (const auto* patches = object.find<BezierPatchSurface>()) {
    out.mesh = build_bezier_patches(patches->points, patches->steps);
    out.net = patch_net_lines(patches->points, 4, 0);
    out.net_role = Role::ControlNet;
  } else if (const auto* patch = object.find<BSplinePatchSurface>()) {
    out.mesh = build_bspline_patch(patch->points, patch->rows, patch->columns, patch->steps);
    out.net = patch_net_lines(patch->points, patch->rows, patch->columns);
    out.net_role = Role::ControlNet;
  } else if (object.find<PolygonMeshSurface>()) {
    const Cage cage = cage_of(object);
    out.mesh = cage_mesh(cage);
    out.net = cage_edge_lines(cage);
    out.net_role = Role::ControlNet;
  } else {
    const SubdivisionSurface& subd = object.as<SubdivisionSurface>();
    const auto source_index = static_cast<std::size_t>(subd.source);
    const SubdivisionScheme scheme = subd.loop ? SubdivisionScheme::Loop : SubdivisionScheme::CatmullClark;
    const Cage cage = source_cage(doc.objects[source_index], scene.objects[source_index].mesh, scheme);
    out.mesh = subdivide(cage, {subd.levels, scheme, subd.smooth_boundary}).mesh;
    out.net = cage_edge_lines(cage);
    out.net_role = Role::Cage;
  }
}

/// The track of a rider's path as the scene sampled it.
RiderTrack rider_track(const Document& doc, const Scene& scene, const RiderObject& rider) {
  const auto path = static_cast<std::size_t>(rider.path);
  std::optional<glm::dvec3> up;
  if (rider.up != glm::dvec3(0.0)) up = rider.up;
  return make_rider_track(describe_curve(doc.objects[path]), scene.objects[path].curve, up);
}

bool is_net_object(ObjectKind kind) {
  return has_control_net(kind) || kind == ObjectKind::Subdivision;
}

void evaluate_object(Scene& scene, const Document& doc, std::size_t i, const EvaluationOptions& options) {
  const Object& object = doc.objects[i];
  EvaluatedObject& out = scene.objects[i];
  out.curve = {};
  out.track = {};
  Mesh storage = emptied(std::move(out.mesh));  // its buffers, for the surface built next
  out.mesh = {};
  out.diagnostics = {};
  out.over_limit = false;
  out.net.clear();
  out.net_role = EvaluatedObject::NetRole::None;
  if (is_material(object.kind())) {
    // Nothing to evaluate: renderers and exporters read it through the surfaces that use it.
  } else if (const auto* rider = object.find<RiderObject>()) {
    out.track = rider_track(doc, scene, *rider);
  } else if (is_net_object(object.kind())) {
    evaluate_net_object(scene, doc, object, out);
    if (wants_uvs(doc, object, options)) add_box_texture_coordinates(out.mesh);
  } else if (is_curve(object.kind())) {
    out.curve = evaluate_curve(object, options.frames, {options.tolerance, 0.0});
    out.over_limit = out.curve.capped;
  } else if (options.tolerance > 0.0) {
    const SurfaceSampling s = surface_sampling(doc, scene, static_cast<int>(i), options);
    out.over_limit = s.over_limit;
    out.mesh = build_surface(scene, object, s.profile, s.sweep, s.rail2, s.copies, options, out.diagnostics,
                             std::move(storage));
    add_swept_uvs(out.mesh, doc, object, s.profile, s.sweep, s.rail2, s.copies, out.diagnostics, options);
  } else {
    // By STEPS the scene's curves are the surface's (no copy on the re-mesh of an edit).
    const auto curve = [&scene](int index) -> const CurveSamples& {
      static const CurveSamples none;
      return index >= 0 ? scene.objects[static_cast<std::size_t>(index)].curve : none;
    };
    const SweptCurves curves = swept_curves(object);
    const CopiesPart* revolution = object.find<CopiesPart>();  // srev: its copies about the axis
    const int copies = revolution ? revolution->copies : 0;
    out.mesh = build_surface(scene, object, curve(curves.profile), curve(curves.path), curve(curves.rail2), copies,
                             options, out.diagnostics, std::move(storage));
    add_swept_uvs(out.mesh, doc, object, curve(curves.profile), curve(curves.path), curve(curves.rail2), copies,
                  out.diagnostics, options);
  }
  out.revision = next_revision();
}

}  // namespace

SurfaceSampling surface_sampling(const Document& doc, const Scene& scene, int index, const EvaluationOptions& options) {
  SWEEP_EXPECTS(index >= 0 && static_cast<std::size_t>(index) < doc.objects.size() &&
                    (doc.objects[static_cast<std::size_t>(index)].kind() == ObjectKind::SurfaceOfRevolution ||
                     doc.objects[static_cast<std::size_t>(index)].kind() == ObjectKind::GeneralizedCylinder ||
                     doc.objects[static_cast<std::size_t>(index)].kind() == ObjectKind::Birail),
                "doc.objects[index] is a swept surface (srev, gcyl, birail)");
  SWEEP_EXPECTS(scene.objects.size() >= static_cast<std::size_t>(index), "scene holds the evaluated objects before it");
  const Object& surface = doc.objects[static_cast<std::size_t>(index)];
  const SweptCurves curves = swept_curves(surface);
  const auto profile_index = static_cast<std::size_t>(curves.profile);
  const auto sweep_index = static_cast<std::size_t>(curves.path);
  const bool revolution = surface.kind() == ObjectKind::SurfaceOfRevolution;
  SurfaceSampling s;
  if (options.tolerance > 0.0) {
    // A share of the tolerance for the profile, the same for the sweep or the turn: their errors
    // add up in the middle of a quad, and the rest covers the quad's diagonal (its triangles
    // are not the bilinear patch) and the frames' discretization on 3D sweeps (measured on
    // every starter file; docs/adaptive-sampling.md).
    const double half = kSurfaceShare * options.tolerance;
    s.profile = evaluate_curve(doc.objects[profile_index], options.frames, {half, 0.0});
    const auto profile_samples = static_cast<std::int64_t>(s.profile.frames.size());
    std::int64_t vertices = 0;
    if (revolution) {
      double radius = 0.0;  // from the axis; the exact profile reaches at most `half` farther
      for (const Frame& f : s.profile.frames) radius = std::max(radius, std::abs(f.V.x));
      s.copies = circle_segments(radius + half, half);
      vertices = revolution_vertex_count(profile_samples, s.profile.closed, s.copies);
    } else if (surface.kind() == ObjectKind::Birail) {
      s.sweep = evaluate_curve(doc.objects[sweep_index], options.frames, {half, 0.0});
      s.rail2 = evaluate_curve(doc.objects[static_cast<std::size_t>(curves.rail2)], options.frames, {half, 0.0});
      vertices = birail_vertex_count(profile_samples, static_cast<std::int64_t>(s.sweep.frames.size()),
                                     static_cast<std::int64_t>(s.rail2.frames.size()));
    } else {
      if (deviation_is_measured(surface)) {
        s.sweep = evaluate_curve(doc.objects[sweep_index], options.frames, {half, profile_radius(s.profile) + half});
      } else {
        // A scale or twist changes the surface between sweep samples that the sweep's own
        // flatness knows nothing of: such a sweep keeps its STEPS (deviation.hpp).
        s.sweep = evaluate_by_steps(doc.objects[sweep_index], options.frames);
      }
      vertices =
          cylinder_vertex_count(profile_samples, s.profile.closed, static_cast<std::int64_t>(s.sweep.frames.size()),
                                s.sweep.closed, static_cast<std::int64_t>(bevel_count(s.sweep, options.mitre_limit)));
    }
    s.over_limit = s.profile.capped || s.sweep.capped || s.rail2.capped || vertices > limits::kMaxMeshVertices;
    if (!s.over_limit) return s;
  }
  if (s.over_limit) {
    // Past a cap for the tolerance: by STEPS (the curves' own clauses too), as promised.
    const auto by_steps = [&](std::size_t curve_index) {
      return evaluate_by_steps(doc.objects[curve_index], options.frames);
    };
    s.profile = by_steps(profile_index);
    if (revolution) {
      s.copies = surface.as<RevolutionSurface>().copies;
    } else {
      s.sweep = by_steps(sweep_index);
    }
    if (curves.rail2 >= 0) s.rail2 = by_steps(static_cast<std::size_t>(curves.rail2));
    return s;
  }
  s.profile = scene.objects[profile_index].curve;
  if (revolution) {
    s.copies = surface.as<RevolutionSurface>().copies;
  } else {
    s.sweep = scene.objects[sweep_index].curve;
  }
  if (curves.rail2 >= 0) s.rail2 = scene.objects[static_cast<std::size_t>(curves.rail2)].curve;
  return s;
}

Scene evaluate_document(const Document& doc, const EvaluationOptions& options) {
  Scene scene;
  reevaluate_all(scene, doc, options);
  return scene;
}

void reevaluate_all(Scene& scene, const Document& doc, const EvaluationOptions& options) {
  scene.objects.resize(doc.objects.size());
  for (std::size_t i = 0; i < doc.objects.size(); ++i) evaluate_object(scene, doc, i, options);
}

std::vector<int> dependents_of(const Document& doc, int index) {
  std::vector<bool> affected(doc.objects.size(), false);
  std::vector<int> result;
  if (index < 0 || static_cast<std::size_t>(index) >= doc.objects.size()) return result;
  affected[static_cast<std::size_t>(index)] = true;
  result.push_back(index);
  // References point backwards, so one forward pass finds everything downstream.
  for (std::size_t i = static_cast<std::size_t>(index) + 1; i < doc.objects.size(); ++i) {
    bool uses = false;
    for (const int r : references(doc.objects[i])) uses = uses || (r >= 0 && affected[static_cast<std::size_t>(r)]);
    if (uses) {
      affected[i] = true;
      result.push_back(static_cast<int>(i));
    }
  }
  return result;
}

std::vector<int> reevaluate(Scene& scene, const Document& doc, int index, const EvaluationOptions& options) {
  scene.objects.resize(doc.objects.size());
  const std::vector<int> changed = dependents_of(doc, index);
  for (int i : changed) evaluate_object(scene, doc, static_cast<std::size_t>(i), options);
  return changed;
}

bool evaluate_objects(Scene& scene, const Document& doc, const std::vector<int>& indices,
                      const EvaluationOptions& options, EvaluationProgress* progress) {
  SWEEP_EXPECTS(scene.objects.size() == doc.objects.size(), "scene is sized as doc");
  SWEEP_EXPECTS(std::is_sorted(indices.begin(), indices.end()), "indices are in document order");
  for (const int i : indices) {
    if (progress && progress->cancel.load(std::memory_order_relaxed)) return false;
    evaluate_object(scene, doc, static_cast<std::size_t>(i), options);
    if (progress) progress->done.fetch_add(1, std::memory_order_relaxed);
  }
  return true;
}

std::uint64_t new_scene_revision() {
  return next_revision();
}

EvaluationOptions evaluation_options(std::string_view frames, std::string_view seam, double tolerance,
                                     double mitre_limit) {
  SWEEP_EXPECTS((frames == "rmf" || frames == "projection") &&
                    (seam == "full" || seam == "symmetric" || seam == "index" || seam == "none"),
                "evaluation_options: known frames and seam names");
  EvaluationOptions options;
  options.frames.method = frames == "projection" ? FrameMethod::Projection : FrameMethod::RotationMinimizing;
  options.seam = seam == "symmetric" ? SeamMode::Symmetric : SeamMode::Full;
  options.frames.close_seam = seam != "none";
  options.frames.seam_spread = seam == "index" ? SeamSpread::SampleIndex : SeamSpread::ArcLength;
  options.tolerance = tolerance;
  options.mitre_limit = mitre_limit;
  return options;
}

}  // namespace sweep
