// Material objects in SWP: `material NAME [color R G B] [shininess S] [texture FILE.png |
// checker N] [bump FILE.png HEIGHT]` and the `material NAME` clause of every surface: every
// clause read into its field, defaults, round trips, the exact messages for bad input (images
// are checked when read, relative to the SWP file's folder), and surface_material's resolved look.
#include "model/material.hpp"
#include "io/mesh/mtl_writer.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/edit/edit.hpp"
#include "model/edit/history.hpp"

#include "support/core_test_support.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <iterator>
#include <span>
#include <string>
#include <vector>

namespace {

namespace fs = std::filesystem;
using sweep::Document;
using sweep::Object;
using sweep::ObjectKind;
using sweep::test::error_of;
using sweep::test::expect_error;
using sweep::test::kTinyPng;
using sweep::test::read_file;
using sweep::test::write_bytes;
using sweep::test::write_text;
using sweep::test::write_tiny_png;

/// A 1x1 GIF header (signature, logical screen descriptor): enough for stb_image's info call.
const unsigned char kTinyGif[] = {0x47, 0x49, 0x46, 0x38, 0x39, 0x61, 0x01, 0x00, 0x01, 0x00, 0x00, 0x00, 0x00};

/// A scratch folder holding wood.png and grain.png, and the SWP file name inside it that image
/// paths are resolved against.
class MaterialFolder {
 public:
  MaterialFolder() : folder_("sweep-material") {
    write_tiny_png(folder_.path() / "wood.png");
    write_tiny_png(folder_.path() / "grain.png");
  }
  const fs::path& path() const { return folder_.path(); }
  std::string file() const { return (folder_.path() / "m.swp").string(); }
  Document parse(const std::string& text) const { return sweep::io::parse_swp(text, file()); }

 private:
  sweep::test::ScratchFolder folder_;
};

/// Compares what Object::operator== may not: the material fields and the surfaces' clause.
void expect_same_looks(const Document& a, const Document& b) {
  ASSERT_EQ(a.objects.size(), b.objects.size());
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    const Object& x = a.objects[i];
    const Object& y = b.objects[i];
    ASSERT_EQ(x.kind(), y.kind()) << i;
    if (const auto* surface = x.find<sweep::MaterialPart>()) {
      EXPECT_EQ(surface->material, y.as<sweep::MaterialPart>().material) << i;
    }
    if (const auto* look = x.find<sweep::MaterialLook>()) {
      const sweep::MaterialLook& other = y.as<sweep::MaterialLook>();
      EXPECT_EQ(look->color, other.color) << i;
      EXPECT_EQ(look->shininess, other.shininess) << i;
      EXPECT_EQ(look->texture, other.texture) << i;
      EXPECT_EQ(look->checker, other.checker) << i;
      EXPECT_EQ(look->bump, other.bump) << i;
      EXPECT_EQ(look->bump_height, other.bump_height) << i;
    }
  }
}

void expect_default_look(const Object& m) {
  EXPECT_EQ(m.as<sweep::MaterialLook>().color,
            glm::dvec3(sweep::kDefaultColor[0], sweep::kDefaultColor[1], sweep::kDefaultColor[2]));
  EXPECT_EQ(m.as<sweep::MaterialLook>().shininess, sweep::kDefaultShininess);
  EXPECT_EQ(m.as<sweep::MaterialLook>().texture, "");
  EXPECT_EQ(m.as<sweep::MaterialLook>().checker, 0);
  EXPECT_EQ(m.as<sweep::MaterialLook>().bump, "");
  EXPECT_EQ(m.as<sweep::MaterialLook>().bump_height, 0.0);
}

const std::string kCurves =
    "circ c 8 1\n"
    "bez3 s 2 4 [0 0 0] [0 0 1] [0 0 2] [0 0 3]\n";  // lines 1 and 2

/// 16 points of one flat bicubic patch.
std::string patch_points() {
  std::string out;
  for (int row = 0; row < 4; ++row) {
    for (int column = 0; column < 4; ++column) {
      out += '[';
      out += std::to_string(column);
      out += ' ';
      out += std::to_string(row);
      out += " 0]";
    }
  }
  return out;
}

// ---------------------------------------------------------------------------------------------
// Reading and writing

TEST(MaterialSwp, EveryClauseIsReadIntoItsField) {
  const MaterialFolder folder;
  const Document doc = folder.parse(
      "material wood color 0.8 0.5 0.25 shininess 20 texture wood.png bump grain.png 0.05\n"
      "material chk checker 8\n");
  ASSERT_EQ(doc.objects.size(), 2u);
  const Object& wood = doc.objects[0];
  EXPECT_EQ(wood.kind(), ObjectKind::Material);
  EXPECT_TRUE(sweep::is_material(wood.kind()));
  EXPECT_FALSE(sweep::is_curve(wood.kind()));
  EXPECT_FALSE(sweep::is_surface(wood.kind()));
  EXPECT_EQ(wood.name, "wood");
  EXPECT_EQ(wood.as<sweep::MaterialLook>().color, glm::dvec3(0.8, 0.5, 0.25));
  EXPECT_EQ(wood.as<sweep::MaterialLook>().shininess, 20.0);
  EXPECT_EQ(wood.as<sweep::MaterialLook>().texture, "wood.png");  // as written, not resolved
  EXPECT_EQ(wood.as<sweep::MaterialLook>().checker, 0);
  EXPECT_EQ(wood.as<sweep::MaterialLook>().bump, "grain.png");
  EXPECT_EQ(wood.as<sweep::MaterialLook>().bump_height, 0.05);
  EXPECT_EQ(wood.location, (sweep::SourceLocation{1, 1}));
  const Object& chk = doc.objects[1];
  EXPECT_EQ(chk.as<sweep::MaterialLook>().checker, 8);
  EXPECT_EQ(chk.as<sweep::MaterialLook>().texture, "");
  EXPECT_EQ(chk.location, (sweep::SourceLocation{2, 1}));
}

