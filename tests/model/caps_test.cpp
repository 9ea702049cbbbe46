// The document's size caps, stated once (model/caps.hpp): the reader and the editor count the
// same things and say the same words, the reader at a token, the editor naming the object.
#include "model/caps.hpp"

#include "io/swp/read.hpp"
#include "model/edit/edit.hpp"
#include "model/file_limits.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

#include <string>

namespace {

using sweep::CapTally;
using sweep::Document;
using sweep::test::edit_error;
using sweep::test::error_of;

/// The words "expected ... (note)" of a breach, as both the reader's and the editor's messages
/// end (the reader puts ", found TOKEN" between them).
std::string words_in(const std::string& message) {
  const auto expected = message.find("expected ");
  return expected == std::string::npos ? message : message.substr(expected);
}

TEST(CapTally, CountsPointsSamplesAndVerticesAgainstTheirCaps) {
  CapTally tally;
  EXPECT_FALSE(tally.add_points(sweep::limits::kMaxControlPoints, "this curve"));
  const auto points = tally.add_points(1, "this object");
  ASSERT_TRUE(points);
  EXPECT_TRUE(points->whole_document);
  EXPECT_EQ(points->expected, "expected at most 10000000 control points in the whole document");
  EXPECT_EQ(points->note, "this object brings the total to 10000001");

  const auto one_curve = tally.add_samples(sweep::limits::kMaxCurveSamples + 1, "STEPS 7 gives");
  ASSERT_TRUE(one_curve);
  EXPECT_FALSE(one_curve->whole_document);
  EXPECT_EQ(one_curve->note, "STEPS 7 gives 10000001");
  EXPECT_FALSE(tally.add_samples(sweep::limits::kMaxCurveSamples, "STEPS 1 gives"))
      << "a curve over its own cap adds nothing to the total";
  EXPECT_FALSE(tally.add_samples(sweep::limits::kMaxCurveSamples, "STEPS 1 gives"));
  const auto total = tally.add_samples(1, "STEPS 1 gives");
  ASSERT_TRUE(total);
  EXPECT_TRUE(total->whole_document);

  const auto surface = tally.add_vertices(sweep::limits::kMaxMeshVertices + 1);
  ASSERT_TRUE(surface);
  EXPECT_EQ(surface->expected, "expected a surface of at most 50000000 vertices");
}

TEST(Caps, TheEditorSaysTheReadersWordsForACurveOverItsSampleCap) {
  // 101 pieces of STEPS 100000 are 10100001 samples.
  std::string points;
  for (int i = 0; i < 104; ++i) points += " [" + std::to_string(i) + " " + std::to_string(i % 2) + "]";
  const std::string reader = error_of("bsp2 long 100000 104" + points + "\n", "long.swp");
  EXPECT_EQ(reader,
            "long.swp:1:11: expected at most 10000000 samples per curve, found '100000' (STEPS 100000 gives 10100001)");
  Document doc = sweep::io::parse_swp("bsp2 long 1 104" + points + "\n", "long.swp");
  const std::string editor = edit_error(doc, [&] { sweep::set_steps_or_levels(doc, 0, 100000); });
  EXPECT_EQ(editor, "curve 'long': expected at most 10000000 samples per curve (STEPS 100000 gives 10100001)");
}

TEST(Caps, TheEditorCountsPatchAndCageVerticesAsTheReaderDoes) {
  // A B-spline patch of STEPS 100000 on 4 x 4 points is one patch of 100001^2 vertices.
  const std::string grid =
      "bsppatch g 100000 4 4 [0 0 0] [1 0 0] [2 0 0] [3 0 0] [0 1 0] [1 1 0] [2 1 0] [3 1 0] "
      "[0 2 0] [1 2 0] [2 2 0] [3 2 0] [0 3 0] [1 3 0] [2 3 0] [3 3 0]\n";
  const std::string reader = error_of(grid, "g.swp");
  EXPECT_NE(reader.find("expected a surface of at most 50000000 vertices"), std::string::npos) << reader;
  Document doc = sweep::io::parse_swp(
      "bsppatch g 2 4 4 [0 0 0] [1 0 0] [2 0 0] [3 0 0] [0 1 0] [1 1 0] [2 1 0] [3 1 0] "
      "[0 2 0] [1 2 0] [2 2 0] [3 2 0] [0 3 0] [1 3 0] [2 3 0] [3 3 0]\n",
      "g.swp");
  const std::string editor = edit_error(doc, [&] { sweep::set_steps_or_levels(doc, 0, 100000); });
  EXPECT_EQ(editor, "surface 'g': expected a surface of at most 50000000 vertices (this one would have 10000200001)");
  EXPECT_EQ(words_in(editor),
            words_in(reader.substr(0, reader.find(", found "))) + reader.substr(reader.find(" (this one would have")));
}

}  // namespace
