#pragma once
// References that belong to no case of the suite: named in the run's summary (the first few),
// listed whole by `--prune --dry-run`, deleted by `--prune`, and compared with each new case, so a
// renamed model says which old references are its own ("looks like OLD (renamed?)").
#include "snapshot/sidecar.hpp"

#include <filesystem>
#include <mutex>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace sweep::snapshot {

class StaleReferences {
 public:
  /// The reference files under `folder` that belong to no case in `names`. `command` starts the
  /// commands the messages show ("sweep snapshot models").
  StaleReferences(const std::filesystem::path& folder, const std::set<std::string>& names, std::string command);

  const std::vector<std::filesystem::path>& files() const { return files_; }

  /// "; looks like OLD (renamed?): move its references with `COMMAND --rename OLD NAME`" when a
  /// stale case's first sidecar shows the same model (same objects, geometry and materials) in
  /// the same mode, colour, view and size as `now`; else "". Safe to call from several workers:
  /// the stale sidecars are read on the first call.
  std::string renamed_hint(const std::string& name, const Sidecar& now) const;

  /// "12 reference files belong to no case: a-smooth.png, ... (and 7 more); ..." or "".
  std::string summary() const;

 private:
  std::filesystem::path folder_;
  std::vector<std::filesystem::path> files_;
  std::string command_;
  mutable std::once_flag read_once_;
  mutable std::vector<std::pair<std::string, Sidecar>> sidecars_;  // stale case, its first sidecar
};

/// `--prune`: deletes `files` (or, with `dry_run`, only lists them), one line each on stdout.
void prune(const std::vector<std::filesystem::path>& files, bool dry_run);

}  // namespace sweep::snapshot