TEST(MaterialSwp, ClausesComeInAnyOrderAndKeysIgnoreCase) {
  const MaterialFolder folder;
  const Document doc = folder.parse(
      "MATERIAL wood Bump grain.png 2 CHECKER 3 Shininess 1000 COLOR 0 1 0.5\n"
      "material Wood texture wood.png color 1 1 1 shininess 1\n");
  ASSERT_EQ(doc.objects.size(), 2u);
  const Object& a = doc.objects[0];
  EXPECT_EQ(a.kind(), ObjectKind::Material);
  EXPECT_EQ(a.as<sweep::MaterialLook>().color, glm::dvec3(0.0, 1.0, 0.5));
  EXPECT_EQ(a.as<sweep::MaterialLook>().shininess, 1000.0);
  EXPECT_EQ(a.as<sweep::MaterialLook>().checker, 3);
  EXPECT_EQ(a.as<sweep::MaterialLook>().bump, "grain.png");
  EXPECT_EQ(a.as<sweep::MaterialLook>().bump_height, 2.0);
  // Names keep their case: "Wood" is another name.
  const Object& b = doc.objects[1];
  EXPECT_EQ(b.name, "Wood");
  EXPECT_EQ(b.as<sweep::MaterialLook>().texture, "wood.png");
  EXPECT_EQ(b.as<sweep::MaterialLook>().color, glm::dvec3(1.0));
  EXPECT_EQ(b.as<sweep::MaterialLook>().shininess, 1.0);
  // Written in the reader's order, lower case.
  EXPECT_EQ(sweep::io::write_swp(doc),
            "material wood color 0 1 0.5 shininess 1000 checker 3 bump grain.png 2\n\n"
            "material Wood color 1 1 1 shininess 1 texture wood.png\n\n");
}

TEST(MaterialSwp, AbsentClausesKeepTheDefaultsAndAreNotWritten) {
  const MaterialFolder folder;
  const Document doc = folder.parse("material plain\nmaterial . shininess 48 color 0.62 0.68 0.80\n");
  ASSERT_EQ(doc.objects.size(), 2u);
  for (const Object& m : doc.objects) {
    EXPECT_EQ(m.kind(), ObjectKind::Material);
    expect_default_look(m);
  }
  EXPECT_EQ(doc.objects[1].name, "");
  // A clause equal to its default is not written; a new material has the default look, a new
  // surface the default material.
  EXPECT_EQ(sweep::io::write_swp(doc), "material plain\n\nmaterial .\n\n");
  expect_default_look(Object(ObjectKind::Material));
  EXPECT_EQ(Object(ObjectKind::GeneralizedCylinder).as<sweep::MaterialPart>().material, -1);
  // A zero bump height is kept with its image (the height is a field of the clause).
  const Document flat = folder.parse("material m bump grain.png 0\n");
  EXPECT_EQ(sweep::io::write_swp(flat), "material m bump grain.png 0\n\n");
}

