// The recovery copy and the recent-files store with every write failing in turn (issue 29): the
// earlier copy or list stays whole or the new one is complete, no temporary is left, and the
// problem names the path and the cause.
#include "desktop/recent_files.hpp"
#include "desktop/recovery.hpp"
#include "io/swp/read.hpp"
#include "support/scratch_folder.hpp"
#include "support/write_failure_support.hpp"

#include <gtest/gtest.h>

#include <deque>
#include <sstream>
#include <string>

namespace sweep::editor {
namespace {

namespace fs = std::filesystem;
using test::WriteOutcome;

TEST(StoreFailure, ARecoveryCopyIsTheEarlierOneOrTheNewOneWhole) {
  const test::ScratchFolder folder;
  const RecoveryStore store(folder.path());
  std::ostringstream text;
  text << "poly3 line 3000\n";
  for (int i = 0; i < 3000; ++i) text << '[' << i << " 0.5 -1]\n";
  const Document doc = io::parse_swp(text.str());
  const std::string copy = store.copy_path("/home/user/line.swp").filename().string();
  test::restore_folder(folder.path(), {{copy, "circ earlier 8 1\n"}});
  test::expect_every_failure_leaves_old_or_new(
      folder.path(),
      [&] {
        const std::string problem = store.write(doc, "/home/user/line.swp");
        return WriteOutcome{problem.empty(), problem};
      },
      [&](const WriteOutcome& failed) {
        EXPECT_NE(failed.message.find((folder.path() / copy).string()), std::string::npos) << failed.message;
      });
}

TEST(StoreFailure, TheRecentFilesListIsTheEarlierOneOrTheNewOneWhole) {
  const test::ScratchFolder folder;
  const fs::path list = folder.path() / "recent-files.txt";
  test::restore_folder(folder.path(), {{"recent-files.txt", "/old/one.swp\n"}});
  std::deque<std::string> recent;
  for (int i = 0; i < 10; ++i) recent.push_back("/home/user/models/model-" + std::to_string(i) + ".swp");
  test::expect_every_failure_leaves_old_or_new(
      folder.path(),
      [&] {
        const std::string problem = save_recent(list, recent);
        return WriteOutcome{problem.empty(), problem};
      },
      [&](const WriteOutcome& failed) {
        EXPECT_NE(failed.message.find(list.string()), std::string::npos) << failed.message;
      });
}

}  // namespace
}  // namespace sweep::editor
