#pragma once
// What Sweep says about a document in words: the one text behind `sweep info`, the viewer's
// stats panel and the export's fold warnings.
#include "geometry/surfaces/surface.hpp"
#include "model/document.hpp"
#include "model/evaluation/scene.hpp"

#include <string>
#include <vector>

namespace sweep::editor {

/// "t = 1.20 to 1.45, t = 3.00 to 3.10": the parameter ranges of the folds.
std::string fold_ranges(const std::vector<FoldRange>& folds);

/// "closed sweep, seam angle 12.00 deg, total twist 30.00 deg, no folds" (or "folds at ...").
std::string sweep_diagnostics_text(const SweepDiagnostics& diagnostics);

/// What a surface is made of: "profile P, sweep S" (gcyl; then ", scale C", ", twist 90 deg" or
/// ", twist C" and ", caps" when given), "profile P, rails R1 and R2" (birail; ", height"),
/// "profile P" (srev; ", caps"). Files without the clauses read as before.
std::string surface_sources_text(const Document& doc, int index);

/// The export's warning for a surface that folds over itself.
std::string fold_warning(const std::string& name, const SweepDiagnostics& diagnostics);

/// `sweep info`: "FILE: N objects", then a line per object (two for a generalized cylinder,
/// the second its sweep_diagnostics_text). With options.tolerance > 0 the first line says so and
/// every object's line ends with its measured deviation (deviation.hpp). Precondition: `scene`
/// is evaluated from `doc` with `options`.
std::string document_summary(const Document& doc, const Scene& scene, const std::string& file,
                             const EvaluationOptions& options = {});

/// Why object `index` was sampled by STEPS instead of for `tolerance` (EvaluatedObject::over_limit):
/// "tolerance D is too small for 'NAME': it needs more than N samples or M vertices; use a larger one".
std::string over_limit_message(const Document& doc, int index, double tolerance);

}  // namespace sweep::editor
