#pragma once
// A document turned into geometry: one entry per object, in document order. Each entry has a
// revision that grows when it is re-evaluated, so a renderer re-uploads only what changed.
#include "core/curve.hpp"
#include "core/document.hpp"
#include "core/mesh.hpp"
#include "core/surface.hpp"

#include <cstdint>
#include <vector>

namespace sweep {

struct EvaluatedObject {
  CurveSamples curve;            // curves only
  Mesh mesh;                     // surfaces only
  SweepDiagnostics diagnostics;  // gcyl only
  std::uint64_t revision = 0;
};

struct EvaluationOptions {
  FrameOptions frames;
  SeamMode seam = SeamMode::Full;  // how generalized cylinders along closed sweeps close
};

struct Scene {
  std::vector<EvaluatedObject> objects;  // objects[i] belongs to Document::objects[i]
};

/// Evaluates every object. Precondition: the document is valid (parsed or validated).
Scene evaluate_document(const Document& doc, const EvaluationOptions& options = {});

/// Indices of the objects that depend on object `index` (directly or not), `index` first,
/// in document order after it.
std::vector<int> dependents_of(const Document& doc, int index);

/// Re-evaluates object `index` and everything that depends on it, bumping their revisions.
/// Returns the indices re-evaluated.
std::vector<int> reevaluate(Scene& scene, const Document& doc, int index, const EvaluationOptions& options = {});

}  // namespace sweep
