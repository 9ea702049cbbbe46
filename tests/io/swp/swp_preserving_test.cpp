// Format-preserving saving (write_swp_preserving): a file read and saved unchanged comes back
// byte for byte; moving one point changes exactly that point's line, in the file's precision;
// renaming changes the lines that name the object; inserting, deleting and adding keep every
// other line as it was; CRLF files stay CRLF. Every starter file, the originals and the artifacts.
#include "io/swp/clause_order.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/edit/edit.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "support/core_test_support.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

namespace sweep {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> every_file() {
  std::vector<fs::path> files = test::starter_files();
  for (const fs::path& f : test::artifact_files()) files.push_back(f);
  const fs::path originals = fs::path(SWEEP_SWP_DIR) / ".." / ".." / "shared" / "swp";
  if (fs::is_directory(originals)) {
    for (const fs::path& f : test::swp_files_in(originals)) files.push_back(f);
  }
  return files;
}

/// The file's lines, each with its line end.
std::vector<std::string> lines_of(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t from = 0;
  while (from < text.size()) {
    const std::size_t end = text.find('\n', from);
    const std::size_t to = end == std::string::npos ? text.size() : end + 1;
    lines.push_back(text.substr(from, to - from));
    from = to;
  }
  return lines;
}

/// The index in `lines` of the line of point k of the object whose keyword is on line
/// `object_line` (1-based): the line of the k-th '[' from there (a line may hold several).
std::size_t point_line(const std::vector<std::string>& lines, int object_line, std::size_t k) {
  std::size_t seen = 0;
  for (std::size_t n = static_cast<std::size_t>(object_line) - 1; n < lines.size(); ++n) {
    seen += static_cast<std::size_t>(std::count(lines[n].begin(), lines[n].end(), '['));
    if (seen > k) return n;
  }
  ADD_FAILURE() << "no point " << k << " after line " << object_line;
  return 0;
}

/// Lines of `after` not in `before` at the same place (same line count required).
int changed_lines(const std::string& before, const std::string& after) {
  const std::vector<std::string> a = lines_of(before), b = lines_of(after);
  if (a.size() != b.size()) return -1;
  int changed = 0;
  for (std::size_t k = 0; k < a.size(); ++k) changed += a[k] != b[k] ? 1 : 0;
  return changed;
}

Document read(const fs::path& file) {
  return io::load_swp_file(file);
}

/// The document `text` reads as, with its numbers compared to a millionth of its size.
void expect_reads_as(const std::string& text, const Document& doc, const std::string& what,
                     const fs::path& file = "x.swp") {
  const Document back = io::parse_swp(text, file.string());  // images are found beside `file`
  ASSERT_EQ(back.objects.size(), doc.objects.size()) << what;
  const double tolerance = 1e-6 * document_extent(doc);
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    EXPECT_EQ(back.objects[i].name, doc.objects[i].name) << what;
    EXPECT_EQ(back.objects[i].kind(), doc.objects[i].kind()) << what;
    const auto p = points_of(back.objects[i]), q = points_of(doc.objects[i]);
    ASSERT_EQ(p.size(), q.size()) << what << " object " << i;
    for (std::size_t k = 0; k < p.size(); ++k) {
      EXPECT_LE(glm::length(p[k] - q[k]), 2.0 * tolerance) << what << " object " << i << " point " << k;
    }
  }
}

TEST(SwpPreserving, EveryFileSavedUnchangedIsByteForByteTheSame) {
  for (const fs::path& file : every_file()) {
    const std::string text = test::read_file(file);
    EXPECT_TRUE(io::write_swp_preserving(read(file)) == text) << file;
  }
}

