#pragma once
// The suite's files (internal to src/snapshot: suite.cpp): the .swp files below a folder, and the
// files a path pattern matches. Every walk enters each real folder once (by its canonical path), so
// a symlinked folder never leads into a loop; hidden entries and __snapshots__ folders are left out.
#include <cstddef>
#include <filesystem>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace sweep::snapshot {

inline constexpr std::string_view kSwpExtension = ".swp";

bool ends_with_swp(std::string_view name);

/// Every .swp file below `dir`, as paths relative to it with '/', sorted.
std::set<std::string> swp_files_below(const std::filesystem::path& dir);

/// The files a path pattern matches below the suite's folder: the segments of the pattern ('/'
/// between them), each literal, a wildcard segment ('*' and '?' within it, never matching a
/// hidden name or __snapshots__) or "**" (any number of visible folders).
class GlobWalk {
 public:
  GlobWalk(std::vector<std::string> segments, std::size_t limit) : segments_(std::move(segments)), limit_(limit) {}

  /// The matches below `root`, sorted; stops once more than the limit are found.
  const std::set<std::string>& run(const std::filesystem::path& root);
  bool over_limit() const { return matches_.size() > limit_; }

 private:
  void walk(const std::filesystem::path& folder, const std::string& prefix, std::size_t i);
  void add(std::string relative);

  std::vector<std::string> segments_;
  std::size_t limit_;
  std::set<std::string> matches_;
  std::set<std::pair<std::size_t, std::filesystem::path>> seen_;  // (segment, real folder) pairs walked
};

}  // namespace sweep::snapshot
