// Stable object ids: every object gets a distinct id on load or creation, edits keep it, undo and
// redo bring back the same ids, and ids are never reused within a session.
#include "editor/edit_session.hpp"
#include "io/swp/read.hpp"
#include "model/edit/edit.hpp"
#include "support/editor_test_support.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

namespace sweep::editor {
namespace {

constexpr const char* kText =
    "bsp2 profile 4 6\n[-1 1]\n[-1.2 0.5]\n[-0.8 0]\n[-1 -0.5]\n[-1 -1]\n[-0.5 -1.2]\n"
    "srev vase 12 profile\n"
    "circ ring 16 0.5\n";

using test::session_of;

std::vector<ObjectId> ids(const EditSession& session) {
  std::vector<ObjectId> out;
  for (const Object& o : session.document().objects) out.push_back(o.id);
  return out;
}

bool all_distinct_and_set(const std::vector<ObjectId>& list) {
  const std::set<ObjectId> unique(list.begin(), list.end());
  return unique.size() == list.size() && unique.count(kNoObject) == 0;
}

Change add_circle(Document& d) {
  add_curve(d, "circle", "added");
  return Change{{}, true};
}

TEST(ObjectId, LoadGivesEveryObjectADistinctNonZeroId) {
  const EditSession session = session_of(kText);
  const std::vector<ObjectId> loaded = ids(session);
  ASSERT_EQ(loaded.size(), 3u);
  EXPECT_TRUE(all_distinct_and_set(loaded));
}

TEST(ObjectId, EditsInPlaceKeepTheIds) {
  EditSession session = session_of(kText);
  const std::vector<ObjectId> before = ids(session);
  ASSERT_TRUE(session.edit("move", [](Document& d) { return move_point(d, 0, 2, {-0.6, 0.1, 0.0}); }));
  ASSERT_TRUE(session.edit("steps", [](Document& d) { return set_steps_or_levels(d, 1, 20); }));
  EXPECT_EQ(ids(session), before);
  ASSERT_TRUE(session.undo());
  ASSERT_TRUE(session.undo());
  EXPECT_EQ(ids(session), before);
}

TEST(ObjectId, AnAddedObjectGetsANewIdAndRedoBringsTheSameOneBack) {
  EditSession session = session_of(kText);
  const std::vector<ObjectId> before = ids(session);
  ASSERT_TRUE(session.edit("add", add_circle));
  const std::vector<ObjectId> after = ids(session);
  ASSERT_EQ(after.size(), 4u);
  EXPECT_TRUE(std::equal(before.begin(), before.end(), after.begin())) << "the old objects keep theirs";
  EXPECT_TRUE(all_distinct_and_set(after));
  const ObjectId added = after[3];

  ASSERT_TRUE(session.undo());
  EXPECT_EQ(ids(session), before);
  EXPECT_EQ(session.index_of(added), -1);
  ASSERT_TRUE(session.redo());
  EXPECT_EQ(ids(session), after) << "redo brings back the id the add gave";
  EXPECT_EQ(session.index_of(added), 3);
}

TEST(ObjectId, AnAddInsideAContinuousStepKeepsItsIdThroughUndoAndRedo) {
  EditSession session = session_of(kText);
  session.begin_step("add and move");
  ASSERT_TRUE(session.apply(add_circle));
  ASSERT_TRUE(session.apply([](Document& d) { return set_radius(d, 3, 0.25); }));
  session.end_step();
  const std::vector<ObjectId> after = ids(session);
  ASSERT_EQ(after.size(), 4u);
  ASSERT_TRUE(session.undo());
  ASSERT_TRUE(session.redo());
  EXPECT_EQ(ids(session), after);
}

TEST(ObjectId, UndoOfADeleteBringsBackTheSameIdAtTheSameIndex) {
  EditSession session = session_of(kText);
  const std::vector<ObjectId> before = ids(session);
  const ObjectId vase = session.id_of(1);
  ASSERT_TRUE(session.edit("delete", [](Document& d) { return delete_object(d, 1); }));
  EXPECT_EQ(session.index_of(vase), -1) << "a deleted id has no index";
  EXPECT_EQ(ids(session), (std::vector<ObjectId>{before[0], before[2]}));
  EXPECT_EQ(session.index_of(before[2]), 1) << "the ring moved up and kept its id";

  ASSERT_TRUE(session.undo());
  EXPECT_EQ(ids(session), before);
  EXPECT_EQ(session.index_of(vase), 1);
  ASSERT_TRUE(session.redo());
  EXPECT_EQ(session.index_of(vase), -1);
  EXPECT_EQ(session.index_of(before[2]), 1);
}

TEST(ObjectId, IndexOfAndIdOfAreInverse) {
  EditSession session = session_of(kText);
  ASSERT_TRUE(session.edit("add", add_circle));
  const int count = static_cast<int>(session.document().objects.size());
  for (int i = 0; i < count; ++i) {
    EXPECT_EQ(session.index_of(session.id_of(i)), i);
    EXPECT_EQ(session.id_of(i), session.document().objects[std::size_t(i)].id);
  }
  for (ObjectId id : ids(session)) EXPECT_EQ(session.id_of(session.index_of(id)), id);
  EXPECT_EQ(session.id_of(-1), kNoObject);
  EXPECT_EQ(session.id_of(count), kNoObject);
  EXPECT_EQ(session.index_of(kNoObject), -1);
  const std::vector<ObjectId> all = ids(session);
  EXPECT_EQ(session.index_of(*std::max_element(all.begin(), all.end()) + 1), -1) << "never given";
}

TEST(ObjectId, IdsAreNeverReusedWithinASession) {
  EditSession session = session_of(kText);
  std::set<ObjectId> seen;
  for (ObjectId id : ids(session)) seen.insert(id);

  // An undone add's id is not given to the next add.
  ASSERT_TRUE(session.edit("add", add_circle));
  const ObjectId undone = session.id_of(3);
  seen.insert(undone);
  ASSERT_TRUE(session.undo());
  ASSERT_TRUE(session.edit("add again", add_circle));
  EXPECT_EQ(seen.count(session.id_of(3)), 0u) << "id " << session.id_of(3) << " reused";
  seen.insert(session.id_of(3));

  // A new document gets fresh ids, even the same document loaded again with its ids set.
  const Document reloaded = session.document();
  session.load(reloaded, "again.swp");
  const std::vector<ObjectId> fresh = ids(session);
  EXPECT_TRUE(all_distinct_and_set(fresh));
  for (ObjectId id : fresh) EXPECT_EQ(seen.count(id), 0u) << "id " << id << " reused after load";
  for (ObjectId id : fresh) seen.insert(id);

  session.load(io::parse_swp("circ a 8 1\ncirc b 8 1\n"), "other.swp");
  for (ObjectId id : ids(session)) EXPECT_EQ(seen.count(id), 0u) << "id " << id << " reused after load";
  EXPECT_FALSE(session.can_undo()) << "loading forgets the history";
}

}  // namespace
}  // namespace sweep::editor