TEST(MaterialSwp, EverySurfaceKindTakesTheClauseAndRoundTrips) {
  const MaterialFolder folder;
  const std::string text = kCurves +
                           "material wood color 0.8 0.5 0.25 shininess 20 texture wood.png bump grain.png 0.05\n"
                           "material chk checker 4\n"
                           "bez2 prof 2 4 [1 0] [1 1] [1 2] [1 3]\n"
                           "gcyl t c s material wood\n"
                           "gcyl plain c s caps\n"
                           "srev r 8 prof material chk caps\n"
                           "bez3 s2 2 4 [1 0 0] [1 0 1] [1 0 2] [1 0 3]\n"
                           "birail b prof s s2 material wood height\n"
                           "bezpatch p 2 1 material chk " +
                           patch_points() +
                           "\n"
                           "bsppatch q 2 4 4 MATERIAL wood " +
                           patch_points() +
                           "\n"
                           "mesh cage 4 1 material chk [0 0 0] [1 0 0] [1 1 0] [0 1 0] [0 1 2 3]\n"
                           "subd sd 1 cage material wood\n"
                           "subd sd2 1 t smooth-boundary material chk\n";
  const Document doc = folder.parse(text);
  const int wood = doc.find("wood");
  const int chk = doc.find("chk");
  ASSERT_EQ(wood, 2);
  ASSERT_EQ(chk, 3);
  const auto material_of = [&doc](const char* name) { return doc.objects[static_cast<std::size_t>(doc.find(name))]; };
  EXPECT_EQ(material_of("t").as<sweep::MaterialPart>().material, wood);
  EXPECT_EQ(material_of("plain").as<sweep::MaterialPart>().material, -1);
  EXPECT_TRUE(material_of("plain").as<sweep::CapsPart>().caps);
  EXPECT_EQ(material_of("r").as<sweep::MaterialPart>().material, chk);
  EXPECT_TRUE(material_of("r").as<sweep::CapsPart>().caps);
  EXPECT_EQ(material_of("b").as<sweep::MaterialPart>().material, wood);
  EXPECT_TRUE(material_of("b").as<sweep::BirailSurface>().height);
  EXPECT_EQ(material_of("p").as<sweep::MaterialPart>().material, chk);
  EXPECT_EQ(material_of("p").as<sweep::PointsPart>().points.size(), 16u);
  EXPECT_EQ(material_of("q").as<sweep::MaterialPart>().material, wood);
  EXPECT_EQ(material_of("cage").as<sweep::MaterialPart>().material, chk);
  EXPECT_EQ(material_of("sd").as<sweep::MaterialPart>().material, wood);
  EXPECT_EQ(material_of("sd2").as<sweep::MaterialPart>().material, chk);
  EXPECT_TRUE(material_of("sd2").as<sweep::SubdivisionSurface>().smooth_boundary);
  // Curves and materials never carry one.
  for (const Object& o : doc.objects) {
    if (!sweep::is_surface(o.kind())) {
      EXPECT_EQ(o.find<sweep::MaterialPart>(), nullptr) << o.name;
    }
  }
  // The clause is one of the references.
  EXPECT_EQ(sweep::references(material_of("t")).back(), wood);

  const std::string written = sweep::io::write_swp(doc);
  const Document again = sweep::io::parse_swp(written, folder.file());
  EXPECT_EQ(again, doc);
  expect_same_looks(again, doc);
  EXPECT_EQ(sweep::io::write_swp(again), written);
  // After the fixed fields and the other clauses, in the table's order; before a patch's points.
  EXPECT_NE(written.find("gcyl t c s material wood\n"), std::string::npos) << written;
  EXPECT_NE(written.find("gcyl plain c s caps\n"), std::string::npos) << written;
  EXPECT_NE(written.find("srev r 8 prof caps material chk\n"), std::string::npos) << written;
  EXPECT_NE(written.find("birail b prof s s2 height material wood\n"), std::string::npos) << written;
  EXPECT_NE(written.find("bezpatch p 2 1 material chk\n[0 0 0]\n"), std::string::npos) << written;
  EXPECT_NE(written.find("bsppatch q 2 4 4 material wood\n[0 0 0]\n"), std::string::npos) << written;
  EXPECT_NE(written.find("mesh cage 4 1 material chk\n[0 0 0]\n"), std::string::npos) << written;
  EXPECT_NE(written.find("subd sd 1 cage material wood\n"), std::string::npos) << written;
  EXPECT_NE(written.find("subd sd2 1 t smooth-boundary material chk\n"), std::string::npos) << written;
  EXPECT_NE(written.find("material wood color 0.8 0.5 0.25 shininess 20 texture wood.png bump grain.png 0.05\n"),
            std::string::npos)
      << written;
}

TEST(MaterialSwp, DocumentEqualitySeesTheLook) {
  // Round trips, undo and "unsaved changes" compare documents with ==: a changed colour, image
  // or material clause must make them differ.
  const MaterialFolder folder;
  const Document doc = folder.parse(kCurves + "material wood color 0.8 0.5 0.25\ngcyl t c s material wood\n");
  const auto differs = [&doc](const char* what, auto change) {
    Document other = doc;
    change(other);
    EXPECT_NE(other, doc) << what;
  };
  differs("color", [](Document& d) { d.objects[2].as<sweep::MaterialLook>().color.x = 0.9; });
  differs("shininess", [](Document& d) { d.objects[2].as<sweep::MaterialLook>().shininess = 10.0; });
  differs("texture", [](Document& d) { d.objects[2].as<sweep::MaterialLook>().texture = "wood.png"; });
  differs("checker", [](Document& d) { d.objects[2].as<sweep::MaterialLook>().checker = 2; });
  differs("bump", [](Document& d) { d.objects[2].as<sweep::MaterialLook>().bump = "grain.png"; });
  differs("bump height", [](Document& d) { d.objects[2].as<sweep::MaterialLook>().bump_height = 1.0; });
  differs("material clause", [](Document& d) { d.objects[3].as<sweep::MaterialPart>().material = -1; });
}

TEST(MaterialSwp, ALookEditIsAnUndoStep) {
  // The undo history records the objects that are not == (history.cpp, changed_objects): an edit
  // of a material's colour must be a step that undo reverts and that makes the document dirty.
  const MaterialFolder folder;
  Document doc = folder.parse(kCurves + "material wood color 0.8 0.5 0.25\ngcyl t c s material wood\n");
  sweep::History history;
  history.begin(doc, "colour");
  doc.objects[2].as<sweep::MaterialLook>().color = glm::dvec3(0.1, 0.2, 0.3);
  history.end(doc);
  EXPECT_TRUE(history.can_undo());
  EXPECT_TRUE(history.dirty());
  (void)history.undo(doc);
  EXPECT_EQ(doc.objects[2].as<sweep::MaterialLook>().color, glm::dvec3(0.8, 0.5, 0.25));
}