TEST(SwpPreserving, MovingAnyOnePointChangesExactlyItsLine) {
  for (const fs::path& file : every_file()) {
    const std::string text = test::read_file(file);
    const Document doc = read(file);
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      const std::size_t count = points_of(doc.objects[i]).size();
      if (count == 0 || !has_editable_points(doc.objects[i].kind())) continue;
      for (const std::size_t k : {std::size_t{0}, count / 2, count - 1}) {
        Document moved = doc;
        auto& points = moved.objects[i].as<PointsPart>().points;
        points[k] +=
            glm::dvec3(-0.1234567890123, 0.0472135954999, is_planar_curve(moved.objects[i].kind()) ? 0.0 : 0.3);
        const std::string saved = io::write_swp_preserving(moved);
        const std::string what =
            file.filename().string() + " object " + std::to_string(i) + " point " + std::to_string(k);
        EXPECT_EQ(changed_lines(text, saved), 1) << what;
        bool valid = true;  // a scale graph that goes back in x, say, is refused by the reader
        try {
          io::validate_document(moved);
        } catch (const io::ParseError&) {
          valid = false;
        }
        if (valid) expect_reads_as(saved, moved, what, file);
        moved.objects[i].as<PointsPart>().points[k] = doc.objects[i].as<PointsPart>().points[k];  // undo
        EXPECT_TRUE(io::write_swp_preserving(moved) == text) << what << ": undone";
      }
    }
  }
}

TEST(SwpPreserving, AMovedNumberKeepsItsLinesDecimalsAndACrlfFileStaysCrlf) {
  const fs::path file = fs::path(SWEEP_SWP_DIR) / "flircle.swp";
  const std::string text = test::read_file(file);
  ASSERT_NE(text.find("\r\n"), std::string::npos);
  Document doc = read(file);
  int curve = -1;
  for (std::size_t i = 0; i < doc.objects.size() && curve < 0; ++i) {
    if (!points_of(doc.objects[i]).empty()) curve = static_cast<int>(i);
  }
  ASSERT_GE(curve, 0);
  doc.objects[static_cast<std::size_t>(curve)].as<PointsPart>().points[1].x = -2.182528760804141;
  const std::string saved = io::write_swp_preserving(doc);
  EXPECT_NE(saved.find("-2.182529"), std::string::npos);
  EXPECT_EQ(saved.find("-2.18252876"), std::string::npos);
  for (std::size_t at = saved.find('\n'); at != std::string::npos; at = saved.find('\n', at + 1)) {
    ASSERT_GT(at, 0u);
    EXPECT_EQ(saved[at - 1], '\r') << "a bare line feed at byte " << at;
  }
}

TEST(SwpPreserving, ANumberFarFromItsLinesPrecisionGetsTheDecimalsItNeeds) {
  // Whole numbers in the file: a moved point needs decimals to stay within a millionth of the size.
  Document doc = io::parse_swp_keeping_source("bez2 c 4 4\n[0 1]\n[1 2]\n[2 2]\n[3 1]\n", "whole.swp");
  doc.objects[0].as<PointsPart>().points[1].x = 1.0 / 3.0;
  const std::string saved = io::write_swp_preserving(doc);
  EXPECT_EQ(lines_of(saved)[2], "[0.333333 2]\n");  // size ~3.2: 3e-6 allows six decimals, not five
  expect_reads_as(saved, doc, "whole.swp");
}

TEST(SwpPreserving, ClausesInTheFilesOwnOrderOrCaseOrAtTheirDefaultStayAsWritten) {
  const std::string text =
      "CR2 p 4 3 Alpha 0.5 tolerance 0.05\n[0 0]\n[1 1]\n[2 0]\n\ncirc s 12 2\n\nsrev r 8 p caps\n";
  Document doc = io::parse_swp_keeping_source(text, "order.swp");
  EXPECT_TRUE(io::write_swp_preserving(doc) == text);
  doc.objects[0].as<PointsPart>().points[1].y = 1.5;  // the header is as the file wrote it
  EXPECT_EQ(io::write_swp_preserving(doc),
            "CR2 p 4 3 Alpha 0.5 tolerance 0.05\n[0 0]\n[1 1.5]\n[2 0]\n\ncirc s 12 2\n\nsrev r 8 p caps\n");
  doc.objects[0].as<PointsPart>().points.pop_back();  // a count that changes: only the count
  const std::string fewer = io::write_swp_preserving(doc);
  EXPECT_EQ(fewer, "CR2 p 4 2 Alpha 0.5 tolerance 0.05\n[0 0]\n[1 1.5]\n\ncirc s 12 2\n\nsrev r 8 p caps\n");
  expect_reads_as(fewer, doc, "order.swp");
  doc.objects[0].as<PointsPart>().points.push_back({3.0, 0.25, 0.0});
  doc.objects[0].as<TensionPart>().tension = 0.5;  // more than the points: the line is rewritten
  const std::string tense = io::write_swp_preserving(doc);
  EXPECT_EQ(lines_of(tense)[0], "CR2 p 4 3 tolerance 0.05 tension 0.50\n")
      << "the file's tolerance clause stays where it was; the new one follows at its precision";
  expect_reads_as(tense, doc, "order.swp");
}

