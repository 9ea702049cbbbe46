// Undo history: groups (a drag is one step), in-place and structural steps, redo, labels,
// cancel, and the dirty flag across saves, undos and discarded redos.
#include "model/edit/history.hpp"

#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/edit/edit.hpp"

#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using glm::dvec3;
using sweep::Change;
using sweep::Document;
using sweep::History;

using sweep::test::load_starter;

/// One recorded step that moves point `point` of object `object` to `position`.
void move_step(History& history, Document& doc, int object, int point, const dvec3& position,
               const std::string& label = "move point") {
  history.begin(doc, label);
  sweep::move_point(doc, object, point, position);
  history.end(doc);
}

TEST(History, ADragIsOneStep) {
  Document doc = load_starter("wineglass.swp");
  const Document original = doc;
  History history;
  EXPECT_FALSE(history.can_undo());
  EXPECT_EQ(history.undo_label(), "");
  history.begin(doc, "drag");
  EXPECT_TRUE(history.in_step());
  for (int frame = 1; frame <= 20; ++frame) sweep::move_point(doc, 0, 5, {-1.0 - 0.01 * frame, 0.1 * frame, 0});
  history.end(doc);
  EXPECT_FALSE(history.in_step());
  const Document dragged = doc;
  EXPECT_TRUE(history.can_undo());
  EXPECT_FALSE(history.can_redo());
  EXPECT_EQ(history.undo_label(), "drag");

  const Change undone = history.undo(doc);
  EXPECT_EQ(undone.objects, std::vector<int>{0});
  EXPECT_FALSE(undone.structure);
  EXPECT_EQ(doc, original);
  EXPECT_FALSE(history.can_undo());  // one step only
  EXPECT_TRUE(history.can_redo());
  EXPECT_EQ(history.redo_label(), "drag");

  const Change redone = history.redo(doc);
  EXPECT_EQ(redone.objects, std::vector<int>{0});
  EXPECT_FALSE(redone.structure);
  EXPECT_EQ(doc, dragged);
  EXPECT_FALSE(history.can_redo());
  // Nothing more to do: empty changes, document untouched.
  const Change nothing = history.redo(doc);
  EXPECT_TRUE(nothing.objects.empty());
  EXPECT_FALSE(nothing.structure);
  EXPECT_EQ(doc, dragged);
}

TEST(History, UndoAndRedoASequence) {
  Document doc = load_starter("weird.swp");
  History history;
  std::vector<Document> states{doc};
  move_step(history, doc, 0, 4, {0.1, 0.2, 0}, "first");
  states.push_back(doc);
  move_step(history, doc, 1, 5, {1, 2, 3}, "second");
  states.push_back(doc);
  history.begin(doc, "steps");
  sweep::set_steps_or_levels(doc, 0, 5);
  sweep::set_steps_or_levels(doc, 1, 7);
  history.end(doc);
  states.push_back(doc);
  move_step(history, doc, 0, 1, {0.3, 0.3, 0}, "seam");  // moves points 1 and 9
  states.push_back(doc);

  EXPECT_EQ(history.undo_label(), "seam");
  EXPECT_EQ(history.undo(doc).objects, std::vector<int>{0});
  EXPECT_EQ(doc, states[3]);
  EXPECT_EQ(history.undo_label(), "steps");
  EXPECT_EQ(history.undo(doc).objects, (std::vector<int>{0, 1}));
  EXPECT_EQ(doc, states[2]);
  EXPECT_EQ(history.undo(doc).objects, std::vector<int>{1});
  EXPECT_EQ(doc, states[1]);
  EXPECT_EQ(history.undo(doc).objects, std::vector<int>{0});
  EXPECT_EQ(doc, states[0]);
  EXPECT_FALSE(history.can_undo());
  for (std::size_t i = 1; i < states.size(); ++i) {
    history.redo(doc);
    EXPECT_EQ(doc, states[i]) << "after redo " << i;
  }
  EXPECT_FALSE(history.can_redo());
}

TEST(History, StructuralStepsRestoreWholeDocuments) {
  Document doc = load_starter("core.swp");
  History history;
  std::vector<Document> states{doc};
  history.begin(doc, "add curve");
  const int added = sweep::add_curve(doc, "circle", sweep::unique_name(doc, "circle"));
  history.end(doc);
  states.push_back(doc);
  history.begin(doc, "add surface");
  sweep::add_surface(doc, sweep::ObjectKind::SurfaceOfRevolution, "turned", added, -1, 12);
  history.end(doc);
  states.push_back(doc);
  history.begin(doc, "delete");
  sweep::delete_object(doc, 0);
  history.end(doc);
  states.push_back(doc);
  ASSERT_EQ(doc.objects.size(), 5u);

  for (std::size_t i = states.size() - 1; i > 0; --i) {
    const Change change = history.undo(doc);
    EXPECT_TRUE(change.structure);
    EXPECT_EQ(doc, states[i - 1]);
  }
  for (std::size_t i = 1; i < states.size(); ++i) {
    const Change change = history.redo(doc);
    EXPECT_TRUE(change.structure);
    EXPECT_EQ(doc, states[i]);
  }
}

