#include "snapshot/run_case.hpp"

#include "render/png_file.hpp"
#include "snapshot/attribution.hpp"
#include "snapshot/references.hpp"
#include "snapshot/stale_references.hpp"

#include <algorithm>
#include <chrono>

namespace sweep::snapshot {
namespace {

namespace fs = std::filesystem;

/// One accepted reference, its sidecar and its comparison with the picture.
struct Candidate {
  Reference reference;
  std::optional<Sidecar> sidecar;
  std::string sidecar_problem;  // why the sidecar could not be read
  render::Image image;          // the reference's picture, when it could be read
  std::optional<ImageDiff> diff;
  std::string problem;  // why it could not be compared

  const std::string& renderer() const {
    static const std::string kUnknown;
    return sidecar ? sidecar->renderer : kUnknown;
  }
};

Candidate read_candidate(const Reference& reference) {
  Candidate c{reference, std::nullopt, "", {}, std::nullopt, ""};
  try {
    c.sidecar = read_sidecar(reference.sidecar);
  } catch (const SidecarError& e) {
    c.sidecar_problem = e.what();
  }
  return c;
}

void compare_with(Candidate& c, const render::Image& actual, const CaseSpec& spec) {
  render::Image& expected = c.image;
  try {
    expected = render::load_png_file(c.reference.image);
  } catch (const std::exception& e) {
    c.problem = "reference " + c.reference.image.filename().string() + " cannot be read: " + e.what();
    return;
  }
  if (expected.width != actual.width || expected.height != actual.height) {
    c.problem = "reference " + c.reference.image.filename().string() + " is " + std::to_string(expected.width) + "x" +
                std::to_string(expected.height) + ", the case renders " + std::to_string(actual.width) + "x" +
                std::to_string(actual.height);
    return;
  }
  c.diff = diff_images(actual, expected, spec.diff);
}

/// The pictures differ only as two renderers' do: the reference is another renderer's, no
/// accepted reference is this renderer's, and its sidecar shows the same model, seen alike.
bool renderer_noise(const Candidate& c, const std::vector<Candidate>& all, const Sidecar& now) {
  const auto mine = [&](const Candidate& other) { return other.renderer() == now.renderer; };
  return c.diff && c.diff->same_size && c.sidecar && !c.renderer().empty() && !mine(c) &&
         std::none_of(all.begin(), all.end(), mine) && same_model(*c.sidecar, now) && same_setup(*c.sidecar, now);
}

/// The passing candidate; else the renderer difference closest to the picture; else the
/// candidate with the fewest differing pixels; else the first.
const Candidate& best_of(const std::vector<Candidate>& candidates, const DiffLimits& limits, const Sidecar& now) {
  const auto fewer = [](const Candidate* best, const Candidate& c) {
    return c.diff && (!best->diff || c.diff->differing_pixels < best->diff->differing_pixels);
  };
  const Candidate* best = &candidates.front();
  const Candidate* noise = nullptr;
  for (const Candidate& c : candidates) {
    if (c.diff && c.diff->passes(limits)) return c;
    if (renderer_noise(c, candidates, now) && (noise == nullptr || fewer(noise, c))) noise = &c;
    if (fewer(best, c)) best = &c;
  }
  return noise != nullptr ? *noise : *best;
}

/// The reference --update writes: the one from this renderer; else, where another renderer made
/// every accepted one, the next NAME_K.png beside them (never another renderer's).
Reference to_update(const std::vector<Candidate>& candidates, const std::string& renderer, const fs::path& folder,
                    const std::string& name) {
  for (const Candidate& c : candidates) {
    if (c.renderer() == renderer) return c.reference;
  }
  return next_reference(folder, name);
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
  result.renderer = worker.renderer_name();
  const Rendered rendered = worker.render(loaded, spec, fitted_camera(loaded.scene, spec));
  const Reference reference = next_reference(context.references, spec.name);
  write_reference(reference, rendered.image, rendered.sidecar);
  result.status = Status::New;
  result.message = "new reference " + reference.image.string();
  if (context.stale != nullptr) result.message += context.stale->renamed_hint(spec.name, rendered.sidecar);
  result.matched_reference = reference.image.filename().string();
  result.accepted = {{result.matched_reference, result.renderer}};
  result.render_seconds = rendered.render_seconds;
  attach_images(result, context, rendered.image, nullptr);
  return result;
}

/// "profile, wineglass".
std::string listed(const std::vector<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out;
}

/// "renderer difference: 1,204 pixels differ ... from bowl-smooth.png (llvmpipe ...), this
/// machine renders with softpipe ...; ...; to add this renderer's reference: COMMAND".
std::string renderer_difference_text(const CaseResult& result, const Candidate& best, const CaseContext& context) {
  return "renderer difference: " + best.diff->summary() + " against " + best.reference.image.filename().string() +
         " made by " + best.renderer() + "; this machine renders with " + result.renderer +
         "; every object, material, the camera and the options are unchanged; to add this renderer's reference: " +
         context.accept_renderer_command;
}

void judge(CaseResult& result, const Candidate& best, const std::vector<Candidate>& all, const Sidecar& now,
           const CaseContext& context) {
  const bool passes = best.diff && best.diff->passes(result.spec.limits);
  Attribution attribution;
  if (best.sidecar) attribution = attribute(*best.sidecar, now, best.diff ? &*best.diff : nullptr);
  result.changes = attribution.changes;
  if (!passes && renderer_noise(best, all, now)) {
    result.renderer_difference = true;
    result.status = context.strict_renderer ? Status::Fail : Status::Warning;
    result.message = renderer_difference_text(result, best, context);
  } else if (!passes) {
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

/// Whether --update rewrites or adds this case's reference.
bool to_accept(const CaseResult& result, UpdateMode update) {
  const bool judged_wrong = result.status == Status::Fail || result.status == Status::Warning;
  return (update == UpdateMode::All && judged_wrong) || (update == UpdateMode::Renderer && result.renderer_difference);
}

void accept(CaseResult& result, const Rendered& rendered, const std::vector<Candidate>& candidates,
            const CaseContext& context) {
  const Reference target = to_update(candidates, result.renderer, context.references, result.spec.name);
  const bool added = std::none_of(candidates.begin(), candidates.end(),
                                  [&](const Candidate& c) { return c.reference.image == target.image; });
  write_reference(target, rendered.image, rendered.sidecar);
  result.status = Status::Updated;
  result.message = (added ? "added " : "updated ") + target.image.string() + (added ? " for " + result.renderer : "") +
                   " (was: " + result.message + ")";
  if (added) result.accepted.push_back({target.image.filename().string(), result.renderer});
}

CaseResult known_case(Worker& worker, const LoadedScene& loaded, const CaseSpec& spec, const CaseContext& context,
                      const std::vector<Reference>& references) {
  CaseResult result;
  result.spec = spec;
  result.renderer = worker.renderer_name();
  std::vector<Candidate> candidates;
  for (const Reference& r : references) candidates.push_back(read_candidate(r));
  const std::optional<Sidecar>& first = candidates.front().sidecar;
  // The first reference's camera, or a fit when it has no sidecar.
  const render::Camera camera = first ? first->camera : fitted_camera(loaded.scene, spec);
  const Rendered rendered = worker.render(loaded, spec, camera);
  for (Candidate& c : candidates) {
    compare_with(c, rendered.image, spec);
    result.accepted.push_back({c.reference.image.filename().string(), c.renderer()});
  }
  const Candidate& best = best_of(candidates, spec.limits, rendered.sidecar);
  result.render_seconds = rendered.render_seconds;
  result.diff = best.diff;
  result.matched_reference = best.reference.image.filename().string();
  result.other_renderer = !best.renderer().empty() && best.renderer() != result.renderer;
  judge(result, best, candidates, rendered.sidecar, context);
  if (result.accepted.size() > 1) {
    result.message += "; compared with " + result.matched_reference + " of " + std::to_string(result.accepted.size()) +
                      " accepted references";
  }
  if (result.other_renderer && !result.renderer_difference) {
    result.message += "; the reference is from another renderer (" + best.renderer() +
                      "): compared with the thresholds, not bit for bit";
  }
  if (!best.sidecar_problem.empty()) {
    result.changes.push_back({"", "no attribution: sidecar " + best.sidecar_problem, false});
  }
  if (to_accept(result, context.update)) accept(result, rendered, candidates, context);
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
  // The per-pixel arrays served the heat map and the attribution; a suite of thousands keeps
  // only the figures.
  if (result.diff) {
    result.diff->distance = std::vector<float>();  // (`= {}` would keep the capacity)
    result.diff->classes = std::vector<PixelClass>();
  }
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace sweep::snapshot
