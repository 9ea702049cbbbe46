// The viewer's exports and PNGs, without a window: names typed into the File panel resolve
// against the SWP file's folder (an untitled document's: the folder last opened or saved in, else
// the working folder), never against the folder Sweep was started from; Export OBJ / STL / glb
// write what `sweep export --format` writes and the status names every file with its full path;
// a failure names the path and the cause; the view PNG's columns leave the panels out.
#include "app/viewer/actions.hpp"
#include "app/viewer/command_bindings.hpp"
#include "app/viewer/viewer_state.hpp"
#include "editor/commands.hpp"
#include "editor/viewport_layout.hpp"
#include "io/surface_export.hpp"
#include "io/swp/read.hpp"
#include "render/camera.hpp"
#include "support/file_support.hpp"
#include "support/scratch_folder.hpp"

#include <gtest/gtest.h>
#include <glm/vec4.hpp>

#include <algorithm>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace sweep::viewer {
namespace {

namespace fs = std::filesystem;
using test::ScratchFolder;
using test::write_text;

// Two named surfaces, the vase with a generated checker (an MTL and a PNG beside its OBJ).
constexpr const char* kText =
    "material tiles checker 4\n"
    "circ profile 12 0.5\n"
    "circ path 24 2\n"
    "srev vase 8 profile material tiles\n"
    "gcyl tube profile path\n";

/// Runs in `folder` as the working folder and goes back to the old one at the end.
class WorkingFolder {
 public:
  explicit WorkingFolder(const fs::path& folder) : old_(fs::current_path()) { fs::current_path(folder); }
  ~WorkingFolder() { fs::current_path(old_); }
  WorkingFolder(const WorkingFolder&) = delete;
  WorkingFolder& operator=(const WorkingFolder&) = delete;

 private:
  fs::path old_;
};

/// A scratch folder with `project/model.swp` and an empty `elsewhere/` to start Sweep from.
struct Project {
  ScratchFolder root{"sweep-export-actions"};
  fs::path folder = root.path() / "project";
  fs::path file = folder / "model.swp";
  fs::path elsewhere = root.path() / "elsewhere";
  Project() {
    fs::create_directories(folder);
    fs::create_directories(elsewhere);
    write_text(file, kText);
  }
  std::vector<std::string> entries(const fs::path& where) const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(where)) names.push_back(e.path().filename().string());
    std::sort(names.begin(), names.end());
    return names;
  }
};

/// The status's lines.
std::vector<std::string> lines(const std::string& text) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) out.push_back(line);
  return out;
}

TEST(OutputFolder, IsTheSwpFilesFolderWhereverSweepWasStarted) {
  EXPECT_EQ(output_folder("/p/q/model.swp", "/last", "/work"), fs::path("/p/q"));
  EXPECT_EQ(output_folder("../p/model.swp", "/last", "/work/here"), fs::path("/work/p"));
  EXPECT_EQ(output_folder("model.swp", "/last", "/work"), fs::path("/work"));
  EXPECT_EQ(output_folder("./a/../model.swp", "", "/work/"), fs::path("/work"));
}

TEST(OutputFolder, AnUntitledDocumentsIsTheFolderLastOpenedOrSavedInElseTheWorkingFolder) {
  EXPECT_EQ(output_folder("", "/last/", "/work"), fs::path("/last"));
  EXPECT_EQ(output_folder("", "", "/work"), fs::path("/work"));
}

TEST(ResolveOutputPath, RelativeNamesGoIntoTheFolderAbsoluteOnesAreUsedAsTheyAre) {
  EXPECT_EQ(resolve_output_path("wineglass", "/p", "x"), fs::path("/p/wineglass"));
  EXPECT_EQ(resolve_output_path("out/w", "/p", "x"), fs::path("/p/out/w"));
  EXPECT_EQ(resolve_output_path("../w.png", "/p/q", "x"), fs::path("/p/w.png"));
  EXPECT_EQ(resolve_output_path("/tmp/a/./w", "/p", "x"), fs::path("/tmp/a/w"));
  EXPECT_EQ(resolve_output_path("", "/p", "model"), fs::path("/p/model")) << "empty: the fallback";
}