TEST(MaterialSwp, FilesWithoutMaterialsAreWrittenBackUnchanged) {
  const auto files = sweep::test::starter_files();
  ASSERT_FALSE(files.empty());
  const fs::path expected_dir = fs::path(SWEEP_TEST_DATA_DIR) / "swp-written";
  for (const auto& file : files) {
    const Document doc = sweep::io::load_swp_file(file);
    for (const Object& o : doc.objects) {
      EXPECT_FALSE(sweep::is_material(o.kind())) << file;
      const auto* surface = o.find<sweep::MaterialPart>();
      EXPECT_TRUE(surface == nullptr || surface->material == -1) << file;
    }
    const std::string text = sweep::io::write_swp(doc);
    EXPECT_EQ(text.find("material"), std::string::npos) << file;
    EXPECT_EQ(sweep::io::write_swp(sweep::io::parse_swp(text, "again.swp")), text) << file;
    if (const fs::path expected = expected_dir / file.filename(); fs::exists(expected)) {
      EXPECT_EQ(text, read_file(expected)) << file;
    }
    // An unused material at the end changes nothing before it.
    Document more = doc;
    Object m;
    m.set_kind(ObjectKind::Material);
    m.name = "zz_material";
    m.as<sweep::MaterialLook>().checker = 2;
    more.objects.push_back(m);
    EXPECT_EQ(sweep::io::write_swp(more), text + "material zz_material checker 2\n\n") << file;
  }
}

// ---------------------------------------------------------------------------------------------
// Messages

TEST(MaterialErrors, UnknownClauseKey) {
  const MaterialFolder folder;
  expect_error("material m gloss 3", 1, 12,
               "expected a material clause (color, shininess, texture, checker, bump) or a keyword, found "
               "'gloss'",
               folder.file());
  expect_error("material m color 1 1 1\n  material", 2, 11,
               "expected a name (a letter or '_', then letters, digits, '_', '-' or '.') or '.' for none, found "
               "end of file",
               folder.file());
  // A point where a clause or a keyword belongs ends the material: the file then has a stray '['.
  EXPECT_NE(error_of("material m [0 0 0]", folder.file()).find(":1:12: expected a keyword (bez2, "), std::string::npos);
}

TEST(MaterialErrors, EachClauseAtMostOnce) {
  const MaterialFolder folder;
  expect_error("material m color 1 0 0 color 0 0 0", 1, 24,
               "expected each clause at most once, found 'color' (already given at line 1, column 12)", folder.file());
  expect_error("material m\n shininess 2\n checker 2 SHININESS 3", 3, 12,
               "expected each clause at most once, found 'SHININESS' (already given at line 2, column 2)",
               folder.file());
  expect_error("material m texture wood.png texture grain.png", 1, 29,
               "expected each clause at most once, found 'texture' (already given at line 1, column 12)",
               folder.file());
  expect_error("material m bump wood.png 1 bump grain.png 2", 1, 28,
               "expected each clause at most once, found 'bump' (already given at line 1, column 12)", folder.file());
  expect_error("material m checker 2 checker 3", 1, 22,
               "expected each clause at most once, found 'checker' (already given at line 1, column 12)",
               folder.file());
}

TEST(MaterialErrors, TextureAndCheckerTogether) {
  const MaterialFolder folder;
  expect_error("material m checker 2 texture wood.png", 1, 22,
               "expected a texture or a checker, not both, found 'texture'", folder.file());
  expect_error("material m texture wood.png color 1 1 1 checker 2", 1, 41,
               "expected a texture or a checker, not both, found 'checker'", folder.file());
  // A bump goes with either.
  EXPECT_EQ(
      error_of("material m texture wood.png bump grain.png 1\nmaterial n checker 2 bump grain.png 1", folder.file()),
      "no error");
}

TEST(MaterialErrors, ColourComponentsFrom0To1) {
  const MaterialFolder folder;
  expect_error("material m color 1.5 0 0", 1, 18, "expected a colour component from 0 to 1 (red), found '1.5'",
               folder.file());
  expect_error("material m color 0 -0.1 0", 1, 20, "expected a colour component from 0 to 1 (green), found '-0.1'",
               folder.file());
  expect_error("material m color 0 0 2", 1, 22, "expected a colour component from 0 to 1 (blue), found '2'",
               folder.file());
  expect_error("material m color 0 0 nan", 1, 22, "expected a finite number (blue), found 'nan'", folder.file());
  expect_error("material m color 0 0", 1, 21, "expected a number (blue), found end of file", folder.file());
  expect_error("material m color 0 x 0", 1, 20, "expected a number (green), found 'x'", folder.file());
  const Document edges = folder.parse("material m color 0 1 +1\n");
  EXPECT_EQ(edges.objects[0].as<sweep::MaterialLook>().color, glm::dvec3(0.0, 1.0, 1.0));
}

