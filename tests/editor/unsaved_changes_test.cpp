// The questions before work could be lost, walked through without a window: every path from a
// request to the action running (or not), and Save As on its own.
#include "editor/unsaved_changes.hpp"

#include <gtest/gtest.h>

namespace sweep::editor {
namespace {

using Stage = UnsavedChangesFlow::Stage;

TEST(UnsavedChanges, StartsIdleWithNothingToRun) {
  UnsavedChangesFlow flow;
  EXPECT_EQ(flow.stage(), Stage::Idle);
  EXPECT_EQ(flow.action(), PendingAction::None);
  EXPECT_EQ(flow.take_ready(), PendingAction::None);
  EXPECT_EQ(flow.error(), "");
}

TEST(UnsavedChanges, ACleanDocumentRunsTheActionOnce) {
  UnsavedChangesFlow flow;
  flow.request(PendingAction::Open, "next.swp", false);
  EXPECT_EQ(flow.stage(), Stage::Ready);
  EXPECT_EQ(flow.path(), "next.swp");
  EXPECT_EQ(flow.take_ready(), PendingAction::Open);
  EXPECT_EQ(flow.stage(), Stage::Idle);
  EXPECT_EQ(flow.take_ready(), PendingAction::None) << "the action runs once";
  EXPECT_EQ(flow.action(), PendingAction::None);
}

TEST(UnsavedChanges, ADirtyDocumentAsksAndDiscardRunsTheAction) {
  UnsavedChangesFlow flow;
  flow.request(PendingAction::Quit, "", true);
  EXPECT_EQ(flow.stage(), Stage::AskSave);
  EXPECT_EQ(flow.take_ready(), PendingAction::None) << "nothing runs while the question is open";
  EXPECT_EQ(flow.stage(), Stage::AskSave);
  flow.choose_discard();
  EXPECT_EQ(flow.stage(), Stage::Ready);
  EXPECT_EQ(flow.take_ready(), PendingAction::Quit);
  EXPECT_EQ(flow.stage(), Stage::Idle);
}

TEST(UnsavedChanges, SavingToTheFileRunsTheActionAfterASuccessfulSave) {
  UnsavedChangesFlow flow;
  flow.request(PendingAction::Open, "next.swp", true);
  flow.choose_save(true);
  EXPECT_EQ(flow.stage(), Stage::AskSave) << "the caller saves and reports back";
  flow.saved(true);
  EXPECT_EQ(flow.stage(), Stage::Ready);
  EXPECT_EQ(flow.path(), "next.swp");
  EXPECT_EQ(flow.take_ready(), PendingAction::Open);
}

TEST(UnsavedChanges, AFailedSaveKeepsTheQuestionOpenWithItsMessage) {
  UnsavedChangesFlow flow;
  flow.request(PendingAction::Quit, "", true);
  flow.choose_save(true);
  flow.saved(false, "could not save: disk full");
  EXPECT_EQ(flow.stage(), Stage::AskSave);
  EXPECT_EQ(flow.error(), "could not save: disk full");
  EXPECT_EQ(flow.take_ready(), PendingAction::None);
  flow.choose_save(true);
  flow.saved(true);
  EXPECT_EQ(flow.stage(), Stage::Ready);
  EXPECT_EQ(flow.error(), "") << "a success clears the message";
  EXPECT_EQ(flow.take_ready(), PendingAction::Quit);
}

TEST(UnsavedChanges, AnUntitledDocumentAsksForAPathAndThenRunsTheAction) {
  UnsavedChangesFlow flow;
  flow.request(PendingAction::Open, "next.swp", true);
  flow.choose_save(false);
  EXPECT_EQ(flow.stage(), Stage::AskPath);
  EXPECT_EQ(flow.action(), PendingAction::Open) << "the action waits for Save As";
  flow.choose_discard();
  EXPECT_EQ(flow.stage(), Stage::AskPath) << "discard is no answer to the path question";
  flow.saved(false, "could not save: no such folder");
  EXPECT_EQ(flow.stage(), Stage::AskPath);
  EXPECT_EQ(flow.error(), "could not save: no such folder");
  flow.saved(true);
  EXPECT_EQ(flow.stage(), Stage::Ready);
  EXPECT_EQ(flow.action(), PendingAction::Open);
  EXPECT_EQ(flow.path(), "next.swp") << "the file to open is kept";
  EXPECT_EQ(flow.take_ready(), PendingAction::Open);
}

TEST(UnsavedChanges, CancelFromEitherQuestionRunsNothing) {
  UnsavedChangesFlow flow;
  flow.request(PendingAction::Quit, "", true);
  flow.cancel();
  EXPECT_EQ(flow.stage(), Stage::Idle);
  EXPECT_EQ(flow.action(), PendingAction::None);
  EXPECT_EQ(flow.take_ready(), PendingAction::None);

  flow.request(PendingAction::Open, "next.swp", true);
  flow.choose_save(false);
  flow.saved(false, "could not save");
  ASSERT_EQ(flow.stage(), Stage::AskPath);
  flow.cancel();
  EXPECT_EQ(flow.stage(), Stage::Idle);
  EXPECT_EQ(flow.action(), PendingAction::None);
  EXPECT_EQ(flow.error(), "");
  EXPECT_EQ(flow.take_ready(), PendingAction::None);
  flow.saved(true);
  EXPECT_EQ(flow.stage(), Stage::Idle) << "a save nobody asked for changes nothing";
}

TEST(UnsavedChanges, SaveAsOnItsOwnHasNothingToRunAfterIt) {
  UnsavedChangesFlow flow;
  flow.ask_path();
  EXPECT_EQ(flow.stage(), Stage::AskPath);
  EXPECT_EQ(flow.take_ready(), PendingAction::None);
  flow.saved(true);
  EXPECT_EQ(flow.stage(), Stage::Idle);
  EXPECT_EQ(flow.take_ready(), PendingAction::None);

  // And after an earlier flow has run its action.
  flow.request(PendingAction::Quit, "", false);
  ASSERT_EQ(flow.take_ready(), PendingAction::Quit);
  flow.ask_path();
  flow.saved(true);
  EXPECT_EQ(flow.stage(), Stage::Idle);
  EXPECT_EQ(flow.take_ready(), PendingAction::None);
}

TEST(UnsavedChanges, AnswersOutsideTheirQuestionAreIgnored) {
  UnsavedChangesFlow flow;
  flow.choose_save(true);
  flow.choose_discard();
  flow.saved(false, "ignored");
  EXPECT_EQ(flow.stage(), Stage::Idle);
  EXPECT_EQ(flow.error(), "");
  EXPECT_EQ(flow.take_ready(), PendingAction::None);
}

}  // namespace
}  // namespace sweep::editor
