#pragma once
// `sweep snapshot`: renders the cases through OSMesa (one context per worker), compares each with
// its accepted references, attributes failures to named objects, writes what --update asks and
// the reports. Returns the process exit code: 0 all pass, 1 any failed (or is new without
// --update), 2 usage or input errors.
#include "snapshot/suite.hpp"

#include <filesystem>
#include <string>

namespace sweep::snapshot {

enum class UpdateMode { None, Missing, All };

struct RunOptions {
  std::filesystem::path dir;         // the models
  std::filesystem::path suite;       // empty: DIR/snapshots.txt when it exists, else every file
  std::filesystem::path references;  // empty: DIR/__snapshots__
  std::filesystem::path report;      // empty: no HTML report
  std::filesystem::path junit;       // empty: no JUnit XML
  UpdateMode update = UpdateMode::None;
  bool prune = false;
  bool strict_geometry = false;
  int shard_k = 1;
  int shard_n = 1;
  int jobs = 0;  // 0: the cores
  CaseDefaults defaults;
  bool quiet = false;  // no progress count
};

int run_snapshots(const RunOptions& options);

}  // namespace sweep::snapshot