TEST(SwpPreserving, AnInsertedPointsWholeNumbersGetTheirNeighboursDecimalsButACagesFacesStayIntegers) {
  const fs::path file = fs::path(SWEEP_SWP_DIR) / "wineglass.swp";
  Document doc = read(file);
  doc.objects[0].as<PointsPart>().points.push_back({-1.0, 3.0, 0.0});
  const std::string saved = io::write_swp_preserving(doc);
  const std::vector<std::string> lines = lines_of(saved);
  EXPECT_EQ(lines[point_line(lines, 1, 26)], "[-1.000000 3.000000]\n");

  const fs::path cages = fs::path(SWEEP_SWP_DIR) / "subdivision.swp";
  Document cube = read(cages);
  auto& cage = cube.objects[0].as<PolygonMeshSurface>();
  cage.points.push_back({-12.8, 0.0, 2.0});  // a pyramid on the top face [4 5 6 7]
  cage.face_sizes = {4, 3, 3, 3, 3, 4, 4, 4, 4};
  cage.face_vertices = {0, 3, 2, 1, 4, 5, 8, 5, 6, 8, 6, 7, 8, 7, 4, 8, 0, 1, 5, 4, 1, 2, 6, 5, 2, 3, 7, 6, 3, 0, 4, 7};
  const std::string pyramid = io::write_swp_preserving(cube);
  EXPECT_EQ(pyramid.find(".000000"), std::string::npos) << "no coordinate or index gets decimals here";
  EXPECT_EQ(lines_of(pyramid)[0], "mesh cube0 9 9\n");
  expect_reads_as(pyramid, cube, "subdivision.swp", cages);
}

TEST(SwpPreserving, ChangedClausesKeepTheOrderTheFileWroteThemIn) {
  const std::string text =
      "material tiles checker 4 shininess 32\n\ncirc ring 12 0.5\ncirc path 24 3\n"
      "gcyl tiled ring path Caps material tiles Twist 90\n";
  Document doc = io::parse_swp_keeping_source(text, "tiles.swp");
  auto& look = doc.objects[0].as<MaterialLook>();
  look.shininess = 250.0;
  look.checker = 12;
  EXPECT_EQ(lines_of(io::write_swp_preserving(doc))[0], "material tiles checker 12 shininess 250\n");
  doc.objects[3].as<CylinderSurface>().twist = 180.0;
  doc.objects[3].as<CapsPart>().caps = false;  // a clause gone; the others stay in the file's order
  const std::string saved = io::write_swp_preserving(doc);
  EXPECT_EQ(lines_of(saved)[4], "gcyl tiled ring path material tiles Twist 180\n");
  expect_reads_as(saved, doc, "tiles.swp");
  // A clause the file lacks goes after the file's; a key in another case is the same key.
  EXPECT_EQ(
      io::in_clause_order_of("material tiles CHECKER 4 shininess 32\n",
                             "material tiles shininess 250 bump grain.png 0.5 checker 12\n", ObjectKind::Material),
      "material tiles checker 12 shininess 250 bump grain.png 0.5\n");
  EXPECT_EQ(io::in_clause_order_of("circ r 12 1\n", "circ r 12 2\n", ObjectKind::Circle), "circ r 12 2\n");
}

