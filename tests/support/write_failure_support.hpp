#pragma once
// Every write fails in turn (issue 29): runs an output once to count the system calls it makes
// (io/files/file_faults.hpp) and to learn what it writes, then once more for every call kind and every
// k up to that count with the k-th call failing with ENOSPC, each time from the same folder as
// before, and checks what must hold after any failure: the output reports it, every file in the
// folder holds its old bytes or its complete new ones, and no other file (a temporary) is there.
#include "io/files/file_faults.hpp"

#include <gtest/gtest.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <string>

namespace sweep::test {

/// What an output did: whether it succeeded, and its message when not.
struct WriteOutcome {
  bool ok = true;
  std::string message;
};

using FolderContents = std::map<std::string, std::string>;

/// The regular files of `folder` (not recursive) and their bytes, by file name.
inline FolderContents folder_contents(const std::filesystem::path& folder) {
  FolderContents contents;
  for (const auto& entry : std::filesystem::directory_iterator(folder)) {
    std::ifstream in(entry.path(), std::ios::binary);
    contents[entry.path().filename().string()] = std::string(std::istreambuf_iterator<char>(in), {});
  }
  return contents;
}

/// Makes `folder` hold exactly `contents`.
inline void restore_folder(const std::filesystem::path& folder, const FolderContents& contents) {
  for (const auto& entry : std::filesystem::directory_iterator(folder)) std::filesystem::remove_all(entry.path());
  for (const auto& [name, bytes] : contents) std::ofstream(folder / name, std::ios::binary) << bytes;
}

inline const char* call_name(io::FileCall call) {
  static const char* const names[] = {"create", "write", "fsync", "close", "rename"};
  return names[static_cast<int>(call)];
}

/// The check above for `write`, which writes into `folder` (holding the old files already) and
/// reports failure by its outcome. `all_or_nothing`: the files are old all together or new all
/// together (a multi-file export); otherwise each file is old or new on its own. `expect_failure`
/// checks each failure's message (and anything else the caller keeps, such as an unsaved flag).
/// Returns the number of failures injected.
inline int expect_every_failure_leaves_old_or_new(const std::filesystem::path& folder,
                                                  const std::function<WriteOutcome()>& write,
                                                  const std::function<void(const WriteOutcome&)>& expect_failure,
                                                  bool all_or_nothing = false) {
  const FolderContents before = folder_contents(folder);
  io::reset_file_calls();
  const WriteOutcome fine = write();
  EXPECT_TRUE(fine.ok) << fine.message;
  const FolderContents after = folder_contents(folder);
  EXPECT_NE(before, after) << "the output wrote nothing";
  std::int64_t counts[io::kFileCallCount];
  for (int c = 0; c < io::kFileCallCount; ++c) counts[c] = io::file_calls(static_cast<io::FileCall>(c));
  EXPECT_GE(counts[static_cast<int>(io::FileCall::Write)], 1);
  int injected = 0;
  for (int c = 0; c < io::kFileCallCount; ++c) {
    const auto call = static_cast<io::FileCall>(c);
    for (std::int64_t k = 1; k <= counts[c]; ++k) {
      SCOPED_TRACE(std::string("failing ") + call_name(call) + " call " + std::to_string(k));
      restore_folder(folder, before);
      WriteOutcome failed;
      {
        const io::ScopedFileFault fault(call, k, ENOSPC);
        failed = write();
        EXPECT_TRUE(fault.injected());
      }
      ++injected;
      EXPECT_FALSE(failed.ok);
      EXPECT_NE(failed.message.find(std::strerror(ENOSPC)), std::string::npos) << failed.message;
      expect_failure(failed);
      const FolderContents now = folder_contents(folder);
      if (all_or_nothing) {
        EXPECT_TRUE(now == before || now == after) << "a mix of old and new files";
      }
      for (const auto& [name, bytes] : now) {
        const auto old_file = before.find(name);
        const auto new_file = after.find(name);
        const bool old_bytes = old_file != before.end() && old_file->second == bytes;
        const bool new_bytes = new_file != after.end() && new_file->second == bytes;
        EXPECT_TRUE(old_bytes || new_bytes) << name << " is neither the old file nor the new one (a temporary?)";
      }
      for (const auto& [name, bytes] : before) EXPECT_TRUE(now.count(name)) << name << " was lost";
    }
  }
  restore_folder(folder, after);
  return injected;
}

}  // namespace sweep::test