TEST(ViewRect, IsTheFreePartBetweenThePanelsAndAboveTheStatusBarInPixels) {
  const editor::ViewportLayout layout = editor::compute_layout({1200, 760}, {1200, 760}, 1.0f, true);
  const PixelRect view = view_rect(layout, {1200, 760});
  EXPECT_EQ(view.x, 368) << "the main panel: 8 margin + 360";
  EXPECT_EQ(view.width, 1200 - 368 - 358) << "the edit panel: 350 + 8 margin";
  EXPECT_EQ(view.y, 0);
  EXPECT_EQ(view.height, 760 - int(editor::kStatusBarHeight)) << "the status bar along the bottom";

  const editor::ViewportLayout hidpi = editor::compute_layout({1200, 760}, {2400, 1520}, 1.0f, true);
  const PixelRect doubled = view_rect(hidpi, {2400, 1520});
  EXPECT_EQ(doubled.x, 2 * 368) << "a framebuffer twice the window's size";
  EXPECT_EQ(doubled.width, 2 * (1200 - 368 - 358));
  EXPECT_EQ(doubled.height, 2 * view.height);

  // A window too narrow for both panels: the part the scene is centred in (the panels are
  // clamped to 60 % and 35 % of the width; the view PNG is read before they are drawn).
  const editor::ViewportLayout narrow = editor::compute_layout({600, 380}, {600, 380}, 1.0f, true);
  EXPECT_EQ(view_rect(narrow, {600, 380}).x, 360);
  EXPECT_EQ(view_rect(narrow, {600, 380}).width, 30);

  const editor::ViewportLayout no_ui = editor::compute_layout({1200, 760}, {1200, 760}, 1.0f, false);
  const PixelRect whole = view_rect(no_ui, {1200, 760});
  EXPECT_EQ(whole.x, 0);
  EXPECT_EQ(whole.y, 0);
  EXPECT_EQ(whole.width, 1200);
  EXPECT_EQ(whole.height, 760);
}

TEST(ViewRect, RoundsInwardsSoNoPixelOutsideTheFreePartIsInThePicture) {
  editor::ViewportLayout layout;
  layout.pixel_ratio = 1.5f;
  layout.free_origin = {100.5, 0.5};  // 150.75 pixels: column 150 is partly outside (row 0 too)
  layout.free_size = {200.5, 300.0};  // right edge 451.5 pixels: column 451 too (bottom 450.75: row 450)
  const PixelRect view = view_rect(layout, {600, 600});
  EXPECT_EQ(view.x, 151);
  EXPECT_EQ(view.x + view.width, 451);
  EXPECT_EQ(view.y, 1);
  EXPECT_EQ(view.y + view.height, 450);
}

TEST(ViewerExport, StlAndGlbGoBesideTheSwpFileAndTheStatusNamesThemInFull) {
  const Project p;
  const WorkingFolder here(p.elsewhere);
  ViewerState s;
  ASSERT_TRUE(open_file(s, "../project/model.swp"));
  EXPECT_EQ(s.fields.export_prefix.get(), "model") << "the field shows the name, relative to the folder";
  editor::CommandTable commands;
  bind_commands(commands, s);

  ASSERT_TRUE(commands.run(editor::CommandId::ExportStl));
  EXPECT_EQ(s.error, "");
  const fs::path folder = fs::canonical(p.folder);
  EXPECT_EQ(lines(s.status)[0].rfind("wrote " + (folder / "model_vase.stl").string() + " (", 0), 0u) << s.status;
  EXPECT_EQ(lines(s.status)[1].rfind("wrote " + (folder / "model_tube.stl").string() + " (", 0), 0u) << s.status;
  ASSERT_TRUE(commands.run(editor::CommandId::ExportGlb));
  EXPECT_EQ(lines(s.status)[0].rfind("wrote " + (folder / "model_vase.glb").string() + " (", 0), 0u) << s.status;
  EXPECT_EQ(lines(s.status).size(), 2u) << s.status;

  EXPECT_EQ(p.entries(p.folder), (std::vector<std::string>{"model.swp", "model_tube.glb", "model_tube.stl",
                                                           "model_vase.glb", "model_vase.stl"}));
  EXPECT_TRUE(p.entries(p.elsewhere).empty()) << "nothing in the folder Sweep was started from";
}

TEST(ViewerExport, ObjNamesItsMaterialLibraryAndImageAsTheCommandLinePrintsThem) {
  const Project p;
  const WorkingFolder here(p.elsewhere);
  ViewerState s;
  ASSERT_TRUE(open_file(s, p.file.string()));
  s.fields.export_prefix.set("out");
  editor::CommandTable commands;
  bind_commands(commands, s);
  ASSERT_TRUE(commands.run(editor::CommandId::ExportObj));
  EXPECT_EQ(s.error, "");

  // What `sweep export FILE FOLDER/out` prints: the same lines.
  const Document doc = io::load_swp_file(p.file);
  const ScratchFolder cli("sweep-export-actions-cli");
  const Scene scene = evaluate_document(doc, io::export_evaluation({}, io::ExportFormat::Obj));
  const io::ExportReport report =
      io::export_surfaces(doc, scene, p.file.string(), (cli.path() / "out").string(), io::ExportFormat::Obj);
  std::vector<std::string> expected;
  for (std::string line : io::written_lines(report)) {
    line.replace(line.find(cli.path().string()), cli.path().string().size(), p.folder.string());
    expected.push_back(line);
  }
  EXPECT_EQ(lines(s.status), expected);
  ASSERT_EQ(expected.size(), 4u) << "the vase's OBJ, MTL and checker, the tube's OBJ";
  for (const std::string& path : io::written_files(report)) {
    EXPECT_TRUE(fs::exists(p.folder / fs::path(path).filename())) << path;
    EXPECT_NE(s.status.find((p.folder / fs::path(path).filename()).string()), std::string::npos) << path;
  }
  EXPECT_TRUE(p.entries(p.elsewhere).empty());
}

