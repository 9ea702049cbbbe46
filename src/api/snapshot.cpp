#include "api/document_state.hpp"

#include "api/thread_worker.hpp"
#include "snapshot/run_case.hpp"

#include <sweep/snapshot.hpp>

#include <memory>

// One `sweep snapshot` case for a document in memory: the runner's own run_case, so a program's
// check and the command's agree.

namespace sweep::v0 {
namespace {}  // namespace

namespace detail {

::sweep::snapshot::Mode mode_named(const std::string& mode) {
  if (const auto value = ::sweep::snapshot::named(::sweep::snapshot::kEveryMode, mode)) return *value;
  throw Error("mode must be smooth, wire or frames, not '" + mode + "'");
}

::sweep::render::ColorMode color_named(const std::string& color) {
  if (const auto value = ::sweep::snapshot::named(::sweep::render::kColorModes, color)) return *value;
  throw Error("color must be material, gaussian, mean, normals or uv, not '" + color + "'");
}

::sweep::snapshot::Worker& thread_worker() {
  thread_local std::unique_ptr<::sweep::snapshot::Worker> worker;
  if (worker == nullptr) worker = std::make_unique<::sweep::snapshot::Worker>();
  return *worker;
}

/// The document's loaded scene, as the runner takes it.
::sweep::snapshot::LoadedScene loaded_scene(const DocumentState& s) {
  return {s.doc, *s.scene, s.file.empty() ? std::filesystem::path() : s.file.parent_path(), ""};
}

}  // namespace detail

SnapshotResult check_snapshot(const Document& doc, const std::filesystem::path& folder, const std::string& name,
                              const SnapshotOptions& options) {
  namespace snap = ::sweep::snapshot;
  snap::CaseSpec spec;
  spec.mode = detail::mode_named(options.mode);
  spec.name = name + "-" + snap::name_of(spec.mode);
  spec.file = doc.file();
  spec.relative = doc.file().filename();
  spec.size = {options.width, options.height};
  spec.diff.threshold = options.threshold;
  spec.limits.max_diff_pixels = options.max_diff_pixels;
  if (options.width < 1 || options.height < 1 || options.width > snap::kMaxSnapshotSide ||
      options.height > snap::kMaxSnapshotSide) {
    throw Error("a snapshot is 1 to " + std::to_string(snap::kMaxSnapshotSide) + " pixels a side");
  }
  snap::CaseContext context;
  context.references = folder;
  context.update = options.update ? snap::UpdateMode::All : snap::UpdateMode::None;
  context.accept_renderer_command = "check_snapshot(..., update=True)";
  snap::CaseResult result;
  try {
    result =
        snap::run_case(detail::thread_worker(), detail::loaded_scene(detail::DocumentState::of(doc)), spec, context);
  } catch (...) {
    detail::throw_public_error();
  }
  SnapshotResult out;
  out.status = snap::name_of(result.status);
  out.passed = result.status == snap::Status::Pass || result.status == snap::Status::Warning ||
               result.status == snap::Status::Updated || (result.status == snap::Status::New && options.update);
  out.message = result.message;
  for (const snap::ObjectChange& change : result.changes) {
    out.objects.push_back(change.text);
    if (change.changed && !change.object.empty()) out.changed_objects.push_back(change.object);
  }
  out.reference = folder / (result.matched_reference.empty() ? spec.name + ".png" : result.matched_reference);
  return out;
}

}  // namespace sweep::v0