TEST(SwpPreserving, RenamingChangesTheLinesThatNameTheObjectAndNoOther) {
  const fs::path file = fs::path(SWEEP_SWP_DIR) / "weird.swp";
  const std::string text = test::read_file(file);
  Document doc = read(file);
  const int profile = doc.find("profile");
  ASSERT_GE(profile, 0);
  doc.objects[static_cast<std::size_t>(profile)].name = "outline";
  const std::string saved = io::write_swp_preserving(doc);
  const std::vector<std::string> a = lines_of(text), b = lines_of(saved);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t k = 0; k < a.size(); ++k) {
    const bool names = a[k].find("profile") != std::string::npos;
    EXPECT_EQ(a[k] != b[k], names) << "line " << k + 1 << ": " << a[k];
  }
  EXPECT_EQ(io::parse_swp(saved).find("outline"), profile);
}

TEST(SwpPreserving, InsertingAndDeletingAPointChangeItsCountAndOneLineOnly) {
  const fs::path file = fs::path(SWEEP_SWP_DIR) / "wineglass.swp";
  const std::string text = test::read_file(file);
  const std::vector<std::string> before = lines_of(text);
  Document doc = read(file);
  auto& points = doc.objects[0].as<PointsPart>().points;
  const glm::dvec3 middle = 0.5 * (points[2] + points[3]);
  points.insert(points.begin() + 3, middle);
  const std::string inserted = io::write_swp_preserving(doc);
  std::vector<std::string> expected = before;
  expected[0] = "bsp2 profile 8 27\n";
  expected.insert(expected.begin() + static_cast<std::ptrdiff_t>(point_line(before, 1, 3)), "[0.000000 -0.459545]\n");
  expected[point_line(expected, 1, 3)] = lines_of(inserted)[point_line(expected, 1, 3)];  // the midpoint
  EXPECT_EQ(lines_of(inserted), expected);
  EXPECT_EQ(lines_of(inserted)[point_line(expected, 1, 3)], "[-0.175941 -0.443146]\n");
  expect_reads_as(inserted, doc, "inserted");

  points.erase(points.begin() + 3);
  points.erase(points.begin() + 1);
  const std::string deleted = io::write_swp_preserving(doc);
  expected = before;
  expected[0] = "bsp2 profile 8 25\n";
  expected.erase(expected.begin() + static_cast<std::ptrdiff_t>(point_line(before, 1, 1)));
  EXPECT_EQ(lines_of(deleted), expected);
  expect_reads_as(deleted, doc, "deleted");
}

TEST(SwpPreserving, ANewObjectFollowsTheFilesStyleAndDeletingOneKeepsTheRest) {
  const fs::path file = fs::path(SWEEP_SWP_DIR) / "florus.swp";  // CRLF
  const std::string text = test::read_file(file);
  Document doc = read(file);
  Object ring(ObjectKind::Circle);
  ring.name = "ring";
  ring.as<StepsPart>().steps = 12;
  ring.as<RadiusPart>().radius = 0.5;
  doc.objects.push_back(ring);
  const std::string added = io::write_swp_preserving(doc);
  const std::size_t content_end = text.find_last_not_of(" \t\r\n") + 1;
  EXPECT_EQ(added.substr(0, content_end), text.substr(0, content_end));
  EXPECT_NE(added.find("\r\n\r\ncirc ring 12 0.5"), std::string::npos) << added.substr(content_end);
  expect_reads_as(added, doc, "added");

  doc.objects.pop_back();
  doc.objects.erase(doc.objects.begin());  // the first curve, if nothing uses it...
  if (doc.objects.empty()) return;
  try {
    io::validate_document(doc);
  } catch (const io::ParseError&) {
    return;  // ...a surface needs it: nothing to check
  }
  const std::string deleted = io::write_swp_preserving(doc);
  EXPECT_NE(text.find(deleted.substr(deleted.find_first_not_of("\r\n"))), std::string::npos);
}

