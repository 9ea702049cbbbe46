// Background evaluation (EditSession::set_background): the scene always matches the document's
// indices, shows each object's last complete evaluation until the new one is installed whole,
// a newer edit supersedes an older evaluation, an edit of other objects goes on beside it, and
// Cancel takes the document back to what the scene shows. The end result always equals a fresh
// evaluation of the document.
#include "editor/edit_session.hpp"
#include "io/swp/read.hpp"
#include "model/edit/edit.hpp"

#include <gtest/gtest.h>

#include <string>

namespace sweep::editor {
namespace {

// A cube cage, its subdivision, and a curve that neither uses.
const std::string kFile =
    "mesh cube 8 6\n[-1 -1 -1]\n[1 -1 -1]\n[1 1 -1]\n[-1 1 -1]\n[-1 -1 1]\n[1 -1 1]\n[1 1 1]\n[-1 1 1]\n"
    "[0 3 2 1]\n[4 5 6 7]\n[0 1 5 4]\n[1 2 6 5]\n[2 3 7 6]\n[3 0 4 7]\n"
    "subd smooth 1 cube\n"
    "circ ring 8 2\n";
constexpr int kSubd = 1;
constexpr int kRing = 2;

/// The scene a fresh, synchronous evaluation of the session's document gives, compared object by
/// object with what the session shows (revisions aside).
void expect_scene_is_evaluation_of_document(const EditSession& session) {
  const Scene fresh = evaluate_document(session.document(), session.evaluation());
  ASSERT_EQ(session.scene().objects.size(), fresh.objects.size());
  for (std::size_t i = 0; i < fresh.objects.size(); ++i) {
    SCOPED_TRACE("object " + std::to_string(i));
    const EvaluatedObject& shown = session.scene().objects[i];
    EXPECT_EQ(shown.mesh.positions, fresh.objects[i].mesh.positions);
    EXPECT_EQ(shown.mesh.indices, fresh.objects[i].mesh.indices);
    ASSERT_EQ(shown.curve.frames.size(), fresh.objects[i].curve.frames.size());
    for (std::size_t k = 0; k < shown.curve.frames.size(); ++k) {
      EXPECT_EQ(shown.curve.frames[k].V, fresh.objects[i].curve.frames[k].V);
    }
  }
}

/// A session on kFile where every re-evaluation of the subd (and only of it) is large.
EditSession background_session() {
  EditSession session;
  session.load(io::parse_swp(kFile), "test.swp");
  session.set_background(200);  // the cube's subd at level 1 has 98 vertices, more later; a circle 9 samples
  return session;
}

std::size_t subd_vertices(const EditSession& session) {
  return session.scene().objects[kSubd].mesh.positions.size();
}

EditSession::Operation level(int levels) {
  return [levels](Document& doc) { return set_steps_or_levels(doc, kSubd, levels); };
}

TEST(BackgroundEvaluation, ShowsTheLastCompleteEvaluationUntilTheNewOneIsInstalled) {
  EditSession session = background_session();
  const std::size_t before = subd_vertices(session);
  const std::uint64_t revision = session.scene().objects[kSubd].revision;
  ASSERT_TRUE(session.edit("level", level(3)));
  EXPECT_TRUE(session.evaluating());
  EXPECT_EQ(session.document().objects[kSubd].as<SubdivisionSurface>().levels, 3);
  // Until poll() installs it, the scene holds the level-1 mesh, complete.
  EXPECT_EQ(subd_vertices(session), before);
  EXPECT_EQ(session.scene().objects[kSubd].revision, revision);
  session.finish_evaluation();
  EXPECT_FALSE(session.evaluating());
  EXPECT_GT(subd_vertices(session), before);
  EXPECT_NE(session.scene().objects[kSubd].revision, revision);
  expect_scene_is_evaluation_of_document(session);
}

TEST(BackgroundEvaluation, ANewerEditSupersedesTheOlderEvaluation) {
  EditSession session = background_session();
  // A drag of the level: each value supersedes the last; only the last is ever installed.
  session.begin_step("drag level");
  for (int levels = 2; levels <= 4; ++levels) ASSERT_TRUE(session.apply(level(levels)));
  session.end_step();
  std::vector<std::size_t> shown;
  while (session.evaluating()) {
    if (session.poll()) shown.push_back(subd_vertices(session));
  }
  ASSERT_EQ(shown.size(), 1u);
  expect_scene_is_evaluation_of_document(session);
  EXPECT_TRUE(session.undo());  // one step for the drag, back to level 1 at once (small)
  EXPECT_FALSE(session.evaluating());
  expect_scene_is_evaluation_of_document(session);
}

TEST(BackgroundEvaluation, AnEditOfOtherObjectsGoesOnBesideTheEvaluation) {
  EditSession session = background_session();
  ASSERT_TRUE(session.edit("level", level(3)));
  ASSERT_TRUE(session.evaluating());
  const std::uint64_t ring = session.scene().objects[kRing].revision;
  ASSERT_TRUE(session.edit("radius", [](Document& doc) { return set_radius(doc, kRing, 5.0); }));
  EXPECT_NE(session.scene().objects[kRing].revision, ring);  // evaluated at once
  EXPECT_NEAR(glm::length(session.scene().objects[kRing].curve.frames[0].V), 5.0, 1e-12);
  EXPECT_TRUE(session.evaluating());  // the subd's evaluation goes on
  session.finish_evaluation();
  expect_scene_is_evaluation_of_document(session);
}

TEST(BackgroundEvaluation, CancelGoesBackToWhatTheSceneShows) {
  EditSession session = background_session();
  const std::size_t before = subd_vertices(session);
  ASSERT_TRUE(session.edit("level", level(4)));
  ASSERT_TRUE(session.can_cancel_evaluation());
  EXPECT_TRUE(session.cancel_evaluation());
  EXPECT_FALSE(session.evaluating());
  EXPECT_EQ(session.document().objects[kSubd].as<SubdivisionSurface>().levels, 1);
  EXPECT_FALSE(session.dirty());
  EXPECT_FALSE(session.can_undo());
  EXPECT_EQ(subd_vertices(session), before);
  expect_scene_is_evaluation_of_document(session);
  // A drag cancelled: the open step goes, as Esc would take it.
  session.begin_step("drag level");
  ASSERT_TRUE(session.apply(level(3)));
  EXPECT_TRUE(session.cancel_evaluation());
  EXPECT_FALSE(session.in_step());
  EXPECT_EQ(session.document().objects[kSubd].as<SubdivisionSurface>().levels, 1);
  expect_scene_is_evaluation_of_document(session);
}

TEST(BackgroundEvaluation, CancelAfterAnUndoRedoesIt) {
  EditSession session = background_session();
  ASSERT_TRUE(session.edit("level", level(3)));
  session.finish_evaluation();
  ASSERT_TRUE(session.edit("level", level(1)));  // small: at once
  ASSERT_FALSE(session.evaluating());
  ASSERT_TRUE(session.undo());  // back to level 3: large
  ASSERT_TRUE(session.evaluating());
  EXPECT_TRUE(session.cancel_evaluation());  // back to level 1, the undo redone
  EXPECT_EQ(session.document().objects[kSubd].as<SubdivisionSurface>().levels, 1);
  EXPECT_FALSE(session.can_redo());
  session.finish_evaluation();
  expect_scene_is_evaluation_of_document(session);
}

TEST(BackgroundEvaluation, StructureChangesKeepTheSceneAlignedWithTheDocument) {
  EditSession session = background_session();
  ASSERT_TRUE(session.edit("level", level(3)));
  const std::size_t shown = subd_vertices(session);
  // The ring is unused: delete it, then add a curve at the end.
  ASSERT_TRUE(session.edit("delete", [](Document& doc) { return delete_object(doc, kRing); }));
  EXPECT_EQ(session.scene().objects.size(), session.document().objects.size());
  ASSERT_TRUE(session.edit("add", [](Document& doc) {
    add_curve(doc, "open B-spline (2D)", "added");
    return Change{{}, true};
  }));
  EXPECT_EQ(session.scene().objects.size(), session.document().objects.size());
  if (session.evaluating()) {
    EXPECT_EQ(subd_vertices(session), shown);                          // its last complete evaluation, moved along
    EXPECT_TRUE(session.scene().objects.back().curve.frames.empty());  // the new curve: nothing yet
  }
  session.finish_evaluation();
  expect_scene_is_evaluation_of_document(session);
}

TEST(BackgroundEvaluation, AFileTooLargeToEvaluateAtOnceShowsNothingUntilDone) {
  EditSession session;
  session.set_background(1);
  session.load(io::parse_swp(kFile), "test.swp");
  ASSERT_TRUE(session.evaluating());
  EXPECT_FALSE(session.can_cancel_evaluation());  // nothing to go back to
  EXPECT_EQ(session.scene().objects.size(), 3u);
  for (const EvaluatedObject& entry : session.scene().objects) {
    EXPECT_TRUE(entry.mesh.positions.empty());
    EXPECT_TRUE(entry.curve.frames.empty());
  }
  session.finish_evaluation();
  expect_scene_is_evaluation_of_document(session);
  EXPECT_FALSE(session.dirty());
}

TEST(BackgroundEvaluation, OffByDefault) {
  EditSession session;
  session.load(io::parse_swp(kFile), "test.swp");
  ASSERT_TRUE(session.edit("level", level(4)));
  EXPECT_FALSE(session.evaluating());
  expect_scene_is_evaluation_of_document(session);
}

}  // namespace
}  // namespace sweep::editor
