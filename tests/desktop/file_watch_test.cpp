// Noticing that the open file changed on disk: rewritten in place (new size, or the same size
// and a later time), replaced by a rename, deleted and written again; once per version, never
// for our own save, and no more often than the interval.
#include "desktop/file_watch.hpp"

#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

namespace sweep::editor {
namespace {

using test::write_text;

/// A fixed modification time `seconds` after a base an hour ago, so tests never depend on the
/// file system's clock resolution.
void set_time(const std::filesystem::path& path, int seconds) {
  static const auto base = std::filesystem::file_time_type::clock::now() - std::chrono::hours(1);
  std::filesystem::last_write_time(path, base + std::chrono::seconds(seconds));
}

TEST(FileStamp, DescribesAnExistingFileAndIsEmptyForAMissingOne) {
  test::ScratchFolder scratch("sweep-watch");
  const auto file = scratch.path() / "a.swp";
  EXPECT_EQ(file_stamp(file), FileStamp{});
  EXPECT_FALSE(file_stamp(file).exists);
  EXPECT_FALSE(file_stamp("").exists);
  write_text(file, "12345");
  set_time(file, 7);
  const FileStamp stamp = file_stamp(file);
  EXPECT_TRUE(stamp.exists);
  EXPECT_EQ(stamp.size, 5u);
  EXPECT_NE(stamp.inode, 0u);
  set_time(file, 8);
  EXPECT_EQ(file_stamp(file).modified_ns - stamp.modified_ns, 1'000'000'000) << "nanoseconds";
  set_time(file, 7);
  EXPECT_EQ(file_stamp(file), stamp) << "nothing changed";
}

TEST(FileWatcher, TheInitialVersionIsNotAChange) {
  test::ScratchFolder scratch("sweep-watch");
  const auto file = scratch.path() / "a.swp";
  write_text(file, "circ a 8 1\n");
  FileWatcher watcher(0.25, 0.0);  // no settling: each version counts when seen
  watcher.watch(file.string());
  EXPECT_EQ(watcher.path(), file.string());
  EXPECT_FALSE(watcher.changed(0.0));
  EXPECT_FALSE(watcher.changed(1.0));
  EXPECT_FALSE(watcher.changed(2.0));
}

TEST(FileWatcher, AnInPlaceRewriteWithANewSizeIsOneChange) {
  test::ScratchFolder scratch("sweep-watch");
  const auto file = scratch.path() / "a.swp";
  write_text(file, "circ a 8 1\n");
  set_time(file, 0);
  FileWatcher watcher(0.25, 0.0);  // no settling: each version counts when seen
  watcher.watch(file.string());
  write_text(file, "circ a 8 1\ncirc b 8 1\n");
  set_time(file, 0);  // even with the same time
  EXPECT_TRUE(watcher.changed(1.0));
  EXPECT_FALSE(watcher.changed(2.0)) << "once per version";
}

TEST(FileWatcher, TheSameSizeWithALaterTimeIsAChange) {
  test::ScratchFolder scratch("sweep-watch");
  const auto file = scratch.path() / "a.swp";
  write_text(file, "circ a 8 1\n");
  set_time(file, 0);
  FileWatcher watcher(0.25, 0.0);  // no settling: each version counts when seen
  watcher.watch(file.string());
  const auto inode = file_stamp(file).inode;
  write_text(file, "circ b 8 1\n");
  set_time(file, 1);
  ASSERT_EQ(file_stamp(file).inode, inode) << "rewritten in place";
  EXPECT_TRUE(watcher.changed(1.0));
  EXPECT_FALSE(watcher.changed(2.0));
}

TEST(FileWatcher, ARenameOverTheFileIsAChange) {
  test::ScratchFolder scratch("sweep-watch");
  const auto file = scratch.path() / "a.swp";
  const auto temp = scratch.path() / "a.swp.tmp";
  write_text(file, "circ a 8 1\n");
  set_time(file, 0);
  FileWatcher watcher(0.25, 0.0);  // no settling: each version counts when seen
  watcher.watch(file.string());
  write_text(temp, "circ b 8 1\n");  // same size
  set_time(temp, 0);                 // and the same time: only the inode tells
  std::filesystem::rename(temp, file);
  EXPECT_TRUE(watcher.changed(1.0));
  EXPECT_FALSE(watcher.changed(2.0));
}

TEST(FileWatcher, ADeletedFileCountsOnlyWhenItComesBack) {
  test::ScratchFolder scratch("sweep-watch");
  const auto file = scratch.path() / "a.swp";
  write_text(file, "circ a 8 1\n");
  set_time(file, 0);
  FileWatcher watcher(0.25, 0.0);  // no settling: each version counts when seen
  watcher.watch(file.string());
  std::filesystem::remove(file);
  EXPECT_FALSE(watcher.changed(1.0)) << "gone: wait for it";
  EXPECT_FALSE(watcher.changed(2.0));
  write_text(file, "circ a 8 2\n");
  set_time(file, 3);
  EXPECT_TRUE(watcher.changed(3.0));
  EXPECT_FALSE(watcher.changed(4.0));
}

TEST(FileWatcher, AnEmptiedFileCountsOnlyOnceItHasContentAgain) {
  // `>file` truncates before the writer writes: under load the empty file can outlast the
  // settling time, and an empty file is a valid, empty SWP document.
  test::ScratchFolder scratch("sweep-watch");
  const auto file = scratch.path() / "a.swp";
  write_text(file, "circ a 8 1\n");
  set_time(file, 0);
  FileWatcher watcher(0.25, 0.0);  // no settling: each version counts when seen
  watcher.watch(file.string());
  write_text(file, "");
  set_time(file, 1);
  EXPECT_FALSE(watcher.changed(1.0)) << "empty: a write in progress";
  EXPECT_FALSE(watcher.changed(2.0));
  write_text(file, "circ a 8 2\n");
  set_time(file, 3);
  EXPECT_TRUE(watcher.changed(3.0));
  EXPECT_FALSE(watcher.changed(4.0));
}

TEST(FileWatcher, AFileThatDidNotExistIsNoticedWhenItAppears) {
  test::ScratchFolder scratch("sweep-watch");
  const auto file = scratch.path() / "new.swp";
  FileWatcher watcher(0.25, 0.0);  // no settling: each version counts when seen
  watcher.watch(file.string());
  EXPECT_FALSE(watcher.changed(1.0));
  write_text(file, "circ a 8 1\n");
  EXPECT_TRUE(watcher.changed(2.0));
}

TEST(FileWatcher, PollsNoMoreOftenThanTheInterval) {
  test::ScratchFolder scratch("sweep-watch");
  const auto file = scratch.path() / "a.swp";
  write_text(file, "circ a 8 1\n");
  set_time(file, 0);
  FileWatcher watcher(0.5, 0.0);
  watcher.watch(file.string());
  EXPECT_EQ(watcher.wait_time(0.0), 0.0) << "the first poll is due at once";
  EXPECT_FALSE(watcher.changed(10.0));
  EXPECT_DOUBLE_EQ(watcher.wait_time(10.0), 0.5);
  EXPECT_DOUBLE_EQ(watcher.wait_time(10.25), 0.25);
  write_text(file, "circ a 8 1\ncirc b 8 1\n");
  EXPECT_FALSE(watcher.changed(10.25)) << "inside the interval: not polled";
  EXPECT_FALSE(watcher.changed(10.49));
  EXPECT_TRUE(watcher.changed(10.5));
  EXPECT_EQ(watcher.wait_time(20.0), 0.0) << "overdue: never negative";
}

TEST(FileWatcher, AcceptTakesOurOwnWriteAsThePresentVersion) {
  test::ScratchFolder scratch("sweep-watch");
  const auto file = scratch.path() / "a.swp";
  write_text(file, "circ a 8 1\n");
  set_time(file, 0);
  FileWatcher watcher(0.25, 0.0);  // no settling: each version counts when seen
  watcher.watch(file.string());
  EXPECT_FALSE(watcher.changed(1.0));
  write_text(file, "circ a 8 1\ncirc b 8 1\n");  // we saved
  watcher.accept();
  EXPECT_FALSE(watcher.changed(2.0));
  write_text(file, "circ a 8 3\n");  // someone else did
  set_time(file, 5);
  EXPECT_TRUE(watcher.changed(3.0));
}

TEST(FileWatcher, WatchingNothingNeverChanges) {
  FileWatcher watcher;
  EXPECT_EQ(watcher.path(), "");
  EXPECT_FALSE(watcher.changed(0.0));
  EXPECT_LT(watcher.wait_time(0.0), 0.0);
  watcher.watch("");
  EXPECT_FALSE(watcher.changed(100.0));
  EXPECT_LT(watcher.wait_time(100.0), 0.0);
}

TEST(FileWatcher, WatchingAnotherFileStartsFromItsPresentVersion) {
  test::ScratchFolder scratch("sweep-watch");
  const auto first = scratch.path() / "a.swp";
  const auto second = scratch.path() / "b.swp";
  write_text(first, "circ a 8 1\n");
  write_text(second, "circ bb 8 1\n");
  FileWatcher watcher(0.25, 0.0);  // no settling: each version counts when seen
  watcher.watch(first.string());
  EXPECT_FALSE(watcher.changed(1.0));
  watcher.watch(second.string());
  EXPECT_EQ(watcher.wait_time(1.0), 0.0) << "polled at once";
  EXPECT_FALSE(watcher.changed(1.0)) << "its present version is not a change";
}

// Another program writing the file while we watch (issue 29): a version counts only once it has
// stayed the same for the settle time, polled every half of it meanwhile; a file still changing
// is never reported half-written.
TEST(FileWatcher, AVersionCountsOnceItHasSettled) {
  test::ScratchFolder scratch("sweep-watch");
  const auto file = scratch.path() / "a.swp";
  write_text(file, "circ a 8 1\n");
  set_time(file, 0);
  FileWatcher watcher(0.25, 0.1);
  watcher.watch(file.string());
  EXPECT_FALSE(watcher.changed(1.0));
  write_text(file, "circ a 8 1\ncirc b");  // half written
  set_time(file, 1);
  EXPECT_FALSE(watcher.changed(1.25)) << "seen, not settled";
  EXPECT_NEAR(watcher.wait_time(1.25), 0.05, 1e-12) << "polled faster while it settles";
  write_text(file, "circ a 8 1\ncirc b 8 1\n");  // the rest
  set_time(file, 2);
  EXPECT_FALSE(watcher.changed(1.30)) << "changed again: settling starts over";
  EXPECT_FALSE(watcher.changed(1.35));
  EXPECT_TRUE(watcher.changed(1.45)) << "the same for 0.1 s and more";
  EXPECT_FALSE(watcher.changed(2.0)) << "once";
}

TEST(FileWatcher, AFileThatKeepsChangingIsNotReportedUntilItStops) {
  test::ScratchFolder scratch("sweep-watch");
  const auto file = scratch.path() / "a.swp";
  write_text(file, "circ a 8 1\n");
  set_time(file, 0);
  FileWatcher watcher(0.25, 0.1);
  watcher.watch(file.string());
  double now = 1.0;
  for (int version = 1; version <= 20; ++version, now += 0.05) {
    write_text(file, "circ a 8 " + std::to_string(version) + "\n");
    set_time(file, version);
    EXPECT_FALSE(watcher.changed(now)) << "version " << version;
  }
  EXPECT_TRUE(watcher.changed(now + 0.1));
}

TEST(FileWatcher, RetryLooksAgainAfterARead) {
  test::ScratchFolder scratch("sweep-watch");
  const auto file = scratch.path() / "a.swp";
  write_text(file, "circ a 8 1\n");
  set_time(file, 0);
  FileWatcher watcher(0.25, 0.0);
  watcher.watch(file.string());
  write_text(file, "circ a 8 2\n");
  set_time(file, 1);
  EXPECT_TRUE(watcher.changed(1.0));
  // The reader found it changed under it: the version it read is not the present one.
  write_text(file, "circ a 8 3\n");
  set_time(file, 2);
  watcher.retry();
  EXPECT_TRUE(watcher.changed(2.0));
}

}  // namespace
}  // namespace sweep::editor
