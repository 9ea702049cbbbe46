// Export of surfaces with materials: OBJ with its MTL and images beside it (copied byte for byte,
// the checker generated), the report's companion files, glb with nothing beside it, surfaces
// without a material clause as before, and all or nothing when an image has gone missing since
// the file was read or two files would get one name.
#include "io/mesh/mtl_writer.hpp"
#include "io/mesh/obj_writer.hpp"
#include "io/surface_export.hpp"
#include "support/core_test_support.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace sweep::editor {
namespace {

namespace fs = std::filesystem;
using test::read_file;
using test::ScratchFolder;
using test::write_bytes;
using test::write_text;

// wood (line 1): a texture and a bump in images/; tiles (line 2): a 4 x 4 checker; three named
// surfaces: fbf (wood), vase (tiles), plain (none).
constexpr const char* kText =
    "material wood color 0.8 0.5 0.25 shininess 20 texture images/wood.png bump images/grain.png 0.05\n"
    "material tiles checker 4\n"
    "circ profile 30 0.5\n"
    "circ path 60 2\n"
    "gcyl fbf profile path material wood\n"
    "srev vase 12 profile material tiles\n"
    "gcyl plain profile path\n";

/// A SWP file and its images in a scratch folder, parsed and evaluated.
struct Model {
  explicit Model(const ScratchFolder& folder, const std::string& text = kText) {
    fs::create_directories(folder.path() / "images");
    write_bytes(folder.path() / "images" / "wood.png", wood);
    write_bytes(folder.path() / "images" / "grain.png", grain);
    source = (folder.path() / "model.swp").string();
    write_text(source, text);
    doc = io::load_swp_file(source);
    scene = evaluate_document(doc, io::export_evaluation({}, io::ExportFormat::Obj));
  }
  const Mesh& mesh(const char* name) const { return scene.objects.at(static_cast<std::size_t>(doc.find(name))).mesh; }

  std::string wood = io::checker_png(2);  // any PNG will do
  std::string grain = io::checker_png(1);
  std::string source;
  Document doc;
  Scene scene;
};

TEST(MaterialExport, ObjGetsItsMaterialLibraryAndImagesBesideIt) {
  const ScratchFolder folder("sweep-material-export");
  const Model m(folder);
  const fs::path out = folder.path() / "out";
  const std::string prefix = (out / "m").string();
  fs::create_directory(out);
  const io::ExportReport report = io::export_surfaces(m.doc, m.scene, m.source, prefix);

  const std::vector<std::string> expected_files = {"m_fbf.mtl",      "m_fbf.obj",          "m_fbf_grain.png",
                                                   "m_fbf_wood.png", "m_plain.obj",        "m_vase.mtl",
                                                   "m_vase.obj",     "m_vase_checker4.png"};
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(out)) files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, expected_files) << "no temporary left";

  ASSERT_EQ(report.files.size(), 3u);
  const io::ExportedFile& fbf = report.files[0];
  EXPECT_EQ(fbf.path, prefix + "_fbf.obj");
  ASSERT_EQ(fbf.companions.size(), 3u);
  EXPECT_EQ(fbf.companions[0].path, prefix + "_fbf.mtl");
  EXPECT_EQ(fbf.companions[0].what, "material wood");
  EXPECT_EQ(fbf.companions[1].path, prefix + "_fbf_wood.png");
  EXPECT_EQ(fbf.companions[1].what, "texture");
  EXPECT_EQ(fbf.companions[2].path, prefix + "_fbf_grain.png");
  EXPECT_EQ(fbf.companions[2].what, "bump map");
  const io::ExportedFile& vase = report.files[1];
  ASSERT_EQ(vase.companions.size(), 2u);
  EXPECT_EQ(vase.companions[0].what, "material tiles");
  EXPECT_EQ(vase.companions[1].path, prefix + "_vase_checker4.png");
  EXPECT_EQ(vase.companions[1].what, "4 x 4 checker");
  EXPECT_TRUE(report.files[2].companions.empty());

  const std::string comment = "sweep: fbf from " + m.source;
  EXPECT_EQ(read_file(prefix + "_fbf.obj"), io::obj_text(m.mesh("fbf"), comment, {"m_fbf.mtl", "wood"}));
  EXPECT_EQ(read_file(prefix + "_fbf.mtl"),
            "# " + comment +
                "\nnewmtl wood\nKd 0.8 0.5 0.25\nKs 0.45 0.45 0.45\nNs 20\nillum 2\nmap_Kd m_fbf_wood.png\n"
                "map_Bump -bm 0.05 m_fbf_grain.png\n");
  EXPECT_EQ(read_file(prefix + "_fbf_wood.png"), m.wood);
  EXPECT_EQ(read_file(prefix + "_fbf_grain.png"), m.grain);
  EXPECT_EQ(read_file(prefix + "_vase.obj"),
            io::obj_text(m.mesh("vase"), "sweep: vase from " + m.source, {"m_vase.mtl", "tiles"}));
  EXPECT_NE(read_file(prefix + "_vase.mtl").find("newmtl tiles\nKd 0.62 0.68 0.8\n"), std::string::npos);
  EXPECT_NE(read_file(prefix + "_vase.mtl").find("\nmap_Kd m_vase_checker4.png\n"), std::string::npos);
  EXPECT_EQ(read_file(prefix + "_vase_checker4.png"), io::checker_png(4));
  // Without a material clause: no MTL, the OBJ as before (with its texture coordinates, if any).
  EXPECT_EQ(read_file(prefix + "_plain.obj"), io::obj_text(m.mesh("plain"), "sweep: plain from " + m.source));
}

