#pragma once
// What adaptive sampling saves, in numbers the stats panel shows: a scene's vertex, triangle and
// curve sample counts, and what sampling the same document by STEPS would give (from the count
// formulas, without evaluating it again).
#include "core/document.hpp"
#include "core/scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace sweep::editor {

struct SamplingCounts {
  std::int64_t vertices = 0;  // of all surfaces
  std::int64_t triangles = 0;
  std::int64_t curve_samples = 0;  // of all curves
};

/// The counts of an evaluated scene.
SamplingCounts scene_counts(const Scene& scene);

/// The counts `doc` has when every object is sampled by its STEPS (no tolerance anywhere): the
/// curves' sample counts (curve_sample_count) and the surfaces' grids on them, closed where the
/// evaluated curves in `scene` are closed (closing does not depend on the sampling).
/// Precondition: `scene` is evaluated from `doc`.
SamplingCounts steps_counts(const Document& doc, const Scene& scene);

/// One line per object that adaptive sampling could not serve (EvaluatedObject::over_limit):
/// over_limit_message, for the error panel. Empty if none.
std::vector<std::string> over_limit_messages(const Document& doc, const Scene& scene, double tolerance);

/// The tolerance slider's range for a scene of size `extent` (document_extent): from the floor,
/// kMinRelativeTolerance * extent, to a tenth of the scene. Both 0 for an empty scene.
struct ToleranceRange {
  double low = 0.0;
  double high = 0.0;
};
ToleranceRange tolerance_range(double extent);

}  // namespace sweep::editor
