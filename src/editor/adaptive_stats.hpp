#pragma once
// What adaptive sampling saves, in numbers the stats panel shows: a scene's vertex, triangle and
// curve sample counts, and what sampling the same document by STEPS would give (from the count
// formulas, without evaluating it again).
#include "model/document.hpp"
#include "model/evaluation/scene.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace sweep::editor {

struct SamplingCounts {
  std::int64_t vertices = 0;  // of all surfaces
  std::int64_t triangles = 0;
  std::int64_t curve_samples = 0;  // of all curves
};

/// The counts of an evaluated scene; with `visible` (one flag per object, as
/// ViewStates::visibility gives) only of the visible objects, else of all.
SamplingCounts scene_counts(const Scene& scene, const std::vector<bool>& visible = {});

/// The counts `doc` has when every object is sampled by its STEPS (no tolerance anywhere): the
/// curves' sample counts (curve_sample_count) and the surfaces' grids on them, closed where the
/// evaluated curves in `scene` are closed (closing does not depend on the sampling). With
/// `visible`, only the visible objects are counted (a surface still counts its hidden curves'
/// samples). The triangles of generalized cylinders and birails are an upper bound (their grids
/// leave out triangles of no area, add_quad_without_collapsed). Precondition: `scene` is
/// evaluated from `doc`.
SamplingCounts steps_counts(const Document& doc, const Scene& scene, const std::vector<bool>& visible = {});

/// True if anything in `doc` is sampled for a tolerance: the viewer's (options.tolerance) or a
/// curve's own tolerance clause.
bool any_adaptive(const Document& doc, const EvaluationOptions& options);

/// One line per object that adaptive sampling could not serve (EvaluatedObject::over_limit):
/// over_limit_message and what was done instead ("(sampled by STEPS instead)" for a curve, a
/// surface is meshed on its curves' own samples), for the error and stats panels. Empty if none.
std::vector<std::string> over_limit_messages(const Document& doc, const Scene& scene, double tolerance);

/// What the stats panel shows about sampling, computed from the document and its scene only
/// (count formulas, no evaluation), so it costs a pass over the objects.
struct SamplingSummary {
  bool adaptive = false;                // any_adaptive: `by_steps` is worth showing beside `sampled`
  SamplingCounts sampled;               // as evaluated (visible objects)
  SamplingCounts by_steps;              // the same objects by STEPS
  std::vector<std::string> over_limit;  // over_limit_messages
};
/// Precondition: `scene` is evaluated from `doc` with `options`.
SamplingSummary sampling_summary(const Document& doc, const Scene& scene, const EvaluationOptions& options,
                                 const std::vector<bool>& visible = {});

/// `part` as a whole percentage of `whole` ("31 %"), from 10 times on as a ratio ("25x"); "-"
/// when `whole` is 0.
std::string share_text(std::int64_t part, std::int64_t whole);
/// The summary in one line, as scripted runs print it: "vertices A triangles B curve samples C",
/// each count followed by "(by STEPS N)" when the summary is adaptive.
std::string summary_line(const SamplingSummary& summary);

/// The tolerance slider's range for a scene of size `extent` (document_extent): from the floor,
/// kMinRelativeTolerance * extent, to a tenth of the scene. Both 0 for an empty scene.
struct ToleranceRange {
  double low = 0.0;
  double high = 0.0;
};
ToleranceRange tolerance_range(double extent);

/// The tolerance the Adaptive toggle starts at for a scene of size `extent`: 1e-3 of it.
double default_tolerance(double extent);

// The slider's log scale, done here rather than by ImGuiSliderFlags_Logarithmic: ImGui 1.86
// takes 0.1^precision of the format as "near zero" and reads "%e" as precision -1, so a
// logarithmic "%.2e" slider maps every value below 10 to 10.
/// The tolerance at `position` in [0, 1] on a log scale from range.low to range.high, rounded to
/// the 3 significant digits tolerance_text shows (what the slider shows is what is used) and kept
/// within the range. Precondition: 0 < range.low <= range.high.
double tolerance_at(const ToleranceRange& range, double position);
/// Where `tolerance` sits on that scale, clamped to [0, 1]. Precondition as tolerance_at.
double slider_position(const ToleranceRange& range, double tolerance);
/// The tolerance as the slider shows it: "5.57e-03".
std::string tolerance_text(double tolerance);

}  // namespace sweep::editor