TEST(MaterialExport, ABumpThatIsTheTextureIsOneFile) {
  const ScratchFolder folder("sweep-material-export");
  const Model m(folder,
                "material wood texture images/wood.png bump images/wood.png 1\n"
                "circ profile 8 0.5\ncirc path 12 2\ngcyl tube profile path material wood\n");
  const std::string prefix = (folder.path() / "t").string();
  const io::ExportReport report = io::export_surfaces(m.doc, m.scene, m.source, prefix);
  ASSERT_EQ(report.files.size(), 1u);
  ASSERT_EQ(report.files[0].companions.size(), 2u);
  EXPECT_EQ(report.files[0].companions[1].path, prefix + "_tube_wood.png");
  const std::string mtl = read_file(prefix + "_tube.mtl");
  EXPECT_NE(mtl.find("\nmap_Kd t_tube_wood.png\nmap_Bump -bm 1 t_tube_wood.png\n"), std::string::npos) << mtl;
}

TEST(MaterialExport, ABumpWithTheTexturesFileNameGetsItsOwn) {
  const ScratchFolder folder("sweep-material-export");
  fs::create_directories(folder.path() / "other");
  write_bytes(folder.path() / "other" / "wood.png", io::checker_png(3));
  const Model m(folder,
                "material wood texture images/wood.png bump other/wood.png 1\n"
                "circ profile 8 0.5\ncirc path 12 2\ngcyl tube profile path material wood\n");
  const std::string prefix = (folder.path() / "t").string();
  const io::ExportReport report = io::export_surfaces(m.doc, m.scene, m.source, prefix);
  ASSERT_EQ(report.files.at(0).companions.size(), 3u);
  EXPECT_EQ(report.files[0].companions[2].path, prefix + "_tube_bump_wood.png");
  EXPECT_EQ(read_file(prefix + "_tube_wood.png"), m.wood);
  EXPECT_EQ(read_file(prefix + "_tube_bump_wood.png"), io::checker_png(3));
}

TEST(MaterialExport, GlbEmbedsItsImagesAndWritesNothingBeside) {
  const ScratchFolder folder("sweep-material-export");
  const Model m(folder);
  const fs::path out = folder.path() / "out";
  fs::create_directory(out);
  const std::string prefix = (out / "g").string();
  const io::ExportReport report = io::export_surfaces(m.doc, m.scene, m.source, prefix, io::ExportFormat::Glb);
  std::vector<std::string> files;
  for (const auto& e : fs::directory_iterator(out)) files.push_back(e.path().filename().string());
  std::sort(files.begin(), files.end());
  EXPECT_EQ(files, (std::vector<std::string>{"g_fbf.glb", "g_plain.glb", "g_vase.glb"}));
  ASSERT_EQ(report.files.size(), 3u);
  for (const io::ExportedFile& file : report.files) {
    EXPECT_TRUE(file.companions.empty()) << file.path;
    EXPECT_EQ(read_file(file.path).substr(0, 4), "glTF") << file.path;
  }
  EXPECT_EQ(report.files[0].vertices, m.mesh("fbf").vertex_count());
  EXPECT_EQ(report.files[0].triangles, m.mesh("fbf").triangle_count());
  // The texture is inside: its bytes appear in the file.
  EXPECT_NE(read_file(prefix + "_fbf.glb").find(m.wood), std::string::npos);
  EXPECT_NE(read_file(prefix + "_vase.glb").find(io::checker_png(4)), std::string::npos);
}

