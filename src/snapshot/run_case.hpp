#pragma once
// One case against its accepted references: render with the reference's camera, compare with
// each accepted reference (the first that passes wins), attribute a failure to named objects,
// report geometry that changed where the picture did not, and write what --update asks.
#include "snapshot/run_render.hpp"
#include "snapshot/run_snapshots.hpp"

#include <filesystem>

namespace sweep::snapshot {

/// Where a case's files go.
struct CaseContext {
  std::filesystem::path references;  // the references folder
  std::filesystem::path report;      // the report folder, or empty
  UpdateMode update = UpdateMode::None;
  bool strict_geometry = false;
};

/// Runs `spec` on `loaded` (which may carry a load error: the case is then an error).
CaseResult run_case(Worker& worker, const LoadedScene& loaded, const CaseSpec& spec, const CaseContext& context);

}  // namespace sweep::snapshot