TEST(MaterialErrors, ShininessFrom1To1000) {
  const MaterialFolder folder;
  expect_error("material m shininess 0.5", 1, 22, "expected a shininess from 1 to 1000, found '0.5'", folder.file());
  expect_error("material m shininess 1000.5", 1, 22, "expected a shininess from 1 to 1000, found '1000.5'",
               folder.file());
  expect_error("material m shininess -1", 1, 22, "expected a shininess from 1 to 1000, found '-1'", folder.file());
  expect_error("material m shininess inf", 1, 22, "expected a finite number (shininess), found 'inf'", folder.file());
  EXPECT_EQ(folder.parse("material m shininess 1").objects[0].as<sweep::MaterialLook>().shininess, 1.0);
  EXPECT_EQ(folder.parse("material m shininess 1000").objects[0].as<sweep::MaterialLook>().shininess, 1000.0);
}

TEST(MaterialErrors, CheckerFrom1To256) {
  const MaterialFolder folder;
  const std::string expected = "expected the checker's cells per side, a whole number from 1 to 256, found ";
  expect_error("material m checker 0", 1, 20, expected + "'0'", folder.file());
  expect_error("material m checker 257", 1, 20, expected + "'257'", folder.file());
  expect_error("material m checker 2.5", 1, 20, expected + "'2.5'", folder.file());
  expect_error("material m checker", 1, 19, expected + "end of file", folder.file());
  EXPECT_EQ(folder.parse("material m checker 1").objects[0].as<sweep::MaterialLook>().checker, 1);
  EXPECT_EQ(folder.parse("material m checker 256").objects[0].as<sweep::MaterialLook>().checker, 256);
}

TEST(MaterialErrors, BumpHeightFrom0To1e12) {
  const MaterialFolder folder;
  expect_error("material m bump grain.png -1", 1, 27, "expected a bump height from 0 to 1e12 (model units), found '-1'",
               folder.file());
  expect_error("material m bump grain.png -0.001", 1, 27,
               "expected a bump height from 0 to 1e12 (model units), found '-0.001'", folder.file());
  expect_error("material m bump grain.png 2e12", 1, 27,
               "expected a bump height from 0 to 1e12 (model units), found '2e12'", folder.file());
  expect_error("material m bump grain.png", 1, 26, "expected a number (bump height), found end of file", folder.file());
  EXPECT_EQ(folder.parse("material m bump grain.png 1e12").objects[0].as<sweep::MaterialLook>().bump_height, 1e12);
}

TEST(MaterialErrors, ImagesAreCheckedWhenRead) {
  // Only an image that is there and unreadable is an error; a missing one is a warning (below).
  const MaterialFolder folder;
  const std::string base = folder.path().string();
  fs::create_directory(folder.path() / "dir.png");
  expect_error("material m texture dir.png", 1, 20,
               "expected a PNG image file (texture), found 'dir.png' (" + base + "/dir.png is not a regular file)",
               folder.file());
  write_text(folder.path() / "notes.png", "not an image\n");
  expect_error("material m bump notes.png 1", 1, 17,
               "expected a PNG image file (bump), found 'notes.png' (" + base + "/notes.png is not a PNG image)",
               folder.file());
  expect_error("material m texture", 1, 19, "expected a PNG image file (texture), found end of file", folder.file());
  expect_error("material m texture [", 1, 20, "expected a PNG image file (texture), found '['", folder.file());
  // Relative to the SWP file's folder, not the working folder; subfolders and absolute paths work.
  fs::create_directory(folder.path() / "img");
  write_tiny_png(folder.path() / "img" / "tile.png");
  EXPECT_EQ(folder.parse("material m texture img/tile.png").objects[0].as<sweep::MaterialLook>().texture,
            "img/tile.png");
  const std::string absolute = (folder.path() / "img" / "tile.png").string();
  EXPECT_EQ(folder.parse("material m bump " + absolute + " 1").objects[0].as<sweep::MaterialLook>().bump, absolute);
  EXPECT_TRUE(folder.parse("material m texture img/tile.png").missing_images.empty());
}

// ---------------------------------------------------------------------------------------------
// Missing images: the file reads, with a warning at each; drawn as a placeholder

/// The reader's warning for a missing image named at LINE:COLUMN of `file`.
std::string missing_warning(const std::string& file, int line, int column, const std::string& what) {
  return file + ":" + std::to_string(line) + ":" + std::to_string(column) + ": warning: " + what +
         " not found; drawn as a magenta checker";
}

