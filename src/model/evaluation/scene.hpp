#pragma once
// A document turned into geometry: one entry per object, in document order. Each entry has a
// revision that grows when it is re-evaluated, so a renderer re-uploads only what changed.
#include "geometry/curves/curve.hpp"
#include "geometry/mesh/mesh.hpp"
#include "geometry/surfaces/rider_track.hpp"
#include "geometry/surfaces/surface.hpp"
#include "model/document.hpp"

#include <atomic>
#include <cstdint>
#include <string_view>
#include <vector>

namespace sweep {

struct EvaluatedObject {
  CurveSamples curve;            // curves only
  Mesh mesh;                     // surfaces only
  RiderTrack track;              // riders only: their path prepared for riding (model/evaluation/riders.hpp)
  SweepDiagnostics diagnostics;  // gcyl only
  std::uint64_t revision = 0;
  /// Adaptive sampling would have passed a sample or vertex cap (limits.hpp): the object was
  /// sampled by its STEPS instead; the tolerance is too small for it.
  bool over_limit = false;
  /// Lines drawn with the object, as pairs of positions: the control net of a patch or mesh
  /// (shown with the control points), or the cage of a subd (shown with the wireframe).
  std::vector<glm::vec3> net;
  enum class NetRole : std::uint8_t { None, ControlNet, Cage };
  NetRole net_role = NetRole::None;
};

/// Which surfaces get texture coordinates (Mesh::uvs): only those whose material puts an image
/// on them (a checker, texture or bump: what the viewer and renders draw), or every surface (what
/// the OBJ and glb exports write, and the uv colour mode shows). Nothing else reads them.
enum class TextureCoordinates : std::uint8_t { WhereTextured, Everywhere };

struct EvaluationOptions {
  FrameOptions frames;
  TextureCoordinates texture_coordinates = TextureCoordinates::WhereTextured;
  SeamMode seam = SeamMode::Full;  // how generalized cylinders along closed sweeps close
  /// Sweep corners whose mitre would stretch the profile more than this are bevelled (>= 1).
  double mitre_limit = kMitreLimit;
  /// > 0: sample every curve and surface adaptively so it stays within this distance of the
  /// exact one (overrides the curves' own tolerance clauses); 0: by STEPS and the clauses.
  /// A surface spends kSurfaceShare of it on its profile and as much on its sweep (or turn).
  double tolerance = 0.0;
};

/// The options the command line's names give: frames "rmf" | "projection", seam "full" |
/// "symmetric" | "index" | "none" (sweep export, render, view and snapshot share the names).
/// Precondition: both names are among those.
EvaluationOptions evaluation_options(std::string_view frames, std::string_view seam, double tolerance = 0.0,
                                     double mitre_limit = kMitreLimit);

/// The share of a surface's tolerance given to its profile, and the same to its sweep or turn.
inline constexpr double kSurfaceShare = 0.46;

struct Scene {
  std::vector<EvaluatedObject> objects;  // objects[i] belongs to Document::objects[i]
};

/// The curves a surface's mesh is built from: its profile and sweep (gcyl) as sampled for it, and
/// the turn's copies (srev). With options.tolerance they are sampled for the surface (half the
/// tolerance each, see EvaluationOptions); otherwise they are the scene's curves and STEPS.
struct SurfaceSampling {
  CurveSamples profile;
  CurveSamples sweep;  // gcyl; birail: the first rail
  CurveSamples rail2;  // birail only
  int copies = 0;      // srev only
  bool over_limit = false;
};
/// Precondition: doc.objects[index] is a swept surface (srev, gcyl, birail) and `scene` holds the
/// evaluated objects before it.
SurfaceSampling surface_sampling(const Document& doc, const Scene& scene, int index, const EvaluationOptions& options);

/// Evaluates every object. Precondition: the document is valid (parsed or validated).
Scene evaluate_document(const Document& doc, const EvaluationOptions& options = {});

/// Evaluates every object into `scene`, reusing the buffers of the meshes it holds (a
/// re-evaluation of the same document allocates nothing new), and bumps every revision.
/// Precondition: the document is valid (parsed or validated).
void reevaluate_all(Scene& scene, const Document& doc, const EvaluationOptions& options = {});

/// Indices of the objects that depend on object `index` (directly or not), `index` first,
/// in document order after it.
std::vector<int> dependents_of(const Document& doc, int index);

/// Re-evaluates object `index` and everything that depends on it, bumping their revisions.
/// Returns the indices re-evaluated.
std::vector<int> reevaluate(Scene& scene, const Document& doc, int index, const EvaluationOptions& options = {});

/// How far evaluate_objects got, shared with another thread: it stops before its next object once
/// `cancel` is set, and counts the objects it has done.
struct EvaluationProgress {
  std::atomic<bool> cancel{false};
  std::atomic<int> done{0};
};

/// Evaluates the objects `indices` of `doc` into `scene`, in that order, bumping their revisions;
/// each reads the entries of the objects it refers to. Returns false when `progress` was
/// cancelled (the entries not reached keep what they held). Precondition: the document is valid,
/// scene.objects.size() == doc.objects.size(), the indices are in document order and every
/// object they refer to is evaluated in `scene` or comes earlier in `indices`.
bool evaluate_objects(Scene& scene, const Document& doc, const std::vector<int>& indices,
                      const EvaluationOptions& options, EvaluationProgress* progress = nullptr);

/// A revision that no evaluation has given, for an entry that holds nothing yet: renderers see
/// a new revision and drop what they had at its place.
std::uint64_t new_scene_revision();

}  // namespace sweep
