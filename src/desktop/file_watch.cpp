#include "desktop/file_watch.hpp"

#include <sys/stat.h>

namespace sweep::editor {

FileStamp file_stamp(const std::filesystem::path& path) {
  FileStamp stamp;
  struct stat info {};
  if (path.empty() || ::stat(path.c_str(), &info) != 0) return stamp;
  stamp.modified_ns =
      static_cast<std::int64_t>(info.st_mtim.tv_sec) * 1'000'000'000 + static_cast<std::int64_t>(info.st_mtim.tv_nsec);
  stamp.size = static_cast<std::uintmax_t>(info.st_size);
  stamp.inode = static_cast<std::uintmax_t>(info.st_ino);
  stamp.exists = true;
  return stamp;
}

void FileWatcher::watch(const std::string& path) {
  path_ = path;
  stamp_ = file_stamp(path_);
  last_poll_ = -1e300;
}

void FileWatcher::accept() {
  stamp_ = file_stamp(path_);
  pending_ = false;
}

bool FileWatcher::changed(double now) {
  const double interval = pending_ ? 0.5 * settle_ : interval_;
  if (path_.empty() || now - last_poll_ < interval) return false;
  last_poll_ = now;
  const FileStamp stamp = file_stamp(path_);
  // Gone or empty for now (editors delete before they rename, `>file` truncates before it
  // writes; an empty file would read as an empty document): keep the old stamp until it is back.
  if (!stamp.exists || stamp.size == 0) return false;
  if (stamp == stamp_) {
    pending_ = false;  // back to the version we have
    return false;
  }
  if (!pending_ || stamp != pending_stamp_) {  // new, or changed again since: wait for it to settle
    pending_ = true;
    pending_stamp_ = stamp;
    pending_since_ = now;
  }
  if (now - pending_since_ < settle_) return false;
  stamp_ = stamp;
  pending_ = false;
  return true;
}

double FileWatcher::wait_time(double now) const {
  if (path_.empty()) return -1.0;
  const double wait = last_poll_ + (pending_ ? 0.5 * settle_ : interval_) - now;
  return wait > 0.0 ? wait : 0.0;
}

}  // namespace sweep::editor