TEST(MaterialMissingImages, AFileWhoseImagesAreMissingReadsWithAWarningAtEach) {
  const MaterialFolder folder;
  const std::string text = kCurves +
                           "material lost color 0.8 0.5 0.25 texture gone.png bump img/grain.png 0.05\n"
                           "material half texture wood.png\n  bump nowhere.png 2\n"
                           "gcyl t c s material lost\n";
  const Document doc = folder.parse(text);
  ASSERT_EQ(doc.objects.size(), 5u);
  const sweep::MaterialLook& lost = doc.objects[2].as<sweep::MaterialLook>();
  EXPECT_EQ(lost.color, glm::dvec3(0.8, 0.5, 0.25));
  EXPECT_EQ(lost.texture, "gone.png");
  EXPECT_EQ(lost.bump, "img/grain.png");
  EXPECT_EQ(lost.bump_height, 0.05);
  EXPECT_EQ(doc.objects[3].as<sweep::MaterialLook>().bump, "nowhere.png");
  EXPECT_EQ(doc.objects[4].as<sweep::MaterialPart>().material, 2);
  const std::string file = folder.file();
  EXPECT_EQ(doc.missing_images, (std::vector<sweep::MissingImage>{
                                    {"gone.png", missing_warning(file, 3, 42, "texture 'gone.png'")},
                                    {"img/grain.png", missing_warning(file, 3, 56, "bump image 'img/grain.png'")},
                                    {"nowhere.png", missing_warning(file, 5, 8, "bump image 'nowhere.png'")}}));
  // Not part of what the document says: equal to the same objects made in memory.
  Document made = doc;
  made.missing_images.clear();
  EXPECT_EQ(made, doc);
  // An absolute path is named as written; an image there is no warning.
  const std::string absolute = (folder.path() / "sub" / "gone.png").string();
  EXPECT_EQ(folder.parse("material m texture " + absolute).missing_images,
            (std::vector<sweep::MissingImage>{{absolute, missing_warning(file, 1, 20, "texture '" + absolute + "'")}}));
  EXPECT_TRUE(folder.parse("material m texture wood.png bump grain.png 1").missing_images.empty());
  // Without a file name the working folder is looked in, and named in the warning as "<input>".
  EXPECT_EQ(sweep::io::parse_swp("material m texture sweep-no-such-image.png").missing_images.at(0).warning,
            missing_warning("<input>", 1, 20, "texture 'sweep-no-such-image.png'"));
}

TEST(MaterialMissingImages, SavingKeepsTheMaterialAsWritten) {
  const MaterialFolder folder;
  const std::string text = kCurves +
                           "material  lost   texture gone.png\tbump  lost.png 0.050   \n"
                           "gcyl t c s material lost\n";
  const fs::path file = folder.path() / "lost.swp";
  write_text(file, text);
  const Document doc = sweep::io::load_swp_file(file);
  ASSERT_EQ(doc.missing_images.size(), 2u);
  // Format-preserving: byte for byte, and again after an edit elsewhere in the file.
  EXPECT_EQ(sweep::io::write_swp_preserving(doc), text);
  const fs::path saved = folder.path() / "saved.swp";
  sweep::io::save_swp_file(saved, doc);
  EXPECT_EQ(read_file(saved), text);
  Document edited = doc;
  edited.objects[0].as<sweep::RadiusPart>().radius = 2.0;
  EXPECT_EQ(sweep::io::write_swp_preserving(edited), "circ c 8 2\n" + text.substr(text.find('\n') + 1));
  // The canonical writer writes the clauses it read, and reads back the same.
  const std::string canonical = sweep::io::write_swp(doc);
  EXPECT_NE(canonical.find("material lost texture gone.png bump lost.png 0.05\n"), std::string::npos) << canonical;
  const Document again = sweep::io::parse_swp(canonical, file.string());
  EXPECT_EQ(again, doc);
  expect_same_looks(again, doc);
  EXPECT_EQ(again.missing_images.size(), 2u);
}

TEST(MaterialMissingImages, TheLookIsAPlaceholderUntilTheMaterialNamesAnImageThatIsThere) {
  const MaterialFolder folder;
  Document doc = folder.parse(kCurves +
                              "material lost color 0.2 0.6 0.3 texture gone.png\n"
                              "material bumpy texture wood.png bump lost.png 1\n"
                              "material fine texture wood.png bump grain.png 1\n"
                              "gcyl t c s material lost\ngcyl u c s material bumpy\ngcyl v c s material fine\n");
  const fs::path base = folder.path();
  const sweep::SurfaceMaterial lost = sweep::surface_material(doc, 5, base);
  EXPECT_TRUE(lost.placeholder);
  EXPECT_EQ(lost.texture, base / "gone.png") << "resolved as always: the exports try it, and refuse";
  EXPECT_EQ(lost.color, glm::vec3(0.2f, 0.6f, 0.3f));
  EXPECT_TRUE(sweep::surface_material(doc, 6, base).placeholder) << "a missing bump alone";
  EXPECT_FALSE(sweep::surface_material(doc, 7, base).placeholder);
  // Its colour can still be changed: the image it has already is not checked again...
  Object look = doc.objects[2];
  look.as<sweep::MaterialLook>().color = glm::dvec3(1.0, 0.0, 0.0);
  sweep::set_material_look(doc, 2, look, base);
  EXPECT_EQ(doc.objects[2].as<sweep::MaterialLook>().color, glm::dvec3(1.0, 0.0, 0.0));
  EXPECT_TRUE(sweep::surface_material(doc, 5, base).placeholder);
  // ...but a missing image named anew is refused, as before...
  look.as<sweep::MaterialLook>().texture = "other.png";
  try {
    sweep::set_material_look(doc, 2, look, base);
    ADD_FAILURE() << "no EditError";
  } catch (const sweep::EditError& e) {
    EXPECT_EQ(std::string(e.what()),
              "material 'lost': cannot open " + (base / "other.png").string() + ": no such file");
  }
  // ...and one that is there replaces the placeholder.
  look.as<sweep::MaterialLook>().texture = "wood.png";
  sweep::set_material_look(doc, 2, look, base);
  EXPECT_FALSE(sweep::surface_material(doc, 5, base).placeholder);
}

