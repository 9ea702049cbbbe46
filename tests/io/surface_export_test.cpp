// OBJ export of a document's named surfaces: the files and the report, all or nothing on a bad
// mesh or a failed write (old files stay intact, no temporary is left), fold warnings.
#include "io/surface_export.hpp"

#include "io/mesh/obj_writer.hpp"
#include "model/diagnostics_text.hpp"
#include "support/core_test_support.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace sweep::editor {
namespace {

namespace fs = std::filesystem;
using test::read_file;
using test::ScratchFolder;
using test::write_text;

// Named surfaces vase (line 8) and tube (line 12), an anonymous one between them.
constexpr const char* kText =
    "bsp2 arc 4 6\n[-1 1]\n[-1.2 0.5]\n[-0.8 0]\n[-1 -0.5]\n[-1 -1]\n[-0.5 -1.2]\n"
    "srev vase 8 arc\n"
    "srev . 6 arc\n"
    "circ ring 16 0.3\n"
    "circ path 32 2\n"
    "gcyl tube ring path\n";
constexpr std::size_t kVase = 1;
constexpr std::size_t kTube = 5;

struct Model {
  Document doc = io::parse_swp(kText, "model.swp");
  Scene scene = evaluate_document(doc, io::export_evaluation({}, io::ExportFormat::Obj));
};

TEST(SurfaceExport, WritesOneFilePerNamedSurfaceAsCoreWritesIt) {
  const ScratchFolder folder("sweep-export");
  const Model m;
  const std::string prefix = (folder.path() / "out").string();
  const io::ExportReport report = io::export_surfaces(m.doc, m.scene, "model.swp", prefix);

  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"out_tube.obj", "out_vase.obj"}))
      << "nothing for the anonymous surface, no temporary left";
  ASSERT_EQ(report.files.size(), 2u);
  const std::size_t objects[] = {kVase, kTube};
  const char* names[] = {"vase", "tube"};
  for (std::size_t k = 0; k < 2; ++k) {
    const io::ExportedFile& file = report.files[k];
    const Mesh& mesh = m.scene.objects[objects[k]].mesh;
    EXPECT_EQ(file.path, prefix + "_" + names[k] + ".obj");
    EXPECT_EQ(file.vertices, mesh.vertex_count());
    EXPECT_EQ(file.triangles, mesh.triangle_count());
    EXPECT_GT(file.triangles, 0u);
    EXPECT_EQ(read_file(file.path), io::obj_text(mesh, std::string("sweep: ") + names[k] + " from model.swp"));
  }
  EXPECT_TRUE(report.warnings.empty()) << "this tube does not fold";
}

TEST(SurfaceExport, TheTorusStarterFileExportsItsOneSurface) {
  const ScratchFolder folder("sweep-export");
  const Document doc = test::load_starter("tor.swp");
  const Scene scene = evaluate_document(doc, io::export_evaluation({}, io::ExportFormat::Obj));
  const io::ExportReport report = io::export_surfaces(doc, scene, "swp/tor.swp", (folder.path() / "tor").string());
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"tor_fbf.obj"});
  ASSERT_EQ(report.files.size(), 1u);
  const Mesh& mesh = scene.objects[std::size_t(doc.find("fbf"))].mesh;
  EXPECT_EQ(report.files[0].vertices, mesh.vertex_count());
  EXPECT_EQ(report.files[0].triangles, mesh.triangle_count());
  EXPECT_EQ(read_file(report.files[0].path), io::obj_text(mesh, "sweep: fbf from swp/tor.swp"));
}

TEST(SurfaceExport, ADocumentWithoutNamedSurfacesWritesNothing) {
  const ScratchFolder folder("sweep-export");
  for (const char* text : {"circ a 8 1\n", "bsp2 p 4 4\n[-1 1]\n[-1 0]\n[-1 -1]\n[-0.5 -1]\nsrev . 6 p\n"}) {
    const Document doc = io::parse_swp(text);
    const io::ExportReport report =
        io::export_surfaces(doc, evaluate_document(doc, io::export_evaluation({}, io::ExportFormat::Obj)), "x.swp",
                            (folder.path() / "x").string());
    EXPECT_TRUE(report.files.empty()) << text;
    EXPECT_TRUE(report.warnings.empty());
  }
  EXPECT_TRUE(folder.entries().empty());
  EXPECT_EQ(io::no_surfaces_message("x.swp"), "x.swp has no named surfaces; nothing written");
}

