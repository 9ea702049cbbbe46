// Discarding unsaved changes (the "Unsaved changes" question's Discard) removes their recovery
// copy too: opening the file again offers nothing from a session that did not end cleanly.
#include "app/viewer/actions.hpp"
#include "app/viewer/file_safety.hpp"
#include "app/viewer/viewer_state.hpp"
#include "io/swp/read.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>

namespace {

using sweep::viewer::ViewerState;

TEST(DiscardChanges, DiscardingBeforeOpeningAnotherFileRemovesTheRecoveryCopy) {
  const sweep::test::ScratchFolder folder("sweep-discard");
  const std::filesystem::path file = folder.path() / "ring.swp";
  sweep::test::write_text(file, "circ ring 12 1\n");
  // A minute old, so the recovery copy written below is newer than it: file times are coarse (a
  // kernel tick), and a copy written in the file's tick would not count as newer.
  std::filesystem::last_write_time(file, std::filesystem::last_write_time(file) - std::chrono::minutes(1));
  ViewerState s;
  s.safety.recovery.emplace(folder.path() / "recovery");
  s.session.load(sweep::io::load_swp_file(file), file.string());
  ASSERT_TRUE(s.session.edit("radius", [](sweep::Document& doc) {
    doc.objects[0].as<sweep::RadiusPart>().radius = 2.0;
    return sweep::Change{{0}, false};
  }));
  ASSERT_EQ(s.safety.recovery->write(s.doc(), s.session.file()), "");
  ASSERT_TRUE(s.safety.recovery->newer_copy(file.string()).has_value());

  s.unsaved.request(sweep::editor::PendingAction::Open, "other.swp", s.session.dirty());
  ASSERT_EQ(s.unsaved.stage(), sweep::editor::UnsavedChangesFlow::Stage::AskSave);
  sweep::viewer::discard_changes(s);
  EXPECT_EQ(s.unsaved.take_ready(), sweep::editor::PendingAction::Open);
  EXPECT_FALSE(std::filesystem::exists(s.safety.recovery->copy_path(file.string())));
  EXPECT_FALSE(s.safety.recovery->newer_copy(file.string()).has_value());
}

TEST(NewDocument, NewStartsAnUntitledEmptyDocumentAfterAskingAboutUnsavedChanges) {
  ViewerState s;
  s.session.load(sweep::io::parse_swp("circ ring 12 1\n", "ring.swp"), "ring.swp");
  sweep::viewer::request_new(s);  // nothing unsaved: at once
  sweep::viewer::run_ready_action(s);
  EXPECT_TRUE(s.doc().objects.empty());
  EXPECT_EQ(s.session.file(), "");
  EXPECT_FALSE(s.session.dirty());

  s.session.load(sweep::io::parse_swp("circ ring 12 1\n", "ring.swp"), "ring.swp");
  ASSERT_TRUE(s.session.edit("radius", [](sweep::Document& doc) {
    doc.objects[0].as<sweep::RadiusPart>().radius = 2.0;
    return sweep::Change{{0}, false};
  }));
  sweep::viewer::request_new(s);
  EXPECT_EQ(s.unsaved.stage(), sweep::editor::UnsavedChangesFlow::Stage::AskSave);
  sweep::viewer::run_ready_action(s);
  EXPECT_EQ(s.doc().objects.size(), 1u) << "nothing happens before the question is answered";
  sweep::viewer::discard_changes(s);
  sweep::viewer::run_ready_action(s);
  EXPECT_TRUE(s.doc().objects.empty());
  EXPECT_EQ(s.session.file(), "");
}

}  // namespace
