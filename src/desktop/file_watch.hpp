#pragma once
// Noticing that the open file changed on disk: another program saved it in place, or wrote a
// new file and renamed it over this one (as most editors do). Polls the file's modification
// time, size and inode at most every `interval` seconds; a stat() is all a poll costs. A new
// version counts once it has stayed the same for `settle` seconds (polled every settle / 2
// meanwhile), so a file another program is still writing is not read half-written; an empty
// file is taken as a write in progress (the shell's `>file` truncates first) and never counts.
#include <cstdint>
#include <filesystem>
#include <string>

namespace sweep::editor {

/// What identifies one version of a file on disk (all zero when it does not exist).
struct FileStamp {
  std::int64_t modified_ns = 0;
  std::uintmax_t size = 0;
  std::uintmax_t inode = 0;
  bool exists = false;
  bool operator==(const FileStamp&) const = default;
};

/// The stamp of `path` now; never throws.
FileStamp file_stamp(const std::filesystem::path& path);

class FileWatcher {
 public:
  explicit FileWatcher(double interval = 0.25, double settle = 0.1) : interval_(interval), settle_(settle) {}
  /// Watches `path` from its present version ("" watches nothing).
  void watch(const std::string& path);
  /// The version on disk is ours again (we just saved or reloaded it).
  void accept();
  /// At most every interval: true once per new version of the file, once it has been the same
  /// for `settle` seconds (a file that disappears counts only when it comes back: editors delete
  /// before they rename).
  bool changed(double now);
  /// The version read was not the one that settled (it changed while being read): look again.
  void retry() { pending_ = false; }
  /// Seconds until the next poll is due (< 0 when watching nothing).
  double wait_time(double now) const;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
  FileStamp stamp_;
  double interval_;
  double settle_;
  double last_poll_ = -1e300;
  bool pending_ = false;  // a new version seen, not yet settled
  FileStamp pending_stamp_;
  double pending_since_ = 0.0;
};

}  // namespace sweep::editor