TEST(MaterialExport, AnImageGoneSinceTheFileWasReadWritesNothing) {
  for (const io::ExportFormat format : {io::ExportFormat::Obj, io::ExportFormat::Glb}) {
    const ScratchFolder folder("sweep-material-export");
    const Model m(folder);
    const std::string prefix = (folder.path() / "out").string();
    write_text(prefix + "_plain.obj", "old plain\n");
    fs::remove(folder.path() / "images" / "wood.png");
    try {
      io::export_surfaces(m.doc, m.scene, m.source, prefix, format);
      ADD_FAILURE() << "no ExportError";
    } catch (const io::ExportError& e) {
      EXPECT_EQ(std::string(e.what()), m.source + ":1:1: material 'wood': cannot read texture " +
                                           (folder.path() / "images" / "wood.png").string() +
                                           ": No such file or directory; nothing written");
    }
    EXPECT_EQ(folder.entries(), (std::vector<std::string>{"images", "model.swp", "out_plain.obj"}));
    EXPECT_EQ(read_file(prefix + "_plain.obj"), "old plain\n");
  }
}

TEST(MaterialExport, AMissingBumpStopsObjButNotGlb) {
  const ScratchFolder folder("sweep-material-export");
  const Model m(folder);
  fs::remove(folder.path() / "images" / "grain.png");
  const std::string prefix = (folder.path() / "out").string();
  try {
    io::export_surfaces(m.doc, m.scene, m.source, prefix);
    ADD_FAILURE() << "no ExportError";
  } catch (const io::ExportError& e) {
    EXPECT_EQ(std::string(e.what()), m.source + ":1:1: material 'wood': cannot read bump image " +
                                         (folder.path() / "images" / "grain.png").string() +
                                         ": No such file or directory; nothing written");
  }
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"images", "model.swp"}));
  // glb has no bump, so it does not need the file.
  EXPECT_EQ(io::export_surfaces(m.doc, m.scene, m.source, prefix, io::ExportFormat::Glb).files.size(), 3u);
}

TEST(MaterialExport, AFileReadWithoutItsImagesExportsNothingThatNeedsThem) {
  // An SWP file copied without its PNGs reads (with warnings) and is drawn; OBJ and glb, which
  // copy or embed the images, refuse with the message of an image gone since; STL needs none.
  const ScratchFolder folder("sweep-material-export");
  const std::string source = (folder.path() / "model.swp").string();
  write_text(source, kText);
  const Document doc = io::load_swp_file(source);
  ASSERT_EQ(doc.missing_images.size(), 2u);
  EXPECT_EQ(doc.missing_images[0].warning,
            source + ":1:55: warning: texture 'images/wood.png' not found; drawn as a magenta checker");
  EXPECT_EQ(doc.missing_images[1].warning,
            source + ":1:76: warning: bump image 'images/grain.png' not found; drawn as a magenta checker");
  const std::string prefix = (folder.path() / "out").string();
  for (const io::ExportFormat format : {io::ExportFormat::Obj, io::ExportFormat::Glb}) {
    const Scene scene = evaluate_document(doc, io::export_evaluation({}, format));
    try {
      io::export_surfaces(doc, scene, source, prefix, format);
      ADD_FAILURE() << "no ExportError";
    } catch (const io::ExportError& e) {
      EXPECT_EQ(std::string(e.what()), source + ":1:1: material 'wood': cannot read texture " +
                                           (folder.path() / "images" / "wood.png").string() +
                                           ": No such file or directory; nothing written");
    }
    EXPECT_EQ(folder.entries(), (std::vector<std::string>{"model.swp"}));
  }
  const Scene scene = evaluate_document(doc, io::export_evaluation({}, io::ExportFormat::Stl));
  EXPECT_EQ(io::export_surfaces(doc, scene, source, prefix, io::ExportFormat::Stl).files.size(), 3u);
}

TEST(MaterialExport, TwoFilesWithOneNameWriteNothing) {
  // Surface a's texture b_checker4.png and surface a_b's checker 4 would both be out_a_b_checker4.png.
  const ScratchFolder folder("sweep-material-export");
  write_bytes(folder.path() / "b_checker4.png", io::checker_png(1));
  const Model m(folder,
                "material t texture b_checker4.png\nmaterial c checker 4\n"
                "circ profile 8 0.5\ncirc path 12 2\n"
                "gcyl a profile path material t\ngcyl a_b profile path material c\n");
  const std::string prefix = (folder.path() / "out").string();
  try {
    io::export_surfaces(m.doc, m.scene, m.source, prefix);
    ADD_FAILURE() << "no error";
  } catch (const std::runtime_error& e) {
    EXPECT_EQ(std::string(e.what()), "cannot write " + prefix + "_a_b_checker4.png: two exported files have that name");
  }
  EXPECT_EQ(folder.entries(), (std::vector<std::string>{"b_checker4.png", "images", "model.swp"}));
}

}  // namespace
}  // namespace sweep::editor