TEST(SwpPreserving, ANewCurvesPointsUseTheDecimalsOfTheFilesPoints) {
  const fs::path file = fs::path(SWEEP_SWP_DIR) / "wineglass.swp";  // six decimals: [0.000000 -0.459543]
  Document doc = read(file);
  Object curve(ObjectKind::BSpline2);
  curve.name = "drawn";
  curve.as<StepsPart>().steps = 8;
  curve.as<PointsPart>().points = {{-0.5, 1.25, 0.0}, {0.0, 2.0, 0.0}, {0.123456789, -1.0, 0.0}, {-2.0, 0.1, 0.0}};
  doc.objects.push_back(curve);
  const std::string saved = io::write_swp_preserving(doc);
  const std::string added = saved.substr(saved.find("bsp2 drawn"));
  EXPECT_NE(added.find("[-0.500000 1.250000]"), std::string::npos) << added;
  EXPECT_NE(added.find("[0.000000 2.000000]"), std::string::npos) << "integers in a point get the decimals too";
  EXPECT_NE(added.find("[0.123457 -1.000000]"), std::string::npos) << "rounded within a millionth of the scene";
  EXPECT_EQ(added.find("0.123456789"), std::string::npos);
  expect_reads_as(saved, doc, "added");
}

TEST(SwpPreserving, ANewCurveInAFileOfShortNumbersKeepsTheShortestText) {
  const std::string text = "bsp2 a 4 4\n[0 0]\n[1 0]\n[1 1]\n[0 1]\n";
  Document doc = io::parse_swp(text, "short.swp");
  doc.source.text = std::make_shared<const std::string>(text);
  Object curve = doc.objects.front();
  curve.name = "b";
  curve.location = {};
  curve.as<PointsPart>().points[0] = {0.25, 0.5, 0.0};
  doc.objects.push_back(curve);
  const std::string saved = io::write_swp_preserving(doc);
  EXPECT_NE(saved.find("[0.25 0.5]"), std::string::npos) << saved;
}

TEST(SwpPreserving, ANewCurvesLongNumbersInAFileOfWholeNumbersGetTheFewDecimalsTheyNeed) {
  // A file whose points have no decimals: a new curve's points as in a new document
  // (write_swp_rounded), the shortest text within a millionth of the scene, not 17 digits.
  const std::string text = "bsp2 a 4 4\n[0 0]\n[1 0]\n[1 1]\n[0 1]\n";
  Document doc = io::parse_swp(text, "whole.swp");
  doc.source.text = std::make_shared<const std::string>(text);
  Object curve = doc.objects.front();
  curve.name = "b";
  curve.location = {};
  curve.as<PointsPart>().points[0] = {0.1 + 0.2, 2.0 / 3.0, 0.0};  // 0.30000000000000004, 0.6666666666666666
  doc.objects.push_back(curve);
  const std::string saved = io::write_swp_preserving(doc);
  EXPECT_EQ(saved.substr(saved.find("bsp2 b")), "bsp2 b 4 4\n[0.3 0.666667]\n[1 0]\n[1 1]\n[0 1]\n") << saved;
  expect_reads_as(saved, doc, "added");
}

TEST(SwpPreserving, ANewDocumentRoundedWritesItsPointsShortAndTheRestExactly) {
  // write_swp_rounded (what the editor saves a new document with): the numbers in points are the
  // shortest text within a millionth of the scene's size; fields and clauses as write_swp writes
  // them; a cage's faces stay integers; -0 is 0.
  Document doc;
  Object curve(ObjectKind::BSpline2);
  curve.name = "drawn";
  curve.as<StepsPart>().steps = 8;
  curve.as<PointsPart>().points = {
      {-1.0155057200058235, 1.25, 0.0}, {-1e-9, 2.0, 0.0}, {0.123456789, -1.0, 0.0}, {-2.0, 0.1, 0.0}};
  doc.objects.push_back(curve);
  Object ring(ObjectKind::Circle);
  ring.name = "ring";
  ring.as<StepsPart>().steps = 12;
  ring.as<RadiusPart>().radius = 0.123456789012345;
  doc.objects.push_back(ring);
  Object cage(ObjectKind::PolygonMesh);
  cage.name = "cage";
  cage.as<PointsPart>().points = {{0, 0, 0}, {1.0 / 3.0, 0, 0}, {0, 1, 0}};
  cage.as<PolygonMeshSurface>().face_sizes = {3};
  cage.as<PolygonMeshSurface>().face_vertices = {0, 1, 2};
  doc.objects.push_back(cage);
  ASSERT_NO_THROW(io::validate_document(doc));
  ASSERT_NEAR(document_extent(doc), 3.8, 0.01);  // a tolerance of 3.8e-6: 0.12346 is 3.2e-6 off
  EXPECT_EQ(io::write_swp_rounded(doc),
            "bsp2 drawn 8 4\n[-1.015506 1.25]\n[0 2]\n[0.12346 -1]\n[-2 0.1]\n\n"
            "circ ring 12 0.123456789012345\n\n"
            "mesh cage 3 1\n[0 0 0]\n[0.3333333333333333 0 0]\n[0 1 0]\n[0 1 2]\n\n");
  expect_reads_as(io::write_swp_rounded(doc), doc, "rounded");
  // Short numbers stay as write_swp writes them; an empty document is empty.
  Document small = io::parse_swp("bsp2 a 4 4\n[0 0]\n[0.25 0]\n[1 1.5]\n[0 1]\n", "small.swp");
  EXPECT_EQ(io::write_swp_rounded(small), io::write_swp(small));
  EXPECT_EQ(io::write_swp_rounded(Document{}), "");
}