TEST(SurfaceExport, ANanInAnyMeshWritesNoFileAtAll) {
  const ScratchFolder folder("sweep-export");
  const Model m;
  const std::string prefix = (folder.path() / "out").string();
  Scene bad = m.scene;
  bad.objects[kTube].mesh.positions[3].y = std::numeric_limits<float>::quiet_NaN();
  try {
    io::export_surfaces(m.doc, bad, "model.swp", prefix);
    ADD_FAILURE() << "no ExportError";
  } catch (const io::ExportError& e) {
    EXPECT_STREQ(e.what(), "model.swp:12:1: surface 'tube' has a NaN or infinite coordinate; nothing written");
  }
  EXPECT_TRUE(folder.entries().empty()) << "not even the valid vase before it";

  bad = m.scene;
  bad.objects[kVase].mesh.normals[0].x = std::numeric_limits<float>::infinity();
  try {
    io::export_surfaces(m.doc, bad, "model.swp", prefix);
    ADD_FAILURE() << "no ExportError";
  } catch (const io::ExportError& e) {
    EXPECT_STREQ(e.what(), "model.swp:8:1: surface 'vase' has a NaN or infinite coordinate; nothing written");
  }
  EXPECT_TRUE(folder.entries().empty());
}

TEST(SurfaceExport, AMissingFolderThrowsAndWritesNothing) {
  const ScratchFolder folder("sweep-export");
  const Model m;
  try {
    io::export_surfaces(m.doc, m.scene, "model.swp", (folder.path() / "missing" / "out").string());
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("cannot write ", 0), 0u) << message;
    EXPECT_NE(message.find((folder.path() / "missing" / "out_vase.obj").string()), std::string::npos) << message;
    EXPECT_NE(message.find("No such file or directory"), std::string::npos) << message;
  }
  EXPECT_TRUE(folder.entries().empty());
}

TEST(SurfaceExport, AMissingFolderIsNamedWithTheFileThatNeededIt) {
  const ScratchFolder folder("sweep-export");
  const Model m;
  const fs::path missing = folder.path() / "missing";
  try {
    io::export_surfaces(m.doc, m.scene, "model.swp", (missing / "out").string(), io::ExportFormat::Stl);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + (missing / "out_vase.stl").string() + ": folder " +
                                         missing.string() + ": No such file or directory");
  }
  EXPECT_TRUE(folder.entries().empty());
}

TEST(SurfaceExport, AFailedWriteLeavesTheOldFilesIntact) {
  // The second surface's staged file cannot be put in place (a folder with that name is in the
  // way), so the failure comes while the files are being written, before any rename.
  const ScratchFolder folder("sweep-export");
  const Model m;
  const std::string prefix = (folder.path() / "out").string();
  write_text(folder.path() / "out_vase.obj", "old vase\n");
  fs::create_directory(folder.path() / "out_tube.obj.export-tmp");
  write_text(folder.path() / "out_tube.obj.export-tmp" / "keep", "keep\n");
  EXPECT_THROW(io::export_surfaces(m.doc, m.scene, "model.swp", prefix), std::runtime_error);
  EXPECT_EQ(read_file(folder.path() / "out_vase.obj"), "old vase\n");
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"out_tube.obj.export-tmp", "out_vase.obj"}));
}

TEST(SurfaceExport, AFailedRenameLeavesTheOldFilesIntact) {
  // Every file is written; then the second target turns out to be a folder, so its rename fails
  // after the first file was already renamed into place.
  const ScratchFolder folder("sweep-export");
  const Model m;
  const std::string prefix = (folder.path() / "out").string();
  write_text(folder.path() / "out_vase.obj", "old vase\n");
  fs::create_directory(folder.path() / "out_tube.obj");
  try {
    io::export_surfaces(m.doc, m.scene, "model.swp", prefix);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + prefix + "_tube.obj: Is a directory");
  }
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"out_tube.obj", "out_vase.obj"})) << "no temporary left";
  EXPECT_TRUE(fs::is_directory(folder.path() / "out_tube.obj"));
  // All or nothing: the vase written before the failing tube is not installed either.
  const std::string vase = read_file(folder.path() / "out_vase.obj");
  EXPECT_TRUE(vase == "old vase\n") << "out_vase.obj was replaced; it begins " << vase.substr(0, vase.find('\n'));
}

