#pragma once
// One case against its accepted references: render with the reference's camera, compare with
// each accepted reference (the first that passes wins), attribute a failure to named objects,
// report geometry that changed where the picture did not, and write what --update asks.
#include "snapshot/run_render.hpp"
#include "snapshot/run_snapshots.hpp"

#include <filesystem>

namespace sweep::snapshot {

class StaleReferences;

/// Where a case's files go and what the run was asked.
struct CaseContext {
  std::filesystem::path references;  // the references folder
  std::filesystem::path report;      // the report folder, or empty
  UpdateMode update = UpdateMode::None;
  bool strict_geometry = false;
  bool strict_renderer = false;
  /// The command that accepts this machine's pictures where they are renderer differences
  /// ("sweep snapshot models --update=renderer"), which ends their warning.
  std::string accept_renderer_command;
  /// References that belong to no case, for "looks like OLD (renamed?)"; may be null.
  const StaleReferences* stale = nullptr;
};

/// Runs `spec` on `loaded` (which may carry a load error: the case is then an error).
CaseResult run_case(Worker& worker, const LoadedScene& loaded, const CaseSpec& spec, const CaseContext& context);

}  // namespace sweep::snapshot