TEST(ViewerExport, AnAbsolutePrefixIsUsedAsItIs) {
  const Project p;
  const ScratchFolder other("sweep-export-actions-abs");
  ViewerState s;
  ASSERT_TRUE(open_file(s, p.file.string()));
  export_document(s, (other.path() / "x").string(), io::ExportFormat::Stl);
  EXPECT_EQ(s.error, "");
  EXPECT_EQ(other.entries(), (std::vector<std::string>{"x_tube.stl", "x_vase.stl"}));
}

TEST(ViewerExport, QuantizedGlbAndSvgWriteWhatTheCommandLineWrites) {
  const Project p;
  const WorkingFolder here(p.elsewhere);
  ViewerState s;
  ASSERT_TRUE(open_file(s, "../project/model.swp"));
  editor::CommandTable commands;
  bind_commands(commands, s);
  s.fields.export_prefix.set("q");
  ASSERT_TRUE(commands.run(editor::CommandId::ExportGlbQuantized));
  EXPECT_EQ(s.error, "");
  const fs::path folder = fs::canonical(p.folder);
  EXPECT_EQ(lines(s.status)[0].rfind("wrote " + (folder / "q_vase.glb").string() + " (", 0), 0u) << s.status;
  EXPECT_TRUE(lines(s.status)[0].ends_with(" triangles, quantized)")) << s.status;
  EXPECT_NE(test::read_file(p.folder / "q_vase.glb").find("\"extensionsRequired\":[\"KHR_mesh_quantization\"]"),
            std::string::npos);
  s.fields.export_prefix.set("curves");
  ASSERT_TRUE(commands.run(editor::CommandId::ExportSvg));
  EXPECT_EQ(s.error, "");
  EXPECT_EQ(s.status, "wrote " + (folder / "curves.svg").string() + " (2 curves)");
  EXPECT_NE(test::read_file(p.folder / "curves.svg").find("<circle id=\"profile\""), std::string::npos);
  EXPECT_EQ(p.entries(p.folder), (std::vector<std::string>{"curves.svg", "model.swp", "q_tube.glb", "q_vase.glb"}));
}

TEST(ViewerExport, SvgOfADocumentWithoutPlanarCurvesSaysSoAndWritesNothing) {
  const Project p;
  write_text(p.file, "bez3 lifted 8 4\n[0 0 1] [1 1 1] [2 1 1] [3 0 1]\n");
  ViewerState s;
  ASSERT_TRUE(open_file(s, p.file.string()));
  s.status = "before";
  export_planar_curves(s, "out");
  EXPECT_EQ(s.status, p.file.string() + " has no planar curves; nothing written") << "said as OBJ's is";
  EXPECT_EQ(s.error, "");
  EXPECT_EQ(p.entries(p.folder), std::vector<std::string>{"model.swp"});
}

TEST(ViewerExport, AFailureNamesThePathAndTheCauseAndWritesNothing) {
  const Project p;
  ViewerState s;
  ASSERT_TRUE(open_file(s, p.file.string()));
  s.status = "before";
  export_document(s, "missing/out", io::ExportFormat::Glb);
  EXPECT_EQ(s.error, "export glb failed: cannot write " + (p.folder / "missing" / "out_vase.glb").string() +
                         ": folder " + (p.folder / "missing").string() + ": No such file or directory");
  EXPECT_EQ(s.status, "before");
  EXPECT_EQ(p.entries(p.folder), std::vector<std::string>{"model.swp"});
}

TEST(ViewerExport, AnUntitledDocumentExportsIntoTheFolderLastOpenedIn) {
  const Project p;
  const WorkingFolder here(p.elsewhere);
  ViewerState s;
  ASSERT_TRUE(open_file(s, p.file.string()));
  const Document doc = s.doc();
  ASSERT_TRUE(show_document(s, doc, ""));  // as File > New, then a paste, would leave it
  EXPECT_EQ(output_folder(s), p.folder);
  EXPECT_EQ(s.fields.export_prefix.get(), "untitled");
  export_document(s, s.fields.export_prefix.get(), io::ExportFormat::Stl);
  EXPECT_EQ(s.error, "");
  EXPECT_TRUE(fs::exists(p.folder / "untitled_vase.stl")) << s.status;

  ViewerState fresh;  // nothing opened yet: the working folder
  EXPECT_EQ(output_folder(fresh), fs::current_path());
}