TEST(History, AStepThatChangesNothingIsNotRecorded) {
  Document doc = load_starter("core.swp");
  History history;
  history.begin(doc, "click");
  history.end(doc);
  EXPECT_FALSE(history.can_undo());
  // Moving a point away and back is no change either.
  const dvec3 old = doc.objects[1].as<sweep::PointsPart>().points[0];
  history.begin(doc, "drag");
  sweep::move_point(doc, 1, 0, {9, 9, 0});
  sweep::move_point(doc, 1, 0, old);
  history.end(doc);
  EXPECT_FALSE(history.can_undo());
  EXPECT_FALSE(history.dirty());
  // end() without begin() does nothing.
  history.end(doc);
  EXPECT_FALSE(history.can_undo());
}

TEST(History, ANewStepDiscardsTheRedoSteps) {
  Document doc = load_starter("core.swp");
  History history;
  move_step(history, doc, 1, 0, {1, 1, 0}, "a");
  move_step(history, doc, 1, 1, {2, 2, 0}, "b");
  history.undo(doc);
  EXPECT_TRUE(history.can_redo());
  // An empty step keeps the redo steps...
  history.begin(doc, "nothing");
  history.end(doc);
  EXPECT_TRUE(history.can_redo());
  // ...a real one discards them.
  move_step(history, doc, 1, 2, {3, 3, 0}, "c");
  EXPECT_FALSE(history.can_redo());
  EXPECT_EQ(history.redo_label(), "");
  EXPECT_EQ(history.undo_label(), "c");
  history.undo(doc);
  EXPECT_EQ(history.undo_label(), "a");
}

TEST(History, NestedBeginIsFlattenedIntoTheOuterStep) {
  Document doc = load_starter("core.swp");
  const Document original = doc;
  History history;
  history.begin(doc, "outer");
  sweep::move_point(doc, 1, 0, {1, 1, 0});
  history.begin(doc, "inner");
  sweep::move_point(doc, 3, 0, {1, 1, 1});
  history.end(doc);
  EXPECT_TRUE(history.in_step());
  EXPECT_FALSE(history.can_undo());
  sweep::set_steps_or_levels(doc, 0, 3);
  history.end(doc);
  EXPECT_FALSE(history.in_step());
  EXPECT_EQ(history.undo_label(), "outer");
  EXPECT_EQ(history.undo(doc).objects, (std::vector<int>{0, 1, 3}));
  EXPECT_EQ(doc, original);
  EXPECT_FALSE(history.can_undo());
}

TEST(History, CancelRestoresTheSnapshot) {
  Document doc = load_starter("wineglass.swp");
  const Document original = doc;
  History history;
  history.begin(doc, "drag");
  sweep::move_point(doc, 0, 7, {-2, 2, 0});
  sweep::move_point(doc, 0, 8, {-2, 3, 0});
  const Change change = history.cancel(doc);
  EXPECT_EQ(change.objects, std::vector<int>{0});
  EXPECT_FALSE(change.structure);
  EXPECT_EQ(doc, original);
  EXPECT_FALSE(history.in_step());
  EXPECT_FALSE(history.can_undo());
  // A cancelled structural edit says so.
  history.begin(doc, "add");
  sweep::add_curve(doc, "Bezier (2D)", "");
  EXPECT_TRUE(history.cancel(doc).structure);
  EXPECT_EQ(doc, original);
  // Undo and redo wait while a step is open.
  move_step(history, doc, 0, 7, {-2, 2, 0});
  history.begin(doc, "open");
  EXPECT_TRUE(history.undo(doc).objects.empty());
  history.cancel(doc);
  EXPECT_EQ(history.undo(doc).objects, std::vector<int>{0});
  EXPECT_EQ(doc, original);
}