TEST(MaterialErrors, ImagesMustBePngs) {
  // The reader says "expected a PNG image file" and the exporters copy the bytes as .png (they
  // refuse anything else, mesh/mtl_writer.cpp): a GIF that stb_image also reads should be refused here.
  const MaterialFolder folder;
  write_bytes(folder.path() / "tiny.gif", kTinyGif);
  ASSERT_EQ(sweep::image_problem(folder.path() / "wood.png"), "");
  const std::string message = error_of("material m texture tiny.gif", folder.file());
  EXPECT_NE(message.find(":1:20: expected a PNG image file (texture), found 'tiny.gif'"), std::string::npos)
      << "BUG: image_problem (src/core/material.cpp) accepts any image stb_image reads, not only PNGs; got: "
      << message;
  // What accepting it leads to: a document that loads but does not export.
  if (message == "no error") {
    const Document doc = folder.parse(kCurves + "material m texture tiny.gif\ngcyl t c s material m\n");
    EXPECT_NO_THROW((void)sweep::io::read_material_images(sweep::surface_material(doc, 3, folder.path())));
  }
}

TEST(MaterialErrors, ClauseMustNameAMaterialDefinedAbove) {
  const MaterialFolder folder;
  const std::string expected = "expected the name of a material defined above, found ";
  expect_error(kCurves + "gcyl t c s material c", 3, 21, expected + "'c' (it is a curve (circ))", folder.file());
  expect_error(kCurves + "gcyl t c s material s", 3, 21, expected + "'s' (it is a curve (bez3))", folder.file());
  expect_error(kCurves + "gcyl t c s\nsrev r 4 c material t", 4, 21, expected + "'t' (it is a surface (gcyl))",
               folder.file());
  expect_error(kCurves + "material m\ngcyl t c s material m material m", 4, 23,
               "expected each clause at most once, found 'material' (already given at line 4, column 12)",
               folder.file());
  // Patches and meshes: the clause comes before the points, so any name after `material` is read
  // as the clause.
  expect_error("bezpatch p 1 1 material wood " + patch_points() + "\nmaterial wood", 1, 25,
               expected + "'wood' (it is defined further down; references point backwards only)", folder.file());
  expect_error("bsppatch q 1 4 4 material nope " + patch_points(), 1, 27, expected + "'nope' (no object has that name)",
               folder.file());
  expect_error("mesh cage 3 1 material . [0 0 0] [1 0 0] [0 1 0] [0 1 2]", 1, 24,
               expected + "'.' ('.' means no name; only named objects can be referenced)", folder.file());
}

TEST(MaterialErrors, MaterialAfterASurfaceWithANewNameStartsAMaterial) {
  const MaterialFolder folder;
  // `material fresh` after a gcyl: "fresh" is not taken, so it is a new object, not the clause.
  const Document doc = folder.parse(kCurves + "gcyl t c s material fresh color 1 0 0\nsubd sd 0 t material fresh\n");
  ASSERT_EQ(doc.objects.size(), 5u);
  EXPECT_EQ(doc.objects[2].kind(), ObjectKind::GeneralizedCylinder);
  EXPECT_EQ(doc.objects[2].as<sweep::MaterialPart>().material, -1);
  const Object& fresh = doc.objects[3];
  EXPECT_EQ(fresh.kind(), ObjectKind::Material);
  EXPECT_EQ(fresh.name, "fresh");
  EXPECT_EQ(fresh.as<sweep::MaterialLook>().color, glm::dvec3(1.0, 0.0, 0.0));
  EXPECT_EQ(fresh.location, (sweep::SourceLocation{3, 12}));
  EXPECT_EQ(doc.objects[4].as<sweep::MaterialPart>().material, 3);
  // Written on its own line, it reads back the same.
  const std::string written = sweep::io::write_swp(doc);
  EXPECT_NE(written.find("gcyl t c s\n\nmaterial fresh color 1 0 0\n"), std::string::npos) << written;
  expect_same_looks(sweep::io::parse_swp(written, folder.file()), doc);
  // A material defined further down: its name is new where the gcyl is, so the gcyl's `material
  // wood` starts a material of that name, and the real one is then a second "wood".
  expect_error(kCurves + "gcyl t c s material wood\nmaterial wood color 1 0 0", 4, 10,
               "expected a new name, found 'wood' (already used by the object at line 3)", folder.file());
}

// ---------------------------------------------------------------------------------------------
// The resolved look

