#pragma once
// `sweep snapshot`: renders the cases through OSMesa (one context per worker), compares each with
// its accepted references, attributes failures to named objects, writes what --update asks and
// the reports (and the result file that `sweep snapshot merge` reads). Returns the process exit
// code: 0 all pass (warnings allowed), 1 a failure or an unaccepted new reference, 2 a usage,
// suite or input error.
#include "snapshot/suite.hpp"

#include <filesystem>
#include <string>

namespace sweep::snapshot {

/// --update: rewrite what failed or warned and write what is new (All), only write what is new
/// (Missing), or only add this renderer's references where a case is a renderer difference
/// (Renderer: never accepts a model change).
enum class UpdateMode { None, Missing, All, Renderer };

struct RunOptions {
  std::filesystem::path dir;         // the models
  std::filesystem::path suite;       // empty: DIR/snapshots.txt when it exists, else every file
  std::filesystem::path references;  // empty: DIR/__snapshots__
  std::filesystem::path report;      // empty: no HTML report
  std::filesystem::path junit;       // empty: no JUnit XML
  UpdateMode update = UpdateMode::None;
  bool prune = false;
  bool dry_run = false;  // with prune: list what it would delete, delete nothing
  bool strict_geometry = false;
  bool strict_renderer = false;  // a renderer difference fails instead of warning
  std::string rename_from;       // --rename OLD NEW: move case OLD's references to NEW, render nothing
  std::string rename_to;
  int shard_k = 1;
  int shard_n = 1;
  int jobs = 0;  // 0: the cores
  CaseDefaults defaults;
  bool quiet = false;  // no progress count
};

int run_snapshots(const RunOptions& options);

}  // namespace sweep::snapshot
