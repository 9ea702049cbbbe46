// Crash recovery: where copies go, writing one that reads back as the document, when a copy is
// newer than its file, what a recovered document changes, and when the timer asks for a write.
#include "desktop/recovery.hpp"

#include "io/swp/read.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"
#include "support/text_support.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <string>

namespace sweep::editor {
namespace {

using test::joined;
using test::write_text;

const char* const kDocument = "circ profile 8 0.3\ncirc path 16 2\ngcyl tube profile path\ncirc . 12 1\n";

/// Sets the modification times of `older` and `newer` `seconds` apart (exactly, in the past).
void set_times(const std::filesystem::path& older, const std::filesystem::path& newer, int seconds) {
  const auto base = std::filesystem::file_time_type::clock::now() - std::chrono::hours(1);
  std::filesystem::last_write_time(older, base);
  std::filesystem::last_write_time(newer, base + std::chrono::seconds(seconds));
}

TEST(Recovery, CopyPathIsTheStemAndAHashOfTheAbsolutePath) {
  const RecoveryStore store("/state/sweep");
  EXPECT_EQ(store.folder(), std::filesystem::path("/state/sweep"));
  // FNV-1a 64 of "/a/vase.swp".
  EXPECT_EQ(store.copy_path("/a/vase.swp"), std::filesystem::path("/state/sweep/vase-b9ee1ccfbd95a6ff.swp"));
  EXPECT_EQ(store.copy_path("/a/./b/../vase.swp"), store.copy_path("/a/vase.swp")) << "the path is normalized";
  EXPECT_EQ(store.copy_path("vase.swp"), store.copy_path((std::filesystem::current_path() / "vase.swp").string()))
      << "a relative path is made absolute";
  // (No std::regex: GCC 12 warns inside it under the sanitizers.)
  const auto stem_and_hash = [](const std::string& name, const std::string& stem) {
    if (name.size() != stem.size() + 1 + 16 + 4 || name.compare(0, stem.size() + 1, stem + "-") != 0) return false;
    if (name.compare(name.size() - 4, 4, ".swp") != 0) return false;
    const std::string hash = name.substr(stem.size() + 1, 16);
    return hash.find_first_not_of("0123456789abcdef") == std::string::npos;
  };
  const std::string name = store.copy_path("/a/my vase!.swp").filename().string();
  EXPECT_TRUE(stem_and_hash(name, "my_vase_")) << name;
  EXPECT_TRUE(stem_and_hash(store.copy_path("/a/v-1_x.y.swp").filename().string(), "v-1_x.y"));
}

TEST(Recovery, SameNamesInDifferentFoldersGetDifferentCopies) {
  const RecoveryStore store("/state/sweep");
  const auto first = store.copy_path("/home/ann/vase.swp");
  const auto second = store.copy_path("/home/bob/vase.swp");
  EXPECT_NE(first, second);
  EXPECT_EQ(first.parent_path(), second.parent_path());
  EXPECT_TRUE(first.filename().string().starts_with("vase-"));
  EXPECT_TRUE(second.filename().string().starts_with("vase-"));
}

TEST(Recovery, AnUntitledDocumentHasItsOwnCopy) {
  const RecoveryStore store("/state/sweep");
  EXPECT_EQ(store.copy_path(""), std::filesystem::path("/state/sweep/untitled.swp"));
}

TEST(Recovery, AWrittenCopyReadsBackAsTheDocument) {
  test::ScratchFolder scratch("sweep-recovery");
  const RecoveryStore store(scratch.path() / "state" / "sweep");
  const Document doc = io::parse_swp(kDocument);
  const std::string file = (scratch.path() / "vase.swp").string();
  EXPECT_EQ(store.write(doc, file), "") << "the folder is created";
  const auto copy = store.copy_path(file);
  ASSERT_TRUE(std::filesystem::is_regular_file(copy));
  EXPECT_EQ(io::parse_swp(test::read_file(copy)), doc);
  // Nothing else is left beside it (no temporary files).
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(store.folder()), std::filesystem::directory_iterator()),
            1);

