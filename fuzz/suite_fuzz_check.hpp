#pragma once
// The properties the suite fuzzer checks on every input, shared by the libFuzzer harness
// (suite_fuzzer.cpp) and the test that replays the seeds (tests/snapshot/suite_test.cpp). Header
// only, so the snapshot tests reach it without a source of their own.
#include "snapshot/suite.hpp"

#include <algorithm>
#include <exception>
#include <filesystem>
#include <fstream>
#include <set>
#include <string>
#include <string_view>
#include <system_error>

namespace sweep::fuzz {

/// The models folder the fuzzed suites' paths are read against: visible, hidden and
/// __snapshots__ files, nested folders, a name with a space, and a symlink back up (a loop).
inline void make_suite_fuzz_models(const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  for (const char* file : {"a.swp", "b.swp", "with space.swp", "notes.txt", "sub/c.swp", "sub/deep/d.swp",
                           ".hidden.swp", ".git/e.swp", "__snapshots__/f.swp"}) {
    fs::create_directories((dir / file).parent_path());
    std::ofstream(dir / file) << "bsp3 . 4 [0 0] [1 0] [1 1] [0 1]\n";
  }
  std::error_code ec;
  fs::create_directory_symlink("..", dir / "sub" / "loop", ec);  // sub/loop/sub/loop/... if followed blindly
}

/// Runs every check on `bytes` as a suite whose paths are relative to `dir`:
///  - parse_suite either returns cases or throws SuiteError whose message is one line starting
///    "fuzz.txt:LINE:COLUMN: " with LINE and COLUMN >= 1 (no other exception);
///  - the cases are at most kMaxSuiteCases, their names unique, each ending in its mode, each
///    file a .swp below `dir`, every value within the documented ranges;
///  - three shards partition them.
/// Returns an empty string if all hold, otherwise a description of the first violation.
inline std::string check_suite_input(std::string_view bytes, const std::filesystem::path& dir) {
  using namespace sweep::snapshot;
  std::vector<CaseSpec> cases;
  try {
    cases = parse_suite(std::string(bytes), "fuzz.txt", dir, CaseDefaults{});
  } catch (const SuiteError& e) {
    const std::string message = e.what();
    const std::string_view prefix = "fuzz.txt:";
    if (message.rfind(prefix, 0) != 0) return "a suite error not starting with the suite's name: " + message;
    if (message.find('\n') != std::string::npos) return "a suite error of more than one line: " + message;
    const auto digit = [&](std::size_t at, char lowest) {
      return at < message.size() && message[at] >= lowest && message[at] <= '9';
    };
    std::size_t i = prefix.size();
    for (int field = 0; field < 2; ++field) {  // LINE, then COLUMN: a number from 1, then ':'
      if (!digit(i, '1')) return "a suite error without LINE:COLUMN: " + message;
      while (digit(i, '0')) ++i;
      if (i >= message.size() || message[i] != ':') return "a suite error without LINE:COLUMN: " + message;
      ++i;
    }
    if (message.compare(i, 1, " ") != 0 || message.size() == i + 1)
      return "a suite error without a message: " + message;
    return {};
  } catch (const std::exception& e) {
    return std::string("parse_suite threw something other than SuiteError: ") + e.what();
  }
  if (cases.size() > kMaxSuiteCases) return "more than kMaxSuiteCases cases";
  std::set<std::string> names;
  for (const CaseSpec& c : cases) {
    if (!names.insert(c.name).second) return "two cases named '" + c.name + "'";
    const std::string mode = std::string("-") + name_of(c.mode);
    if (c.name.size() <= mode.size() || c.name.compare(c.name.size() - mode.size(), mode.size(), mode) != 0) {
      return "case '" + c.name + "' does not end in its mode";
    }
    const std::string relative = c.relative.generic_string();
    if (relative.empty() || relative.front() == '/' || relative.find("..") != std::string::npos ||
        c.relative.extension() != ".swp" || c.file != dir / c.relative) {
      return "case '" + c.name + "' has the file '" + relative + "'";
    }
    std::error_code ec;
    if (!std::filesystem::is_regular_file(c.file, ec)) return "case '" + c.name + "' names a missing file";
    const auto in = [](double v, double lo, double hi) { return v >= lo && v <= hi; };
    if (!in(c.size.x, 1, kMaxSuiteImageSide) || !in(c.size.y, 1, kMaxSuiteImageSide) || !in(c.diff.threshold, 0, 1) ||
        !in(c.diff.shift, 0, 3) || !in(c.limits.max_diff_ratio, 0, 1) ||
        c.limits.max_diff_pixels > kMaxSuiteDiffPixels || !(c.tolerance >= 0) || !(c.time >= 0) ||
        (c.view.pitch && !in(*c.view.pitch, -90, 90)) || (c.view.distance && !(*c.view.distance > 0))) {
      return "case '" + c.name + "' has a value out of range";
    }
  }
  std::size_t sharded = 0;
  for (int k = 1; k <= 3; ++k) sharded += shard(cases, k, 3).size();
  if (sharded != cases.size()) return "three shards do not partition the cases";
  return {};
}

}  // namespace sweep::fuzz
