#pragma once
// Which cases a run has: every SWP file under DIR in the three modes (zero configuration), or
// the lines of a suite file (DIR/snapshots.txt or --suite FILE). The suite format is documented
// in docs/snapshot.md; every bad line is one "FILE:LINE:COLUMN: message" SuiteError.
#include "snapshot/snapshot_case.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

namespace sweep::snapshot {

class SuiteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;  // what(): "snapshots.txt:3:14: unknown key 'colour' ..."
};

/// What the command line sets for every case (a suite line may override each).
struct CaseDefaults {
  glm::ivec2 size{320, 240};
  double tolerance = 0.0;
  std::string frames = "rmf";
  std::string seam = "full";
  double time = 0.0;
  DiffOptions diff;
  DiffLimits limits;
};

/// Every .swp file under `dir` (recursively, sorted by relative path, hidden folders and
/// __snapshots__ left out), each in the three modes from the default view.
std::vector<CaseSpec> cases_in_folder(const std::filesystem::path& dir, const CaseDefaults& defaults);

/// The cases of suite file `suite`, whose file paths are relative to `dir`. Throws SuiteError.
std::vector<CaseSpec> read_suite(const std::filesystem::path& suite, const std::filesystem::path& dir,
                                 const CaseDefaults& defaults);
/// The same from text (`suite` names it in messages).
std::vector<CaseSpec> parse_suite(const std::string& text, const std::filesystem::path& suite,
                                  const std::filesystem::path& dir, const CaseDefaults& defaults);

/// Shard `k` of `n` (1 <= k <= n): the cases whose name hashes (FNV-1a, 64 bit) to k - 1 modulo n,
/// in their order. The n shards partition the cases, and a case stays in its shard when others
/// are added or removed.
std::vector<CaseSpec> shard(const std::vector<CaseSpec>& cases, int k, int n);

}  // namespace sweep::snapshot
