// The suite's files: the .swp files below a folder and the ones a path pattern (glob) matches,
// each real folder entered once, hidden entries and __snapshots__ folders left out.
#include "snapshot/suite_files.hpp"

#include <algorithm>
#include <system_error>
#include <utility>

namespace sweep::snapshot {

namespace fs = std::filesystem;
namespace {

constexpr std::string_view kReferencesFolder = "__snapshots__";

bool is_hidden(std::string_view name) {
  return !name.empty() && name.front() == '.';
}

/// One visible entry of a folder: hidden entries and __snapshots__ folders are left out, symlinks
/// are followed (a dangling one is left out).
struct Entry {
  std::string name;
  bool folder = false;
  bool file = false;
};

/// The visible entries of `folder` sorted by name; none when it cannot be read.
std::vector<Entry> visible_entries(const fs::path& folder) {
  std::vector<Entry> entries;
  std::error_code ec;
  fs::directory_iterator it(folder, ec);
  for (const fs::directory_iterator end; !ec && it != end; it.increment(ec)) {
    std::string name = it->path().filename().string();
    if (is_hidden(name)) continue;
    std::error_code status_ec;
    const fs::file_status status = it->status(status_ec);
    if (status_ec) continue;
    const bool is_folder = fs::is_directory(status);
    if (is_folder && name == kReferencesFolder) continue;
    entries.push_back({std::move(name), is_folder, fs::is_regular_file(status)});
  }
  std::sort(entries.begin(), entries.end(), [](const Entry& a, const Entry& b) { return a.name < b.name; });
  return entries;
}

/// Whether `folder` is entered for the first time: the walks enter each real folder once (by its
/// canonical path), so a symlinked folder never leads into a loop and the work stays bounded.
bool first_visit(std::set<std::pair<std::size_t, fs::path>>& seen, std::size_t key, const fs::path& folder) {
  std::error_code ec;
  fs::path real = fs::canonical(folder, ec);
  if (ec) return false;
  return seen.insert({key, std::move(real)}).second;
}

/// Every .swp file below `folder` (relative paths with '/', prefixed by `prefix`) into `out`.
void collect_swp_files(const fs::path& folder, const std::string& prefix,
                       std::set<std::pair<std::size_t, fs::path>>& seen, std::set<std::string>& out) {
  for (const Entry& entry : visible_entries(folder)) {
    if (entry.folder) {
      if (first_visit(seen, 0, folder / entry.name)) {
        collect_swp_files(folder / entry.name, prefix + entry.name + "/", seen, out);
      }
    } else if (entry.file && ends_with_swp(entry.name)) {
      out.insert(prefix + entry.name);
    }
  }
}

bool has_wildcard(std::string_view segment) {
  return segment.find_first_of("*?") != std::string_view::npos;
}

/// Whether `name` matches `pattern`, where '*' is any run of bytes and '?' any one byte (the
/// greedy match with one backtrack point: O(size of name × size of pattern) at worst).
bool wildcard_match(std::string_view pattern, std::string_view name) {
  std::size_t p = 0, n = 0;
  std::size_t star = std::string_view::npos, star_n = 0;
  while (n < name.size()) {
    if (p < pattern.size() && (pattern[p] == '?' || pattern[p] == name[n])) {
      ++p;
      ++n;
    } else if (p < pattern.size() && pattern[p] == '*') {
      star = p++;
      star_n = n;
    } else if (star != std::string_view::npos) {
      p = star + 1;
      n = ++star_n;
    } else {
      return false;
    }
  }
  while (p < pattern.size() && pattern[p] == '*') ++p;
  return p == pattern.size();
}

}  // namespace

bool ends_with_swp(std::string_view name) {
  return name.size() >= kSwpExtension.size() && name.substr(name.size() - kSwpExtension.size()) == kSwpExtension;
}

std::set<std::string> swp_files_below(const fs::path& dir) {
  std::set<std::string> files;
  std::set<std::pair<std::size_t, fs::path>> seen;
  if (first_visit(seen, 0, dir)) collect_swp_files(dir, "", seen, files);
  return files;
}

const std::set<std::string>& GlobWalk::run(const fs::path& root) {
  walk(root, "", 0);
  return matches_;
}

void GlobWalk::walk(const fs::path& folder, const std::string& prefix, std::size_t i) {
  if (over_limit() || !first_visit(seen_, i, folder)) return;
  const std::string& segment = segments_[i];
  const bool last = i + 1 == segments_.size();
  if (segment == "**") {
    walk(folder, prefix, i + 1);  // no folder
    for (const Entry& entry : visible_entries(folder)) {
      if (entry.folder) walk(folder / entry.name, prefix + entry.name + "/", i);
    }
  } else if (!has_wildcard(segment)) {
    std::error_code ec;
    const fs::file_status status = fs::status(folder / segment, ec);
    if (ec) return;
    if (last && fs::is_regular_file(status)) add(prefix + segment);
    if (!last && fs::is_directory(status)) walk(folder / segment, prefix + segment + "/", i + 1);
  } else {
    for (const Entry& entry : visible_entries(folder)) {
      if (!wildcard_match(segment, entry.name)) continue;
      if (last && entry.file) add(prefix + entry.name);
      if (!last && entry.folder) walk(folder / entry.name, prefix + entry.name + "/", i + 1);
    }
  }
}

void GlobWalk::add(std::string relative) {
  if (!over_limit()) matches_.insert(std::move(relative));
}

}  // namespace sweep::snapshot