TEST(History, DirtyTracksTheSavedState) {
  Document doc = load_starter("core.swp");
  History history;
  EXPECT_FALSE(history.dirty());
  move_step(history, doc, 1, 0, {1, 1, 0});
  EXPECT_TRUE(history.dirty());
  history.undo(doc);
  EXPECT_FALSE(history.dirty());  // back at the loaded state
  history.redo(doc);
  EXPECT_TRUE(history.dirty());
  history.mark_saved();
  EXPECT_FALSE(history.dirty());
  move_step(history, doc, 1, 1, {2, 2, 0});
  EXPECT_TRUE(history.dirty());
  history.undo(doc);
  EXPECT_FALSE(history.dirty());  // back at the saved state
  history.undo(doc);
  EXPECT_TRUE(history.dirty());  // before the saved state
  history.redo(doc);
  EXPECT_FALSE(history.dirty());

  // Undo past the save, then a new step discards the saved state from the redo list: no state
  // reachable now is the saved one.
  history.undo(doc);
  move_step(history, doc, 1, 2, {3, 3, 0});
  EXPECT_TRUE(history.dirty());
  history.undo(doc);
  EXPECT_TRUE(history.dirty());
  history.redo(doc);
  EXPECT_TRUE(history.dirty());
  history.mark_saved();
  EXPECT_FALSE(history.dirty());
}

TEST(History, SavingInsideAStepStaysDirtyUntilSavedAgain) {
  Document doc = load_starter("core.swp");
  History history;
  history.begin(doc, "drag");
  sweep::move_point(doc, 1, 0, {1, 1, 0});
  history.mark_saved();  // the file now holds the half-dragged state
  sweep::move_point(doc, 1, 0, {2, 2, 0});
  history.end(doc);
  EXPECT_TRUE(history.dirty());
  history.undo(doc);
  EXPECT_TRUE(history.dirty());  // the loaded state is not what the file holds any more
  history.redo(doc);
  EXPECT_TRUE(history.dirty());
  history.mark_saved();
  EXPECT_FALSE(history.dirty());
}

TEST(History, ClearForgetsEverythingAndCountsAsSaved) {
  Document doc = load_starter("core.swp");
  History history;
  move_step(history, doc, 1, 0, {1, 1, 0});
  move_step(history, doc, 1, 1, {1, 2, 0});
  history.undo(doc);
  history.begin(doc, "open");
  history.clear();
  EXPECT_FALSE(history.dirty());
  EXPECT_FALSE(history.can_undo());
  EXPECT_FALSE(history.can_redo());
  EXPECT_FALSE(history.in_step());
  move_step(history, doc, 1, 3, {1, 3, 0});
  EXPECT_TRUE(history.dirty());
  history.undo(doc);
  EXPECT_FALSE(history.dirty());
}

TEST(History, AFailedEditInsideAStepIsCancelledCleanly) {
  Document doc = load_starter("core.swp");
  const Document original = doc;
  History history;
  history.begin(doc, "insert");
  EXPECT_THROW(sweep::delete_point(doc, 1, 0), sweep::EditError);  // a 4-point B-spline
  history.cancel(doc);
  EXPECT_EQ(doc, original);
  EXPECT_FALSE(history.can_undo());
  EXPECT_FALSE(history.dirty());
}

TEST(History, RandomEditsStayValidAndUndoToEveryStateBack) {
  // Random edits, valid and not, on a file with closed and open curves and a surface. Failed
  // edits must leave the document as it was; successful ones a valid document; and undo must
  // walk back through every recorded state, redo forward again.
  Document doc = load_starter("weird.swp");
  sweep::add_curve(doc, "Bezier (2D)", "bez");
  History history;
  std::vector<Document> states{doc};
  std::mt19937 random(12345);
  auto pick = [&](int low, int high) { return std::uniform_int_distribution<int>(low, high)(random); };
  auto coordinate = [&] { return std::uniform_real_distribution<double>(-2.0, 2.0)(random); };
  int failures = 0;
  for (int round = 0; round < 400; ++round) {
    const int object = pick(-1, static_cast<int>(doc.objects.size()));
    const int size = object >= 0 && object < static_cast<int>(doc.objects.size())
                         ? static_cast<int>(sweep::points_of(doc.objects[static_cast<std::size_t>(object)]).size())
                         : 4;
    const int point = pick(-1, size);
    const dvec3 position(coordinate(), coordinate(), coordinate());
    const Document before = doc;
    history.begin(doc, "random");
    try {
      switch (pick(0, 9)) {
        case 0:
          sweep::move_point(doc, object, point, position);
          break;
        case 1:
          sweep::insert_bspline_point(doc, object, point, position);
          break;
        case 2:
          sweep::delete_point(doc, object, point);
          break;
        case 3:
          sweep::split_bezier_piece(doc, object, pick(-1, 3),
                                    std::uniform_real_distribution<double>(-0.2, 1.2)(random));
          break;
        case 4:
          sweep::join_bezier_pieces(doc, object, point);
          break;
        case 5:
          sweep::set_steps_or_levels(doc, object, pick(0, 40));
          break;
        case 6:
          sweep::add_curve(doc, sweep::curve_templates()[std::size_t(pick(0, 5))].label,
                           pick(0, 1) ? sweep::unique_name(doc, "c") : "profile");
          break;
        case 7:
          sweep::delete_object(doc, object);
          break;
        case 8:
          sweep::rename_object(doc, object, pick(0, 1) ? sweep::unique_name(doc, "n") : "");
          break;
        default:
          sweep::add_surface(
              doc, pick(0, 1) ? sweep::ObjectKind::SurfaceOfRevolution : sweep::ObjectKind::GeneralizedCylinder, "",
              object, pick(0, static_cast<int>(doc.objects.size()) - 1), pick(1, 30));
          break;
      }
      history.end(doc);
      ASSERT_NO_THROW(sweep::io::validate_document(doc)) << "round " << round << "\n" << sweep::io::write_swp(doc);
      if (!(doc == before)) states.push_back(doc);
    } catch (const sweep::EditError&) {
      ++failures;
      ASSERT_EQ(doc, before) << "round " << round;
      history.cancel(doc);
      ASSERT_EQ(doc, before);
    }
  }
  // Both kinds happened often enough for the test to mean something.
  EXPECT_GT(failures, 50);
  EXPECT_GT(states.size(), 100u);
  for (std::size_t i = states.size() - 1; i > 0; --i) {
    ASSERT_TRUE(history.can_undo());
    history.undo(doc);
    ASSERT_EQ(doc, states[i - 1]) << "undo to state " << i - 1;
  }
  EXPECT_FALSE(history.can_undo());
  EXPECT_FALSE(history.dirty());
  for (std::size_t i = 1; i < states.size(); ++i) {
    history.redo(doc);
    ASSERT_EQ(doc, states[i]) << "redo to state " << i;
  }
  EXPECT_TRUE(history.dirty());
}

