#pragma once
// Which cases a run has: every SWP file under DIR in the three modes (zero configuration), or
// the lines of a suite file (DIR/snapshots.txt or --suite FILE). The suite format is documented
// in docs/snapshot-suite.md; a bad suite is one "FILE:LINE:COLUMN: message" SuiteError, its first
// problem.
#include "snapshot/snapshot_case.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

namespace sweep::snapshot {

class SuiteError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;  // what(): "snapshots.txt:3:14: unknown key 'colour' ..."
};

/// Bounds of a suite, so bad input never eats memory: its bytes, the bytes of one line (without
/// the newline), the cases it makes, a name='s bytes, a side of size=WxH and max-diff-pixels.
inline constexpr std::size_t kMaxSuiteBytes = std::size_t{1} << 20;
inline constexpr std::size_t kMaxSuiteLineBytes = 4096;
inline constexpr std::size_t kMaxSuiteCases = 100'000;
inline constexpr std::size_t kMaxSuiteNameBytes = 200;
inline constexpr int kMaxSuiteImageSide = kMaxSnapshotSide;  // the command line's --size too
inline constexpr std::uint64_t kMaxSuiteDiffPixels = std::uint64_t{kMaxSuiteImageSide} * kMaxSuiteImageSide;

/// What the command line sets for every case (a suite line may override each).
using CaseDefaults = CaseOptions;

/// "" when `value` is a valid value of suite key `key` ("size", "T", "threshold", ...), else the
/// suite's message ("expected a rider time T in seconds from 0 to 1e9, found '-1'"). The command
/// line's options are checked with it, so both take the same ranges and say the same.
/// Precondition: `key` is a suite key other than name.
std::string case_value_problem(std::string_view key, std::string_view value);

/// Every .swp file under `dir` (recursively, sorted by relative path, hidden folders and
/// __snapshots__ left out), each in the three modes from the default view.
/// Symlinks are followed, but each real folder is walked once (the first path that reaches it
/// in a walk in name order), so links never loop; folders that cannot be read are left out, and
/// a `dir` that does not exist gives no cases.
std::vector<CaseSpec> cases_in_folder(const std::filesystem::path& dir, const CaseDefaults& defaults);

/// The cases of suite file `suite`, whose file paths are relative to `dir`. Throws SuiteError
/// ("SUITE: cannot read: REASON" when the file cannot be read).
std::vector<CaseSpec> read_suite(const std::filesystem::path& suite, const std::filesystem::path& dir,
                                 const CaseDefaults& defaults);
/// The same from text (`suite` names it in messages).
std::vector<CaseSpec> parse_suite(const std::string& text, const std::filesystem::path& suite,
                                  const std::filesystem::path& dir, const CaseDefaults& defaults);

/// FNV-1a (64 bit) of `name`'s bytes: what shard() sorts a case by.
std::uint64_t case_name_hash(std::string_view name);

/// Shard `k` of `n` (precondition: 1 <= k <= n): the cases whose name hashes (FNV-1a, 64 bit) to k - 1 modulo n,
/// in their order. The n shards partition the cases, and a case stays in its shard when others
/// are added or removed.
std::vector<CaseSpec> shard(const std::vector<CaseSpec>& cases, int k, int n);

}  // namespace sweep::snapshot