TEST(SwpPreserving, RandomEditsKeepEveryUntouchedLineAndReadBack) {
  std::mt19937 random(20261202);
  for (const fs::path& file : test::starter_files()) {
    const std::string text = test::read_file(file);
    Document doc = read(file);
    const std::vector<std::string> a = lines_of(text);
    std::vector<std::size_t> lines_touched;
    for (int edit = 0; edit < 5; ++edit) {
      const std::size_t i = random() % doc.objects.size();
      if (!has_editable_points(doc.objects[i].kind())) continue;
      auto& points = doc.objects[i].as<PointsPart>().points;
      if (points.empty()) continue;
      const std::size_t k = random() % points.size();
      const glm::dvec3 was = points[k];
      points[k].y += std::uniform_real_distribution<double>(-0.5, 0.5)(random);
      try {
        io::validate_document(doc);
      } catch (const io::ParseError&) {  // a scale graph below 0, say: not an edit the editor makes
        points[k] = was;
        continue;
      }
      lines_touched.push_back(point_line(a, doc.objects[i].location.line, k));
    }
    const std::string saved = io::write_swp_preserving(doc);
    const std::vector<std::string> b = lines_of(saved);
    ASSERT_EQ(a.size(), b.size()) << file;
    for (std::size_t n = 0; n < a.size(); ++n) {
      if (std::find(lines_touched.begin(), lines_touched.end(), n) != lines_touched.end()) continue;
      EXPECT_EQ(a[n], b[n]) << file << " line " << n + 1;
    }
    expect_reads_as(saved, doc, file.string(), file);
  }
}

TEST(SwpPreserving, SaveUsesItForAFileAndTheCanonicalWriterForADocumentMadeInMemory) {
  const test::ScratchFolder folder("sweep-preserving");
  const fs::path file = fs::path(SWEEP_SWP_DIR) / "wineglass.swp";
  io::save_swp_file(folder.path() / "kept.swp", read(file));
  EXPECT_TRUE(test::read_file(folder.path() / "kept.swp") == test::read_file(file));
  const Document made = io::parse_swp(test::read_file(file), "made.swp");  // no source kept
  io::save_swp_file(folder.path() / "made.swp", made);
  EXPECT_TRUE(test::read_file(folder.path() / "made.swp") == io::write_swp(made));
  // The editor's new documents: their points rounded (write_swp_rounded); a file read, as before.
  Document drawn = made;
  drawn.objects[0].as<PointsPart>().points[1].x += 1e-12;
  io::save_swp_file(folder.path() / "drawn.swp", drawn, io::NewDocumentNumbers::Rounded);
  EXPECT_TRUE(test::read_file(folder.path() / "drawn.swp") == io::write_swp_rounded(drawn));
  EXPECT_TRUE(io::write_swp_rounded(drawn) != io::write_swp(drawn));
  io::save_swp_file(folder.path() / "kept2.swp", read(file), io::NewDocumentNumbers::Rounded);
  EXPECT_TRUE(test::read_file(folder.path() / "kept2.swp") == test::read_file(file));
}

}  // namespace
}  // namespace sweep
