// The recent files list: absolute paths, newest first, repeats moved up, at most
// kMaxRecentFiles; kept in a file one path a line, written atomically.
#include "desktop/recent_files.hpp"

#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"
#include "support/text_support.hpp"

#include <gtest/gtest.h>

#include <string>

namespace sweep::editor {
namespace {

using test::joined;

std::string numbered(int i) {
  return joined({"/models/file", std::to_string(i), ".swp"});
}

TEST(RecentFiles, RememberPutsTheNewestFirst) {
  std::deque<std::string> recent;
  remember_recent(recent, "/models/a.swp");
  remember_recent(recent, "/models/b.swp");
  EXPECT_EQ(recent, (std::deque<std::string>{"/models/b.swp", "/models/a.swp"}));
}

TEST(RecentFiles, RememberMakesPathsAbsoluteAndNormal) {
  std::deque<std::string> recent;
  remember_recent(recent, "vase.swp");
  remember_recent(recent, "/models/./old/../b.swp");
  EXPECT_EQ(recent,
            (std::deque<std::string>{"/models/b.swp", (std::filesystem::current_path() / "vase.swp").string()}));
}

TEST(RecentFiles, ARepeatMovesUpInsteadOfAppearingTwice) {
  std::deque<std::string> recent;
  remember_recent(recent, "/models/a.swp");
  remember_recent(recent, "/models/b.swp");
  remember_recent(recent, "/models/c.swp");
  remember_recent(recent, "/models/../models/a.swp");
  EXPECT_EQ(recent, (std::deque<std::string>{"/models/a.swp", "/models/c.swp", "/models/b.swp"}));
  remember_recent(recent, "/models/a.swp");
  EXPECT_EQ(recent.size(), 3u);
  EXPECT_EQ(recent.front(), "/models/a.swp");
}

TEST(RecentFiles, TheListKeepsTheNewestTen) {
  std::deque<std::string> recent;
  for (int i = 0; i < 15; ++i) remember_recent(recent, numbered(i));
  ASSERT_EQ(recent.size(), kMaxRecentFiles);
  EXPECT_EQ(recent.front(), numbered(14));
  EXPECT_EQ(recent.back(), numbered(5));
}

TEST(RecentFiles, SavedListsLoadBack) {
  test::ScratchFolder scratch("sweep-recent");
  const auto file = scratch.path() / "config" / "sweep" / "recent-files.txt";
  std::deque<std::string> recent;
  remember_recent(recent, "/models/a.swp");
  remember_recent(recent, "/models/with space/b.swp");
  EXPECT_EQ(save_recent(file, recent), "") << "the folders are created";
  EXPECT_EQ(test::read_file(file), "/models/with space/b.swp\n/models/a.swp\n");
  EXPECT_EQ(load_recent(file), recent);
  EXPECT_EQ(save_recent(file, {}), "");
  EXPECT_TRUE(load_recent(file).empty());
  EXPECT_EQ(scratch.entries(), std::vector<std::string>{"config"});
  EXPECT_EQ(
      std::distance(std::filesystem::directory_iterator(file.parent_path()), std::filesystem::directory_iterator()), 1)
      << "no temporary file is left";
}

TEST(RecentFiles, LoadSkipsEmptyLinesAndKeepsTen) {
  test::ScratchFolder scratch("sweep-recent");
  const auto file = scratch.path() / "recent-files.txt";
  std::string text = "\n/models/a.swp\r\n\n";
  for (int i = 0; i < 12; ++i) text += numbered(i) + "\n";
  test::write_text(file, text);
  const std::deque<std::string> recent = load_recent(file);
  ASSERT_EQ(recent.size(), kMaxRecentFiles);
  EXPECT_EQ(recent[0], "/models/a.swp");
  EXPECT_EQ(recent[1], numbered(0));
  EXPECT_EQ(recent.back(), numbered(8));
}

TEST(RecentFiles, AMissingFileIsAnEmptyList) {
  test::ScratchFolder scratch("sweep-recent");
  EXPECT_TRUE(load_recent(scratch.path() / "missing.txt").empty());
  EXPECT_TRUE(load_recent(scratch.path()).empty()) << "a folder is no list";
}

TEST(RecentFiles, SavingWhereAFileBlocksTheFolderSaysWhy) {
  test::ScratchFolder scratch("sweep-recent");
  test::write_text(scratch.path() / "config", "a file where the folder should be");
  const auto file = scratch.path() / "config" / "recent-files.txt";
  EXPECT_EQ(save_recent(file, {"/models/a.swp"}),
            joined({"cannot save the recent files to ", file.string(), ": Not a directory"}));
  const auto deeper = scratch.path() / "config" / "sweep" / "recent-files.txt";
  EXPECT_EQ(save_recent(deeper, {"/models/a.swp"}),
            joined({"cannot save the recent files to ", deeper.string(), ": Not a directory"}));
}

TEST(RecentFiles, SavingOverAFolderSaysWhyAndKeepsIt) {
  test::ScratchFolder scratch("sweep-recent");
  const auto file = scratch.path() / "recent-files.txt";
  std::filesystem::create_directory(file);
  const std::string message = save_recent(file, {"/models/a.swp"});
  EXPECT_TRUE(message.starts_with(joined({"cannot save the recent files to ", file.string(), ": "}))) << message;
  EXPECT_TRUE(std::filesystem::is_directory(file));
  EXPECT_EQ(scratch.entries(), std::vector<std::string>{"recent-files.txt"}) << "no temporary file is left";
}

}  // namespace
}  // namespace sweep::editor