  const Document changed = io::parse_swp("circ profile 8 0.5\n");
  EXPECT_EQ(store.write(changed, file), "");
  EXPECT_EQ(io::parse_swp(test::read_file(copy)), changed) << "a later write replaces the copy";

  EXPECT_EQ(store.write(doc, ""), "");
  EXPECT_EQ(io::parse_swp(test::read_file(store.folder() / "untitled.swp")), doc);
}

TEST(Recovery, AWriteThatCannotHappenSaysWhyAndKeepsTheEarlierCopy) {
  test::ScratchFolder scratch("sweep-recovery");
  write_text(scratch.path() / "state", "a file where the folder should be");
  const RecoveryStore blocked(scratch.path() / "state");
  EXPECT_EQ(blocked.write(io::parse_swp(kDocument), "/a/vase.swp"),
            joined({"cannot use ", (scratch.path() / "state").string(), ": it is not a folder"}));

  // A folder where the copy should be: the rename fails and the message names the copy.
  const RecoveryStore store(scratch.path() / "other");
  const Document doc = io::parse_swp(kDocument);
  ASSERT_EQ(store.write(doc, "/a/vase.swp"), "");
  const auto copy = store.copy_path("/a/vase.swp");
  const std::string before = test::read_file(copy);
  std::filesystem::create_directories(store.copy_path("/b/vase.swp"));
  const std::string message = store.write(doc, "/b/vase.swp");
  EXPECT_TRUE(message.starts_with(joined({"cannot write ", store.copy_path("/b/vase.swp").string(), ": "}))) << message;
  EXPECT_EQ(test::read_file(copy), before) << "other copies are untouched";
}

TEST(Recovery, RemoveDeletesTheCopyAndToleratesNone) {
  test::ScratchFolder scratch("sweep-recovery");
  const RecoveryStore store(scratch.path());
  ASSERT_EQ(store.write(io::parse_swp(kDocument), "/a/vase.swp"), "");
  ASSERT_TRUE(std::filesystem::exists(store.copy_path("/a/vase.swp")));
  store.remove("/a/vase.swp");
  EXPECT_FALSE(std::filesystem::exists(store.copy_path("/a/vase.swp")));
  store.remove("/a/vase.swp");  // nothing there: no throw
  const RecoveryStore missing(scratch.path() / "not-there");
  missing.remove("");
  SUCCEED();
}

TEST(Recovery, NewerCopyComparesModificationTimes) {
  test::ScratchFolder scratch("sweep-recovery");
  const RecoveryStore store(scratch.path() / "state");
  const auto file = scratch.path() / "vase.swp";
  write_text(file, kDocument);
  EXPECT_EQ(store.newer_copy(file.string()), std::nullopt) << "no copy";

  ASSERT_EQ(store.write(io::parse_swp(kDocument), file.string()), "");
  const auto copy = store.copy_path(file.string());

  set_times(file, copy, 5);
  EXPECT_EQ(store.newer_copy(file.string()), copy) << "the copy is newer than the file";

  set_times(copy, file, 5);
  EXPECT_EQ(store.newer_copy(file.string()), std::nullopt) << "the file was saved after the copy";

  set_times(copy, file, 0);
  EXPECT_EQ(store.newer_copy(file.string()), std::nullopt) << "equal times: not newer";

  std::filesystem::remove(file);
  EXPECT_EQ(store.newer_copy(file.string()), copy) << "the file is gone: the copy is all there is";
}

TEST(Recovery, NewerCopyOfAnUntitledDocumentIsItsCopy) {
  test::ScratchFolder scratch("sweep-recovery");
  const RecoveryStore store(scratch.path());
  EXPECT_EQ(store.newer_copy(""), std::nullopt);
  ASSERT_EQ(store.write(io::parse_swp(kDocument), ""), "");
  EXPECT_EQ(store.newer_copy(""), scratch.path() / "untitled.swp");
  store.remove("");
  EXPECT_EQ(store.newer_copy(""), std::nullopt);
}

