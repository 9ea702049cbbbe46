// Editing riders: add_rider and set_rider check references and clauses as the reader does, and a
// refused edit leaves the document as it was; deleting or unnaming what a rider uses is refused
// naming the rider.
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/edit/edit.hpp"
#include "support/core_test_support.hpp"

#include <gtest/gtest.h>

namespace sweep {
namespace {

const char* kFile =
    "circ track 40 2\n"
    "circ body 12 0.2\n"
    "poly3 spine 2\n[0 0 0]\n[0 0 1]\n"
    "gcyl car body spine\n"
    "material red color 1 0 0\n"
    "rider r track car\n";

TEST(EditRider, AddRiderAppendsOneThatWritesAndReadsBack) {
  Document doc = io::parse_swp(kFile);
  const int index = add_rider(doc, "r2", doc.find("track"), doc.find("car"));
  EXPECT_EQ(index, static_cast<int>(doc.objects.size()) - 1);
  const std::string text = io::write_swp(doc);
  EXPECT_NE(text.find("rider r2 track car\n"), std::string::npos) << text;
  EXPECT_EQ(io::parse_swp(text), doc);
}

TEST(EditRider, AddRiderRefusesWhatTheReaderRefuses) {
  Document doc = io::parse_swp(kFile);
  EXPECT_EQ(test::edit_error(doc, [&] { add_rider(doc, "x", doc.find("car"), doc.find("car")); }),
            "'car' cannot be the path: expected a curve, it is a surface (gcyl)");
  EXPECT_EQ(test::edit_error(doc, [&] { add_rider(doc, "x", doc.find("track"), doc.find("red")); }),
            "'red' cannot be the model: expected a surface, it is a material (material)");
  EXPECT_EQ(test::edit_error(doc, [&] { add_rider(doc, "r", doc.find("track"), doc.find("car")); }),
            "name 'r' is already used by another object");
}

TEST(EditRider, SetRiderChangesClausesAsOneCheckedEdit) {
  Document doc = io::parse_swp(kFile);
  const int r = doc.find("r");
  RiderObject value = doc.objects[std::size_t(r)].as<RiderObject>();
  value.seconds = 4.0;
  value.start = 0.5;
  value.up = {0.0, 1.0, 0.0};
  set_rider(doc, r, value);
  EXPECT_NE(io::write_swp(doc).find("rider r track car seconds 4 start 0.5 up 0 1 0\n"), std::string::npos);
  value.seconds = 0.0;
  EXPECT_EQ(test::edit_error(doc, [&] { set_rider(doc, r, value); }),
            "expected seconds greater than 0, at most 1e9, not 0");
  value.seconds = 4.0;
  value.start = 1.0;
  EXPECT_EQ(test::edit_error(doc, [&] { set_rider(doc, r, value); }),
            "expected start from 0 up to (not including) 1, not 1");
}

TEST(EditRider, WhatARiderUsesCannotBeDeletedOrUnnamed) {
  Document doc = io::parse_swp(kFile);
  EXPECT_EQ(test::edit_error(doc, [&] { delete_object(doc, doc.find("track")); }),
            "cannot delete 'track': rider 'r' uses it");
  EXPECT_EQ(test::edit_error(doc, [&] { rename_object(doc, doc.find("car"), ""); }),
            "cannot remove the name of 'car': rider 'r' uses it");
  EXPECT_EQ(test::edit_error(doc, [&] { delete_object(doc, doc.find("body")); }),
            "cannot delete 'body': surface 'car' uses it");
}

}  // namespace
}  // namespace sweep