TEST(History, KeepsAtMostTheGivenNumberOfSteps) {
  Document doc = load_starter("core.swp");
  History history(3, 1'000'000);
  std::vector<Document> states{doc};
  for (int i = 0; i < 5; ++i) {
    move_step(history, doc, 1, 0, {i + 1.0, 0, 0}, "move " + std::to_string(i));
    states.push_back(doc);
  }
  for (int i = 4; i >= 2; --i) {
    ASSERT_TRUE(history.can_undo());
    EXPECT_EQ(history.undo_label(), "move " + std::to_string(i));
    history.undo(doc);
    EXPECT_EQ(doc, states[static_cast<std::size_t>(i)]);
  }
  EXPECT_FALSE(history.can_undo());  // the two oldest steps are forgotten
  EXPECT_EQ(history.forgotten(), 2u);
  EXPECT_TRUE(history.dirty());  // and the loaded state cannot be reached any more
  history.mark_saved();
  EXPECT_FALSE(history.dirty());
  history.redo(doc);
  EXPECT_TRUE(history.dirty());
  history.undo(doc);
  EXPECT_FALSE(history.dirty());
  // A new step from the saved (oldest reachable) state, undone, is clean again.
  move_step(history, doc, 1, 1, {0, 9, 0}, "new");
  EXPECT_TRUE(history.dirty());
  EXPECT_FALSE(history.can_redo());
  history.undo(doc);
  EXPECT_EQ(doc, states[2]);
  EXPECT_FALSE(history.dirty());
  EXPECT_FALSE(history.can_undo());
}

TEST(History, KeepsOnlyTheNewestStepWhenStepsAreBig) {
  Document doc = load_starter("wineglass.swp");  // the profile has 26 points: a move stores 54
  History history(100, 60);
  move_step(history, doc, 0, 3, {-1, 0, 0}, "first");
  move_step(history, doc, 0, 4, {-1, 1, 0}, "second");
  EXPECT_EQ(history.undo_label(), "second");
  history.undo(doc);
  EXPECT_FALSE(history.can_undo());
  // A structural step (two whole documents) is kept alone too.
  history.redo(doc);
  history.begin(doc, "add");
  sweep::add_curve(doc, "circle", "ring");
  history.end(doc);
  history.undo(doc);
  EXPECT_FALSE(history.can_undo());
  EXPECT_EQ(doc.objects.size(), 2u);
}

// The default caps (1000 steps, 2 million stored points) bound a long session's history: 1 200
// edits keep the newest 1000, the oldest forgotten first, and the stored points never pass the
// cap however big the steps.
TEST(History, TheDefaultCapsKeepTheNewest1000Steps) {
  Document doc = load_starter("core.swp");
  History history;
  for (int i = 0; i < 1200; ++i) move_step(history, doc, 1, 0, {i * 0.001, 0, 0}, "move " + std::to_string(i));
  EXPECT_EQ(history.undo_count(), 1000u);
  EXPECT_EQ(history.forgotten(), 200u);
  EXPECT_EQ(history.undo_label(), "move 1199");
  while (history.undo_count() > 1) history.undo(doc);
  EXPECT_EQ(history.undo_label(), "move 200");  // the oldest kept
}

}  // namespace
