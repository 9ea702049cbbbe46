#include "snapshot/run_case.hpp"

#include "render/png_file.hpp"
#include "snapshot/attribution.hpp"
#include "snapshot/references.hpp"

#include <chrono>

namespace sweep::snapshot {
namespace {

namespace fs = std::filesystem;

/// One accepted reference compared with the picture.
struct Candidate {
  Reference reference;
  render::Image image;  // the reference's picture, when it could be read
  std::optional<ImageDiff> diff;
  std::string problem;  // why it could not be compared
};

Candidate compare_with(const Reference& reference, const render::Image& actual, const CaseSpec& spec) {
  Candidate c{reference, {}, std::nullopt, ""};
  render::Image& expected = c.image;
  try {
    expected = render::load_png_file(reference.image);
  } catch (const std::exception& e) {
    c.problem = "reference " + reference.image.filename().string() + " cannot be read: " + e.what();
    return c;
  }
  if (expected.width != actual.width || expected.height != actual.height) {
    c.problem = "reference " + reference.image.filename().string() + " is " + std::to_string(expected.width) + "x" +
                std::to_string(expected.height) + ", the case renders " + std::to_string(actual.width) + "x" +
                std::to_string(actual.height);
    return c;
  }
  c.diff = diff_images(actual, expected, spec.diff);
  return c;
}

/// The passing candidate, else the one with the fewest differing pixels, else the first.
const Candidate& best_of(const std::vector<Candidate>& candidates, const DiffLimits& limits) {
  const Candidate* best = &candidates.front();
  for (const Candidate& c : candidates) {
    if (c.diff && c.diff->passes(limits)) return c;
    if (c.diff && (!best->diff || c.diff->differing_pixels < best->diff->differing_pixels)) best = &c;
  }
  return *best;
}

/// The renderer that made `reference` as its sidecar says ("" when it has none or it is broken).
std::string renderer_of(const Reference& reference, const std::optional<Sidecar>& first,
                        const Reference& first_reference) {
  if (reference.sidecar == first_reference.sidecar) return first ? first->renderer : "";
  try {
    return read_sidecar(reference.sidecar).renderer;
  } catch (const SidecarError&) {
    return "";
  }
}

/// The reference --update rewrites: the one from this renderer, else the first.
Reference to_update(const std::vector<Reference>& references, const std::string& renderer) {
  for (const Reference& r : references) {
    try {
      if (read_sidecar(r.sidecar).renderer == renderer) return r;
    } catch (const SidecarError&) {
    }
  }
  return references.front();
}

/// REPORT/images/NAME-WHAT.png, written; its path relative to REPORT.
std::string report_image(const CaseContext& context, const CaseSpec& spec, const char* what,
                         const render::Image& image) {
  if (context.report.empty()) return "";
  const fs::path relative = fs::path("images") / (spec.name + "-" + what + ".png");
  std::error_code ec;
  fs::create_directories((context.report / relative).parent_path(), ec);  // save_png_file says why if it failed
  render::save_png_file(context.report / relative, image);
  return relative.generic_string();
}

void attach_images(CaseResult& result, const CaseContext& context, const render::Image& actual,
                   const render::Image* reference) {
  if (context.report.empty()) return;
  result.actual_image = report_image(context, result.spec, "actual", actual);
  if (reference == nullptr || result.status == Status::Pass) return;  // a pass shows its picture only
  result.reference_image = report_image(context, result.spec, "reference", *reference);
  if (result.diff && result.diff->same_size) {
    result.diff_image = report_image(context, result.spec, "diff", heat_map(*result.diff, *reference));
  }
}

CaseResult new_case(Worker& worker, const LoadedScene& loaded, const CaseSpec& spec, const CaseContext& context) {
  CaseResult result;
  result.spec = spec;
  const Rendered rendered = worker.render(loaded, spec, fitted_camera(loaded.scene, spec));
  const Reference reference{context.references / (spec.name + ".png"), context.references / (spec.name + ".json")};
  write_reference(reference, rendered.image, rendered.sidecar);
  result.status = Status::New;
  result.message = "new reference " + reference.image.string();
  result.matched_reference = reference.image.filename().string();
  result.references = 1;
  result.render_seconds = rendered.render_seconds;
  attach_images(result, context, rendered.image, nullptr);
  return result;
}

/// The camera of the first reference's sidecar, or a fit (and a note) when it has none.
render::Camera reference_camera(const std::optional<Sidecar>& sidecar, const LoadedScene& loaded,
                                const CaseSpec& spec) {
  return sidecar ? sidecar->camera : fitted_camera(loaded.scene, spec);
}

/// "profile, wineglass".
std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

void judge(CaseResult& result, const Candidate& best, const std::optional<Sidecar>& before, const Sidecar& now,
           const CaseContext& context) {
  const bool passes = best.diff && best.diff->passes(result.spec.limits);
  Attribution attribution;
  if (before) attribution = attribute(*before, now, best.diff ? &*best.diff : nullptr);
  result.changes = attribution.changes;
  if (!passes) {
    result.status = Status::Fail;
    result.message = best.diff ? best.diff->summary() : best.problem;
  } else if (attribution.changed_object_pixels > result.spec.limits.max_diff_pixels) {
    // The allowances for renderer noise do not cover a picture that changed where the model did.
    result.status = Status::Fail;
    result.message = grouped_count(attribution.changed_object_pixels) + " pixels changed where the model changed (" +
                     listed(attribution.changed_objects) + "); " + best.diff->summary();
  } else if (attribution.model_changed) {
    result.status = context.strict_geometry ? Status::Fail : Status::Warning;
    result.message = "geometry changed, not visible from this view (" + best.diff->summary() + ")";
  } else {
    result.status = Status::Pass;
    result.message = best.diff->summary();
    result.changes.clear();
  }
}

CaseResult known_case(Worker& worker, const LoadedScene& loaded, const CaseSpec& spec, const CaseContext& context,
                      const std::vector<Reference>& references) {
  CaseResult result;
  result.spec = spec;
  result.references = int(references.size());
  std::optional<Sidecar> before;
  std::string sidecar_problem;
  try {
    before = read_sidecar(references.front().sidecar);
  } catch (const SidecarError& e) {
    sidecar_problem = e.what();
  }
  const render::Camera camera = reference_camera(before, loaded, spec);
  const Rendered rendered = worker.render(loaded, spec, camera);
  std::vector<Candidate> candidates;
  for (const Reference& r : references) candidates.push_back(compare_with(r, rendered.image, spec));
  const Candidate& best = best_of(candidates, spec.limits);
  result.render_seconds = rendered.render_seconds;
  result.diff = best.diff;
  result.matched_reference = best.reference.image.filename().string();
  const std::string renderer = renderer_of(best.reference, before, references.front());
  result.other_renderer = !renderer.empty() && renderer != worker.renderer_name();
  judge(result, best, before, rendered.sidecar, context);
  if (result.references > 1) {
    result.message += "; compared with " + result.matched_reference + " of " + std::to_string(result.references) +
                      " accepted references";
  }
  if (result.other_renderer) {
    result.message +=
        "; the reference is from another renderer (" + renderer + "): compared with the thresholds, not bit for bit";
  }
  if (!sidecar_problem.empty()) result.changes.push_back({"", "no attribution: sidecar " + sidecar_problem, false});
  const bool rewrite =
      context.update == UpdateMode::All && (result.status == Status::Fail || result.status == Status::Warning);
  if (rewrite) {
    const Reference target = to_update(references, worker.renderer_name());
    write_reference(target, rendered.image, rendered.sidecar);
    result.status = Status::Updated;
    result.message = "updated " + target.image.string() + " (was: " + result.message + ")";
  }
  attach_images(result, context, rendered.image, best.image.empty() ? nullptr : &best.image);
  return result;
}

}  // namespace

CaseResult run_case(Worker& worker, const LoadedScene& loaded, const CaseSpec& spec, const CaseContext& context) {
  const auto start = std::chrono::steady_clock::now();
  CaseResult result;
  result.spec = spec;
  if (!loaded.error.empty()) {
    result.status = Status::Error;
    result.message = loaded.error;
    return result;
  }
  try {
    const std::vector<Reference> references = accepted_references(context.references, spec.name);
    result = references.empty() ? new_case(worker, loaded, spec, context)
                                : known_case(worker, loaded, spec, context, references);
  } catch (const std::exception& e) {  // a reference or report file that cannot be written
    result.status = Status::Error;
    result.message = e.what();
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace sweep::snapshot
