// Recovering a copy keeps the file's text where the copy has the same objects (replace_objects):
// a save after it rewrites only what the copy changed. Found by the session's state machine test
// (tests/desktop/session_state_machine_test.cpp): recovery replaced the whole document, text
// included, so a later save rewrote every line in write_swp's style even when the copy was the
// file.
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/edit/edit.hpp"

#include <gtest/gtest.h>

#include <string>

namespace sweep {
namespace {

constexpr const char* kTyped =
    "circ   ring 8 2.0\r\nbsp2 wave 4 4\r\n[0 0]\r\n[1  1]\r\n[2 0]\r\n[3 1]\r\nsrev   v 12 wave\r\n";

TEST(RecoverObjects, ACopyEqualToTheFileChangesNothing) {
  Document doc = io::parse_swp_keeping_source(kTyped);
  const Change change = replace_objects(doc, io::parse_swp(io::write_swp(doc)));
  EXPECT_FALSE(change.structure);
  EXPECT_TRUE(change.objects.empty());
  EXPECT_EQ(io::write_swp_preserving(doc), kTyped);
}

TEST(RecoverObjects, OnlyWhatTheCopyChangedIsRewritten) {
  Document doc = io::parse_swp_keeping_source(kTyped);
  Document copy = io::parse_swp(io::write_swp(doc));
  copy.objects[1].as<PointsPart>().points[1] = {1.5, 2.0, 0.0};  // the wave edited, then the crash
  const Change change = replace_objects(doc, copy);
  EXPECT_TRUE(change.structure);
  EXPECT_EQ(doc, copy);
  const std::string saved = io::write_swp_preserving(doc);
  EXPECT_EQ(saved.rfind("circ   ring 8 2.0", 0), 0u) << "the ring as typed:\n" << saved;
  EXPECT_NE(saved.find("srev   v 12 wave\r\n"), std::string::npos) << "the srev as typed:\n" << saved;
  EXPECT_NE(saved.find("[1.5 2]"), std::string::npos) << saved;
  EXPECT_EQ(io::parse_swp(saved), copy);
}

}  // namespace
}  // namespace sweep
