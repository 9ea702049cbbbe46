// The viewer's edit session (no window): edits, undo and redo keep the scene in step with the
// document and re-evaluate only what changed; failures change nothing and say why; saving.
#include "editor/edit_session.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/edit/edit_insert.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "support/editor_test_support.hpp"
#include "support/file_support.hpp"

#include <gtest/gtest.h>
#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

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
  EXPECT_EQ(io::load_swp_file(path), session.document());
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

/// The numbers between '[' and ']' of SWP text, as written.
std::vector<std::string> point_numbers(const std::string& text) {
  std::vector<std::string> out;
  bool inside = false;
  std::string word;
  for (const char c : text + ' ') {
    if (inside && (c == ' ' || c == ']') && !word.empty()) {
      out.push_back(word);
      word.clear();
    }
    if (c == '[') inside = true;
    if (c == ']') inside = false;
    if (inside && c != '[' && c != ' ') word += c;
  }
  return out;
}

/// Digits after the point ("-1.015506": 6, "2": 0).
int decimals(const std::string& number) {
  const std::size_t point = number.find('.');
  return point == std::string::npos ? 0 : int(number.size() - point - 1);
}

TEST(EditSession, ANewDocumentSavesThePointsPlacedWithTheMouseInShortNumbers) {
  // A new document: a Create panel template, a point dragged to where the mouse let go, a point
  // inserted at a double-click. Saved, every coordinate is the shortest text within a millionth
  // of the scene's size (the precision edits of a file read are saved in), not 17 digits.
  const fs::path dir = fs::path(SWEEP_TEST_OUTPUT_DIR) / "edit_session_new";
  fs::remove_all(dir);
  fs::create_directories(dir);
  EditSession session;
  session.load(Document{}, "");
  ASSERT_TRUE(session.edit("add curve", [](Document& d) {
    return Change{{add_curve(d, "open B-spline (2D)", "profile")}, true};
  }));
  ASSERT_TRUE(session.edit("add curve", [](Document& d) {
    return Change{{add_curve(d, "star polyline (2D)", "star")}, true};
  }));
  const glm::dvec3 dropped(-1.0155057200058235, 0.31415926535897931, 0.0);
  session.begin_step("drag");
  ASSERT_TRUE(session.apply([](Document& d) { return move_point(d, 0, 1, {-0.9, 0.3, 0.0}); }));
  ASSERT_TRUE(session.apply([&dropped](Document& d) { return move_point(d, 0, 1, dropped); }));
  session.end_step();
  ASSERT_TRUE(session.edit("insert point", [](Document& d) { return insert_point_at(d, 0, 1.3712345678901); }));
  const Document& doc = session.document();
  const double tolerance = 1e-6 * document_extent(doc);
  ASSERT_GT(tolerance, 1e-7);
  ASSERT_LT(tolerance, 1e-5);  // six decimals, as in the starter files

  const fs::path path = dir / "new.swp";
  ASSERT_TRUE(session.save(path.string())) << session.error();
  const std::string text = sweep::test::read_file(path);
  EXPECT_NE(text.find("\n[-1.015506 0.31416]\n"), std::string::npos) << text;  // 7e-7 off, within 1.8e-6
  EXPECT_EQ(text.find("0155057"), std::string::npos) << text;
  // Every coordinate: within the tolerance of the point, and one decimal less would not be.
  const std::vector<std::string> written = point_numbers(text);
  std::vector<double> exact;
  for (const Object& o : doc.objects) {
    for (const glm::dvec3& p : points_of(o)) {
      exact.push_back(p.x);
      exact.push_back(p.y);
    }
  }
  ASSERT_EQ(written.size(), exact.size()) << text;
  int long_ones = 0;
  for (std::size_t k = 0; k < written.size(); ++k) {
    const double value = std::stod(written[k]);
    EXPECT_LE(std::abs(value - exact[k]), tolerance) << written[k];
    const int d = decimals(written[k]);
    EXPECT_LE(d, 7) << written[k];
    if (d > 0) {
      char shorter[64];
      std::snprintf(shorter, sizeof shorter, "%.*f", d - 1, exact[k]);
      EXPECT_GT(std::abs(std::stod(shorter) - exact[k]), tolerance) << written[k] << " is not the shortest";
    }
    long_ones += number_text(exact[k]).size() > written[k].size() ? 1 : 0;
  }
  EXPECT_GE(long_ones, 10) << "the star's, the dragged and the inserted points were 17 digits long";
  // It reads back as the document, its points within the tolerance.
  const Document back = io::load_swp_file(path);
  ASSERT_EQ(back.objects.size(), doc.objects.size());
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    EXPECT_EQ(back.objects[i].kind(), doc.objects[i].kind());
    const auto p = points_of(back.objects[i]), q = points_of(doc.objects[i]);
    ASSERT_EQ(p.size(), q.size());
    for (std::size_t k = 0; k < p.size(); ++k) EXPECT_LE(glm::length(p[k] - q[k]), 2.0 * tolerance);
  }
  EXPECT_EQ(text, io::write_swp_rounded(doc));
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
