// Every write fails in turn (issue 29): SWP save, OBJ with its MTL and image, STL, glb and the
// riders' scene glb, each with its k-th create, write, fsync, close and rename failing for every k
// it makes: the old files stay or the complete new ones are there, no temporary is left, and the
// message names the path and the cause.
#include "io/surface_export.hpp"
#include "io/swp/read.hpp"
#include "io/swp/write.hpp"
#include "model/evaluation/scene.hpp"
#include "support/scratch_folder.hpp"
#include "support/write_failure_support.hpp"

#include <gtest/gtest.h>

#include <sstream>
#include <string>

namespace sweep {
namespace {

namespace fs = std::filesystem;
using io::export_evaluation;
using io::export_surfaces;
using io::ExportFormat;
using test::WriteOutcome;

// Two surfaces, one with a checker (OBJ: an MTL and a PNG beside it), and a rider; large enough
// that each mesh file takes several writes.
constexpr const char* kText =
    "material tiles checker 4\n"
    "circ profile 48 0.5\n"
    "circ path 96 2\n"
    "srev vase 24 profile material tiles\n"
    "gcyl tube profile path\n"
    "rider car path vase seconds 4\n";

/// kText and a polyline of 2 000 points, so the SWP file takes many writes too.
std::string long_text() {
  std::ostringstream text;
  text << kText << "poly3 long 2000\n";
  for (int i = 0; i < 2000; ++i) text << '[' << i << " 0.125 -3.5]\n";
  return text.str();
}

/// The message names a file of `folder` and says why.
void expect_names_a_file_in(const fs::path& folder, const WriteOutcome& failed) {
  EXPECT_NE(failed.message.find("cannot write " + folder.string() + "/"), std::string::npos) << failed.message;
}

TEST(WriteFailure, SwpSaveLeavesTheOldFileOrTheNewOne) {
  const test::ScratchFolder folder;
  const fs::path file = folder.path() / "model.swp";
  test::restore_folder(folder.path(), {{"model.swp", "circ old 8 1\n"}});
  const Document doc = io::parse_swp(long_text());
  const int injected = test::expect_every_failure_leaves_old_or_new(
      folder.path(),
      [&] {
        try {
          io::save_swp_file(file.string(), doc);
          return WriteOutcome{};
        } catch (const std::exception& e) {
          return WriteOutcome{false, e.what()};
        }
      },
      [&](const WriteOutcome& failed) {
        EXPECT_EQ(failed.message.rfind("cannot write " + file.string() + ": ", 0), 0u);
      });
  EXPECT_GE(injected, 6);  // one of each call, and two writes (the text goes in 64 KiB pieces)
}

/// Exports `format` with PREFIX model into `folder`, which holds an older export.
void check_export(io::ExportFormat format, const std::string& first_file) {
  const test::ScratchFolder folder;
  const Document doc = io::parse_swp(kText);
  const Scene scene = evaluate_document(doc, io::export_evaluation({}, format));
  const std::string prefix = (folder.path() / "model").string();
  const auto write = [&] {
    try {
      io::export_surfaces(doc, scene, "model.swp", prefix, format);
      return WriteOutcome{};
    } catch (const std::exception& e) {
      return WriteOutcome{false, e.what()};
    }
  };
  // The files an earlier export left, with other bytes.
  ASSERT_TRUE(write().ok);
  test::FolderContents old = test::folder_contents(folder.path());
  ASSERT_TRUE(old.count(first_file)) << first_file;
  for (auto& [name, bytes] : old) bytes = "an older " + name;
  test::restore_folder(folder.path(), old);
  const int injected = test::expect_every_failure_leaves_old_or_new(
      folder.path(), write, [&](const WriteOutcome& failed) { expect_names_a_file_in(folder.path(), failed); }, true);
  EXPECT_GE(injected, 12);  // two files or more, a call of each kind each, several writes
}

TEST(WriteFailure, ObjWithItsMaterialAndImageIsAllOldOrAllNew) {
  check_export(io::ExportFormat::Obj, "model_vase.mtl");
}

TEST(WriteFailure, StlIsAllOldOrAllNew) {
  check_export(io::ExportFormat::Stl, "model_tube.stl");
}

TEST(WriteFailure, GlbAndTheRidersSceneAreAllOldOrAllNew) {
  check_export(io::ExportFormat::Glb, "model.glb");
}

}  // namespace
}  // namespace sweep