TEST(ViewerScreenshot, TheNameResolvesBesideTheSwpFileAndTheViewIsAskedWithoutPanels) {
  const Project p;
  const WorkingFolder here(p.elsewhere);
  ViewerState s;
  ASSERT_TRUE(open_file(s, "../project/model.swp"));
  EXPECT_EQ(s.fields.screenshot.get(), "model.png");
  editor::CommandTable commands;
  bind_commands(commands, s);
  s.display.grid = false;  // the dialog starts as the view shows
  s.display.control_points = true;
  ASSERT_TRUE(commands.run(editor::CommandId::SavePng));
  EXPECT_TRUE(s.pending_screenshot.path.empty()) << "Save PNG of the view asks first";
  ASSERT_TRUE(s.png_dialog.open);
  EXPECT_EQ(s.png_dialog.size_choice, 0);
  EXPECT_TRUE(s.png_dialog.control_points);
  EXPECT_FALSE(s.png_dialog.grid);
  s.png_dialog.size_choice = 1;
  s.png_dialog.control_points = false;
  request_view_png(s, s.fields.screenshot.get());
  EXPECT_FALSE(s.png_dialog.open);
  EXPECT_EQ(s.pending_screenshot.path, fs::canonical(p.folder) / "model.png");
  EXPECT_FALSE(s.pending_screenshot.with_panels);
  EXPECT_EQ(s.pending_screenshot.size, glm::ivec2(1920, 1080));
  EXPECT_FALSE(s.pending_screenshot.control_points);
  EXPECT_TRUE(s.pending_screenshot.curves);
  EXPECT_FALSE(s.pending_screenshot.grid);
  s.fields.screenshot.set("shots/window");
  ASSERT_TRUE(commands.run(editor::CommandId::SaveWindowPng));
  EXPECT_EQ(s.pending_screenshot.path, fs::canonical(p.folder) / "shots" / "window.png") << ".png added";
  EXPECT_TRUE(s.pending_screenshot.with_panels);
}

/// Where `camera` puts `point` in a picture of `size` pixels drawn at that aspect (top-left origin).
glm::dvec2 pixel_of(const render::Camera& camera, glm::ivec2 size, const glm::dvec3& point) {
  const glm::dvec4 clip =
      camera.projection_matrix(double(size.x) / double(size.y)) * camera.view_matrix() * glm::dvec4(point, 1.0);
  const glm::dvec2 ndc = glm::dvec2(clip) / clip.w;
  return {(ndc.x + 1.0) * 0.5 * size.x, (1.0 - ndc.y) * 0.5 * size.y};
}

TEST(ViewerScreenshot, ThePictureOfTheViewShowsWhatTheViewShowsAtAnySize) {
  render::Camera camera;
  camera.set_yaw_pitch(30.0, 20.0);
  camera.lens_shift = {0.21, -0.05};  // panels on both sides and a status bar
  const glm::ivec2 window(1280, 800);
  const PixelRect view{300, 20, 700, 740};
  const std::vector<glm::dvec3> points = {{0.0, 0.0, 0.0}, {0.7, -0.3, 0.2}, {-0.4, 0.5, -0.6}};
  for (const render::Projection projection : {render::Projection::Perspective, render::Projection::Orthographic}) {
    camera.projection = projection;
    // At the view's own size, every point lands where it is in the view, less the view's corner.
    const render::Camera same = picture_camera(camera, view, window, {view.width, view.height});
    for (const glm::dvec3& point : points) {
      const glm::dvec2 in_window = pixel_of(camera, window, point) - glm::dvec2(view.x, view.y);
      const glm::dvec2 in_picture = pixel_of(same, {view.width, view.height}, point);
      EXPECT_NEAR(in_picture.x, in_window.x, 1e-6);
      EXPECT_NEAR(in_picture.y, in_window.y, 1e-6);
    }
    // At 1920 x 1080 the view's centre is the picture's centre and its height the picture's.
    const glm::ivec2 big(1920, 1080);
    const render::Camera wide = picture_camera(camera, view, window, big);
    const double scale = double(big.y) / double(view.height);
    for (const glm::dvec3& point : points) {
      const glm::dvec2 from_centre =
          pixel_of(camera, window, point) - glm::dvec2(view.x + 0.5 * view.width, view.y + 0.5 * view.height);
      const glm::dvec2 in_picture = pixel_of(wide, big, point) - 0.5 * glm::dvec2(big);
      EXPECT_NEAR(in_picture.x, from_centre.x * scale, 1e-6);
      EXPECT_NEAR(in_picture.y, from_centre.y * scale, 1e-6);
    }
  }
}

}  // namespace
}  // namespace sweep::viewer
