// Save and Save As with every write failing in turn (issue 29): the old file stays or the new one
// is whole, no temporary is left, the message names the path and the cause, and the edits stay
// in memory with the unsaved flag set.
#include "editor/edit_session.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/edit/edit.hpp"
#include "support/scratch_folder.hpp"
#include "support/write_failure_support.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <sstream>
#include <string>

namespace sweep::editor {
namespace {

namespace fs = std::filesystem;
using test::WriteOutcome;

/// A polyline of `points` points: a file of several writes.
std::string polyline_file(int points) {
  std::ostringstream text;
  text << "poly3 line " << points << '\n';
  for (int i = 0; i < points; ++i) text << '[' << i << " 0.5 -1]\n";
  return text.str();
}

/// The k-th call failing in a save to `target` (Save, or Save As to another file) of a session on
/// `folder`/line.swp with a point moved (made anew for every try, as the folder is).
void check_save(const fs::path& folder, const std::string& target) {
  const fs::path path = folder / "line.swp";
  std::optional<EditSession> session;
  Document edited;
  const auto save = [&] {
    session.emplace();
    session->load(io::load_swp_file(path), path.string());
    EXPECT_TRUE(session->edit("move", [](Document& doc) { return move_point(doc, 0, 5, {7.0, 7.0, 7.0}); }));
    edited = session->document();
    if (session->save(target)) return WriteOutcome{};
    return WriteOutcome{false, session->error()};
  };
  test::expect_every_failure_leaves_old_or_new(folder, save, [&](const WriteOutcome& failed) {
    EXPECT_EQ(failed.message.rfind("could not save: cannot write " + target + ": ", 0), 0u) << failed.message;
    EXPECT_TRUE(session->dirty()) << "the edits are still unsaved";
    EXPECT_EQ(session->document(), edited) << "and still in memory";
    EXPECT_EQ(session->file(), path.string()) << "a failed Save As keeps the file it had";
  });
}

TEST(SaveFailure, SaveKeepsTheEditsAndTheOldFileOrWritesTheNewOneWhole) {
  const test::ScratchFolder folder;
  test::restore_folder(folder.path(), {{"line.swp", polyline_file(3000)}});
  check_save(folder.path(), (folder.path() / "line.swp").string());
}

TEST(SaveFailure, SaveAsKeepsTheEditsAndTheFileItHad) {
  const test::ScratchFolder folder;
  test::restore_folder(folder.path(), {{"line.swp", polyline_file(3000)}, {"other.swp", "circ old 8 1\n"}});
  check_save(folder.path(), (folder.path() / "other.swp").string());
}

}  // namespace
}  // namespace sweep::editor