TEST(SurfaceExport, AFoldingTubeIsExportedWithAWarning) {
  const ScratchFolder folder("sweep-export");
  const Document doc = test::load_starter("flircle.swp");
  const Scene scene = evaluate_document(doc, io::export_evaluation({}, io::ExportFormat::Obj));
  const std::size_t tube = std::size_t(doc.find("flircle"));
  ASSERT_FALSE(scene.objects[tube].diagnostics.folds.empty());
  const io::ExportReport report = io::export_surfaces(doc, scene, "flircle.swp", (folder.path() / "f").string());
  ASSERT_EQ(report.files.size(), 1u);
  EXPECT_EQ(folder.entries(), std::vector<std::string>{"f_flircle.obj"});
  EXPECT_EQ(report.warnings, std::vector<std::string>{fold_warning("flircle", scene.objects[tube].diagnostics)});
}

}  // namespace
}  // namespace sweep::editor

namespace sweep::editor {
namespace {

TEST(SurfaceExport, WrittenFilesAndLinesNameEveryFileInTheOrderWritten) {
  io::ExportReport report;
  report.files.push_back(
      {"/d/p_vase.obj", 10, 16, {{"/d/p_vase.mtl", "material tiles"}, {"/d/p_vase_checker4.png", "4 x 4 checker"}}});
  report.files.push_back({"/d/p_tube.obj", 7, 8, {}});
  EXPECT_EQ(io::written_files(report),
            (std::vector<std::string>{"/d/p_vase.obj", "/d/p_vase.mtl", "/d/p_vase_checker4.png", "/d/p_tube.obj"}));
  EXPECT_EQ(io::written_lines(report),
            (std::vector<std::string>{
                "wrote /d/p_vase.obj (10 vertices, 16 triangles)", "wrote /d/p_vase.mtl (material tiles)",
                "wrote /d/p_vase_checker4.png (4 x 4 checker)", "wrote /d/p_tube.obj (7 vertices, 8 triangles)"}));
  EXPECT_TRUE(io::written_files(io::ExportReport{}).empty());
}

TEST(SurfaceExport, WrittenFilesAreWhatAnExportLeavesInTheFolder) {
  const ScratchFolder folder("sweep-export");
  for (io::ExportFormat format : {io::ExportFormat::Obj, io::ExportFormat::Stl, io::ExportFormat::Glb}) {
    const Document doc = io::parse_swp(kText, "model.swp");
    const Scene scene = evaluate_document(doc, io::export_evaluation({}, format));
    const fs::path sub = folder.path() / io::export_format_label(format);
    fs::create_directory(sub);
    const io::ExportReport report = io::export_surfaces(doc, scene, "model.swp", (sub / "out").string(), format);
    std::vector<std::string> names;
    for (const std::string& path : io::written_files(report)) {
      EXPECT_TRUE(fs::is_regular_file(path)) << path;
      names.push_back(fs::path(path).filename().string());
    }
    std::vector<std::string> listed;
    for (const auto& entry : fs::directory_iterator(sub)) listed.push_back(entry.path().filename().string());
    std::sort(names.begin(), names.end());
    std::sort(listed.begin(), listed.end());
    EXPECT_EQ(names, listed) << io::export_format_label(format);
  }
}

TEST(SurfaceExport, FormatsByTheirCommandLineNames) {
  EXPECT_EQ(io::export_format_named("obj"), io::ExportFormat::Obj);
  EXPECT_EQ(io::export_format_named("stl"), io::ExportFormat::Stl);
  EXPECT_EQ(io::export_format_named("glb"), io::ExportFormat::Glb);
  EXPECT_EQ(io::export_format_named("STL"), std::nullopt);
  EXPECT_EQ(io::export_format_named("gltf"), std::nullopt);
  EXPECT_STREQ(io::export_format_label(io::ExportFormat::Obj), "OBJ");
  EXPECT_STREQ(io::export_format_label(io::ExportFormat::Stl), "STL");
  EXPECT_STREQ(io::export_format_label(io::ExportFormat::Glb), "glb");
}

}  // namespace
}  // namespace sweep::editor