TEST(MaterialLook, SurfaceMaterialResolvesImagesAgainstTheFolder) {
  const MaterialFolder folder;
  const Document doc =
      folder.parse(kCurves +
                   "material wood color 0.8 0.5 0.25 shininess 20 texture wood.png bump grain.png 0.05\n"
                   "material chk checker 4 color 1 1 1\n"
                   "gcyl t c s material wood\n"
                   "gcyl u c s material chk\n"
                   "gcyl plain c s\n");
  const fs::path base = sweep::image_base(folder.file());
  EXPECT_EQ(base, folder.path());

  const sweep::SurfaceMaterial wood = sweep::surface_material(doc, 4, base);
  EXPECT_EQ(wood.name, "wood");
  EXPECT_EQ(wood.color, glm::vec3(0.8f, 0.5f, 0.25f));
  EXPECT_EQ(wood.shininess, 20.0f);
  EXPECT_EQ(wood.texture, folder.path() / "wood.png");
  EXPECT_EQ(wood.checker, 0);
  EXPECT_EQ(wood.bump, folder.path() / "grain.png");
  EXPECT_EQ(wood.bump_height, 0.05f);
  EXPECT_TRUE(wood.textured());
  EXPECT_EQ(sweep::image_problem(wood.texture), "");
  EXPECT_EQ(sweep::image_problem(wood.bump), "");

  const sweep::SurfaceMaterial chk = sweep::surface_material(doc, 5, base);
  EXPECT_EQ(chk.name, "chk");
  EXPECT_EQ(chk.checker, 4);
  EXPECT_TRUE(chk.texture.empty());
  EXPECT_TRUE(chk.bump.empty());
  EXPECT_EQ(chk.color, glm::vec3(1.0f));
  EXPECT_EQ(chk.shininess, static_cast<float>(sweep::kDefaultShininess));
  EXPECT_TRUE(chk.textured());

  const sweep::SurfaceMaterial plain = sweep::surface_material(doc, 6, base);
  const sweep::SurfaceMaterial defaults;
  EXPECT_EQ(plain.name, "");
  EXPECT_EQ(plain.color, defaults.color);
  EXPECT_EQ(plain.color, glm::vec3(0.62f, 0.68f, 0.80f));
  EXPECT_EQ(plain.shininess, 48.0f);
  EXPECT_TRUE(plain.texture.empty());
  EXPECT_EQ(plain.checker, 0);
  EXPECT_TRUE(plain.bump.empty());
  EXPECT_EQ(plain.bump_height, 0.0f);
  EXPECT_FALSE(plain.textured());
}

TEST(MaterialLook, ImageBaseAndAbsolutePaths) {
  EXPECT_EQ(sweep::image_base("m.swp"), fs::path());
  EXPECT_EQ(sweep::image_base("/a/b/m.swp"), fs::path("/a/b"));
  EXPECT_EQ(sweep::image_base("a/m.swp"), fs::path("a"));
  const MaterialFolder folder;
  const std::string absolute = (folder.path() / "wood.png").string();
  const Document doc = folder.parse(kCurves + "material m texture " + absolute + "\ngcyl t c s material m\n");
  EXPECT_EQ(sweep::surface_material(doc, 3, "/elsewhere").texture, fs::path(absolute));
  EXPECT_EQ(sweep::surface_material(doc, 3, "/elsewhere").name, "m");
  // With another base a relative path resolves there (the file is not read again here).
  const Document relative = folder.parse(kCurves + "material m bump wood.png 3\ngcyl t c s material m\n");
  EXPECT_EQ(sweep::surface_material(relative, 3, "/elsewhere").bump, fs::path("/elsewhere/wood.png"));
  EXPECT_EQ(sweep::surface_material(relative, 3, "").bump, fs::path("wood.png"));
  EXPECT_EQ(sweep::surface_material(relative, 3, "").bump_height, 3.0f);
  EXPECT_FALSE(sweep::surface_material(relative, 3, "").textured());  // a bump alone is no texture
}

TEST(MaterialLook, ImageProblemReadsOnlyRegularFiles) {
  const MaterialFolder folder;
  EXPECT_EQ(sweep::image_problem(folder.path() / "wood.png"), "");
  const fs::path gone = folder.path() / "gone.png";
  EXPECT_EQ(sweep::image_problem(gone), "cannot open " + gone.string() + ": no such file");
  EXPECT_EQ(sweep::image_problem(folder.path()), folder.path().string() + " is not a regular file");
  // A truncated PNG (signature only) is no image.
  write_bytes(folder.path() / "cut.png", std::span(kTinyPng).first(8));
  EXPECT_NE(sweep::image_problem(folder.path() / "cut.png"), "");
  // Larger than 16384 on a side: the IHDR says 16385 x 1 (the CRC is not checked by the info call).
  unsigned char wide[sizeof kTinyPng];
  std::copy(std::begin(kTinyPng), std::end(kTinyPng), std::begin(wide));
  wide[16 + 2] = 0x40;  // width 0x00004001
  wide[16 + 3] = 0x01;
  write_bytes(folder.path() / "wide.png", wide);
  const std::string problem = sweep::image_problem(folder.path() / "wide.png");
  EXPECT_EQ(problem, (folder.path() / "wide.png").string() + " is 16385x1 pixels; at most 16384 on a side");
}

}  // namespace