TEST(Recovery, DifferencesOfEqualDocumentsAreNone) {
  const Document saved = io::parse_swp(kDocument);
  Document recovered = io::parse_swp(kDocument);
  for (std::size_t i = 0; i < recovered.objects.size(); ++i) {
    recovered.objects[i].id = 100 + i;
    recovered.objects[i].location = {};
  }
  EXPECT_TRUE(document_differences(saved, recovered).empty()) << "ids and locations do not count";
}

TEST(Recovery, DifferencesNameChangedAddedAndRemovedObjects) {
  const Document saved = io::parse_swp("circ a 8 1\ncirc b 8 1\ncirc c 8 1\n");
  const Document recovered = io::parse_swp("circ c 8 2\ncirc d 8 1\ncirc a 8 1\n");
  EXPECT_EQ(document_differences(saved, recovered), (std::vector<std::string>{"changed c", "added d", "removed b"}));
  EXPECT_EQ(document_differences(recovered, saved), (std::vector<std::string>{"added b", "changed c", "removed d"}));
}

TEST(Recovery, DifferencesNameAnonymousObjectsByKindAndIndex) {
  const Document saved = io::parse_swp("circ . 8 1\ncirc . 8 1\n");
  const Document recovered = io::parse_swp("circ . 8 1\ncirc . 9 1\ncirc . 8 1\n");
  EXPECT_EQ(document_differences(saved, recovered), (std::vector<std::string>{"changed circ#1", "added circ#2"}));
  EXPECT_EQ(document_differences(recovered, saved), (std::vector<std::string>{"changed circ#1", "removed circ#2"}));
  EXPECT_EQ(document_differences(Document{}, saved), (std::vector<std::string>{"added circ#0", "added circ#1"}));
  EXPECT_EQ(document_differences(saved, Document{}), (std::vector<std::string>{"removed circ#0", "removed circ#1"}));
}

TEST(RecoveryTimer, NothingIsDueUntilAnEdit) {
  RecoveryTimer timer(1.0);
  EXPECT_FALSE(timer.due(0.0));
  EXPECT_LT(timer.wait_time(0.0), 0.0);
  timer.edited(10.0);
  EXPECT_TRUE(timer.due(10.0)) << "the first edit is written at once";
  EXPECT_EQ(timer.wait_time(10.0), 0.0);
  timer.written(10.0);
  EXPECT_FALSE(timer.due(10.0));
  EXPECT_LT(timer.wait_time(10.5), 0.0);
}

TEST(RecoveryTimer, EditsInsideTheIntervalWaitForIt) {
  RecoveryTimer timer(1.0);
  timer.edited(0.0);
  timer.written(0.0);
  timer.edited(0.25);
  EXPECT_FALSE(timer.due(0.25));
  EXPECT_DOUBLE_EQ(timer.wait_time(0.25), 0.75);
  timer.edited(0.5);
  EXPECT_FALSE(timer.due(0.99));
  EXPECT_TRUE(timer.due(1.0)) << "exactly one interval after the last write";
  EXPECT_EQ(timer.wait_time(1.0), 0.0);
  EXPECT_EQ(timer.wait_time(3.0), 0.0) << "never negative while something waits";
  timer.written(1.0);
  EXPECT_FALSE(timer.due(5.0));
  timer.edited(5.0);
  EXPECT_TRUE(timer.due(5.0)) << "long after the last write: at once";
}

TEST(RecoveryTimer, ClearDropsWhatWaits) {
  RecoveryTimer timer(2.0);
  timer.edited(0.0);
  timer.written(0.0);
  timer.edited(1.0);
  EXPECT_DOUBLE_EQ(timer.wait_time(1.0), 1.0);
  timer.clear();
  EXPECT_FALSE(timer.due(10.0));
  EXPECT_LT(timer.wait_time(10.0), 0.0);
}

}  // namespace
}  // namespace sweep::editor
