#pragma once
// The recent files list, kept across runs in the config folder (recent-files.txt: one absolute
// path a line, newest first, at most kMaxRecentFiles).
#include <deque>
#include <filesystem>
#include <string>

namespace sweep::editor {

inline constexpr std::size_t kMaxRecentFiles = 10;

/// `path` made absolute and put first; a repeat moves up; the list keeps kMaxRecentFiles.
void remember_recent(std::deque<std::string>& recent, const std::string& path);

/// Reads the list from `file`; a missing file is an empty list; unreadable lines are skipped.
std::deque<std::string> load_recent(const std::filesystem::path& file);
/// Writes the list atomically. Returns "" or why not; never throws.
std::string save_recent(const std::filesystem::path& file, const std::deque<std::string>& recent);

}  // namespace sweep::editor
