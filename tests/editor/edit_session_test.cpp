// The viewer's edit session (no window): edits, undo and redo keep the scene in step with the
// document and re-evaluate only what changed; failures change nothing and say why; saving.
#include "editor/edit_session.hpp"
#include "io/swp_parser.hpp"
#include "support/editor_test_support.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace sweep::editor {
namespace {

namespace fs = std::filesystem;

// A profile used by a surface, and an unrelated circle.
constexpr const char* kText =
    "bsp2 profile 4 5\n[-1 1]\n[-1.2 0.5]\n[-0.8 0]\n[-1 -0.5]\n[-1 -1]\n"
    "srev vase 12 profile\n"
    "circ ring 16 0.5\n";

using test::session_of;

std::vector<std::uint64_t> revisions(const EditSession& session) {
  std::vector<std::uint64_t> out;
  for (const EvaluatedObject& o : session.scene().objects) out.push_back(o.revision);
  return out;
}

TEST(EditSession, AMoveReevaluatesTheCurveAndItsSurfaceOnly) {
  EditSession session = session_of(kText);
  const auto before = revisions(session);
  ASSERT_TRUE(session.edit("move", [](Document& d) { return move_point(d, 0, 2, {-0.5, 0.1, 0.0}); }));
  const auto after = revisions(session);
  EXPECT_NE(after[0], before[0]);
  EXPECT_NE(after[1], before[1]) << "the surface of the profile follows";
  EXPECT_EQ(after[2], before[2]) << "the circle is not re-evaluated";
  EXPECT_EQ(session.last_remesh_objects(), 2u);
  // The scene matches a fresh evaluation of the edited document.
  const Scene fresh = evaluate_document(session.document(), session.evaluation());
  EXPECT_EQ(session.scene().objects[1].mesh.positions, fresh.objects[1].mesh.positions);
  EXPECT_TRUE(session.dirty());
}

TEST(EditSession, UndoAndRedoRestoreTheDocumentAndTheSavedState) {
  EditSession session = session_of(kText);
  const Document original = session.document();
  ASSERT_TRUE(session.edit("radius", [](Document& d) { return set_radius(d, 2, 0.75); }));
  const Document edited = session.document();
  EXPECT_TRUE(session.dirty());
  EXPECT_EQ(session.undo_label(), "radius");
  ASSERT_TRUE(session.undo());
  EXPECT_EQ(session.document(), original);
  EXPECT_FALSE(session.dirty());
  EXPECT_EQ(session.scene().objects[2].curve.frames.size(), evaluate_document(original).objects[2].curve.frames.size());
  ASSERT_TRUE(session.redo());
  EXPECT_EQ(session.document(), edited);
  EXPECT_FALSE(session.redo()) << "nothing left to redo";
}

TEST(EditSession, AFailedEditChangesNothingAndSaysWhy) {
  EditSession session = session_of(kText);
  const Document original = session.document();
  const auto before = revisions(session);
  EXPECT_FALSE(session.edit("delete", [](Document& d) { return delete_object(d, 0); }));
  EXPECT_EQ(session.error(), "cannot delete 'profile': surface 'vase' uses it");
  EXPECT_EQ(session.document(), original);
  EXPECT_EQ(revisions(session), before);
  EXPECT_FALSE(session.dirty());
  EXPECT_FALSE(session.can_undo());
}

TEST(EditSession, AContinuousEditIsOneUndoStep) {
  EditSession session = session_of(kText);
  const Document original = session.document();
  session.begin_step("drag");
  session.begin_step("drag again");  // ignored: one step at a time
  for (int i = 1; i <= 5; ++i) {
    ASSERT_TRUE(session.apply([i](Document& d) { return move_point(d, 0, 1, {-1.2 + 0.1 * i, 0.5, 0.0}); }));
  }
  EXPECT_FALSE(session.can_undo()) << "no undo while the drag is open";
  session.end_step();
  EXPECT_EQ(session.undo_label(), "drag");
  ASSERT_TRUE(session.undo());
  EXPECT_EQ(session.document(), original);
  EXPECT_FALSE(session.can_undo());
}

TEST(EditSession, ACancelledStepRestoresTheDocumentAndRecordsNothing) {
  EditSession session = session_of(kText);
  const Document original = session.document();
  const Scene scene = session.scene();
  session.begin_step("grab points");
  ASSERT_TRUE(session.apply([](Document& d) { return move_point(d, 0, 1, {-0.25, 0.5, 0.0}); }));
  ASSERT_TRUE(session.apply([](Document& d) { return move_point(d, 0, 2, {-0.5, 0.125, 0.0}); }));
  session.cancel_step();
  EXPECT_FALSE(session.in_step());
  EXPECT_EQ(session.document(), original);
  EXPECT_EQ(session.scene().objects[1].mesh.positions, scene.objects[1].mesh.positions) << "the surface follows back";
  EXPECT_FALSE(session.can_undo());
  EXPECT_FALSE(session.dirty());
  session.cancel_step();  // nothing open: nothing happens
  EXPECT_EQ(session.document(), original);
}

TEST(EditSession, SavingWritesAFileThatReadsBackAndAFailedSaveKeepsTheEdits) {
  const fs::path dir = fs::path(SWEEP_TEST_OUTPUT_DIR) / "edit_session";
  fs::remove_all(dir);
  fs::create_directories(dir);
  EditSession session = session_of(kText);
  ASSERT_TRUE(session.edit("move", [](Document& d) { return move_point(d, 0, 0, {-0.9, 1.1, 0.0}); }));

  EXPECT_FALSE(session.save((dir / "missing" / "x.swp").string()));
  EXPECT_NE(session.error().find("could not save"), std::string::npos) << session.error();
  EXPECT_NE(session.error().find("x.swp"), std::string::npos) << session.error();
  EXPECT_TRUE(session.dirty()) << "the edits stay unsaved";
  EXPECT_EQ(session.file(), "test.swp");

  const fs::path path = dir / "saved.swp";
  ASSERT_TRUE(session.save(path.string())) << session.error();
  EXPECT_FALSE(session.dirty());
  EXPECT_EQ(session.file(), path.string());
  EXPECT_EQ(load_swp_file(path), session.document());
}

TEST(EditSession, ChangingTheFrameMethodReevaluatesEverythingWithoutDirtying) {
  EditSession session = session_of(kText);
  const auto before = revisions(session);
  EvaluationOptions options = session.evaluation();
  options.frames.method = FrameMethod::Projection;
  session.set_evaluation(options);
  EXPECT_EQ(session.evaluation().frames.method, FrameMethod::Projection);
  const auto after = revisions(session);
  for (std::size_t i = 0; i < before.size(); ++i) EXPECT_NE(after[i], before[i]);
  EXPECT_FALSE(session.dirty());
}

// A long session: once the history forgets its oldest steps, the session says so once.
TEST(EditSession, TellsOnceWhenTheHistoryStartsForgetting) {
  EditSession session = test::session_of("circ ring 8 1\n");
  int notices = 0;
  for (int i = 0; i < 1100; ++i) {
    ASSERT_TRUE(session.edit("radius", [i](Document& doc) { return set_radius(doc, 0, 1.5 + i * 0.001); }));
    if (session.take_history_notice()) {
      ++notices;
      EXPECT_EQ(i, 1000) << "the 1001st step is the first one past the cap";
    }
  }
  EXPECT_EQ(notices, 1);
  EXPECT_EQ(session.forgotten_steps(), 100u);
}

}  // namespace
}  // namespace sweep::editor
