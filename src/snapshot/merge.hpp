#pragma once
// `sweep snapshot merge DIR... --report OUT [--junit FILE]`: the shards of one suite, each run
// with --report DIRk, put back together into the report, results file and JUnit XML one
// unsharded run would have written (cases in the suite's order, images carried along), with the
// exit status that run would have had. Needs no GL.
#include <filesystem>
#include <vector>

namespace sweep::snapshot {

struct MergeOptions {
  std::vector<std::filesystem::path> shards;  // report folders (or their results.json files)
  std::filesystem::path report;               // where the merged report goes
  std::filesystem::path junit;                // empty: no JUnit XML
};

/// Returns the exit status the unsharded run would have had (0, 1 or 2), or 2 with one message
/// on stderr when the shards cannot be merged: a missing or unreadable results file, shards of
/// different splits, a case in two shards, or shards missing (the message names them).
int merge_reports(const MergeOptions& options);

}  // namespace sweep::snapshot
