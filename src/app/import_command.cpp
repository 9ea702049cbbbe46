// `sweep import CAGE.obj OUT.swp [--name NAME]`: a Wavefront OBJ polygon mesh as one `mesh` object.
// `sweep import DRAWING.svg OUT.swp [--scale S] [--name NAME] [--revolve]`: an SVG drawing's paths
// and shapes as bez2 curves (io/svg/import.hpp states the units and names), with --revolve each the
// profile of a surface of revolution (model/evaluation/revolve_curves.hpp). The input's extension decides.
#include "app/commands.hpp"

#include "io/mesh/obj_import.hpp"
#include "io/svg/import.hpp"
#include "io/swp/write.hpp"
#include "model/document.hpp"
#include "model/file_limits.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

namespace sweep::app {
namespace {

struct ImportChoice {
  std::string obj;
  std::string swp;
  std::string name;
  CLI::Option* name_option = nullptr;
  double scale = 1.0;
  CLI::Option* scale_option = nullptr;
  bool revolve = false;
};

/// True for an input whose extension is .svg in any case.
bool is_svg(const std::string& path) {
  std::string extension = std::filesystem::path(path).extension().string();
  std::ranges::transform(extension, extension.begin(), [](unsigned char c) { return std::tolower(c); });
  return extension == ".svg";
}

/// The --name given (checked, with a message if invalid) or the input file's name.
bool chosen_name(const ImportChoice& choice, std::string& name) {
  const bool named = choice.name_option->count() > 0;
  name = named ? choice.name : io::object_name_from_path(choice.obj);
  if (is_valid_object_name(name)) return true;
  std::fprintf(stderr,
               "sweep: --name: expected a name (a letter or '_', then letters, digits, '_', '-' or '.', at most "
               "%zu bytes), found '%s'\n",
               limits::kMaxNameLength, printable_excerpt(name, 40).c_str());
  return false;
}

/// Reads the OBJ and writes the SWP (atomically: on any error nothing is written). A problem with
/// the OBJ is printed as its one line ("FILE:LINE: ..." or "FILE: ..."); a failed write reaches main.
int import_obj(const ImportChoice& choice) {
  if (choice.scale_option->count() > 0) {
    std::fprintf(stderr, "sweep: --scale: expected an SVG drawing (.svg) to scale, found '%s'\n",
                 printable_excerpt(choice.obj, 80).c_str());
    return 1;
  }
  if (choice.revolve) {
    std::fprintf(stderr, "sweep: --revolve: expected an SVG drawing (.svg) to revolve, found '%s'\n",
                 printable_excerpt(choice.obj, 80).c_str());
    return 1;
  }
  std::string name;
  if (!chosen_name(choice, name)) return 1;
  Document doc;
  try {
    doc.objects.push_back(io::import_obj_cage(choice.obj, name));
  } catch (const io::ImportError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  io::save_swp_file(choice.swp, doc);
  const Object& mesh = doc.objects.front();
  std::printf("wrote %s (mesh %s: %zu vertices, %zu faces)\n", choice.swp.c_str(), mesh.name.c_str(),
              mesh.as<PointsPart>().points.size(), mesh.as<PolygonMeshSurface>().face_sizes.size());
  return std::fflush(stdout) == 0 ? 0 : 1;
}

/// "N curves" or "1 curve".
std::string counted(std::size_t n, const char* noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

/// Reads the SVG and writes its curves as bez2 objects (atomically, as import_obj does); prints
/// "wrote OUT (N curves: a, b, ...)", revolved "wrote OUT (N curves, N surfaces: a, b, ...)" with
/// the surfaces' names, at most 10 names.
int import_svg(const ImportChoice& choice) {
  if (!(choice.scale > 0.0) || !std::isfinite(choice.scale)) {
    std::fprintf(stderr, "sweep: --scale: expected a number > 0, found %s\n", number_text(choice.scale).c_str());
    return 1;
  }
  std::string name;
  if (!chosen_name(choice, name)) return 1;
  Document doc;
  try {
    doc = io::import_svg_drawing(choice.obj, name, choice.scale,
                                 choice.revolve ? io::DrawingImport::Revolved : io::DrawingImport::Curves);
  } catch (const io::NothingToImport& e) {
    std::fprintf(stderr, "%s\n", e.what());  // not an error: exit 0 (docs/exports-and-imports.md)
    return 0;
  } catch (const io::ImportError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  io::save_swp_file(choice.swp, doc);
  std::size_t curves = 0;
  std::vector<std::string> surfaces;
  for (const Object& object : doc.objects) {
    if (is_surface(object.kind())) {
      surfaces.push_back(object.name);
    } else {
      ++curves;
    }
  }
  std::vector<std::string> shown = surfaces;  // what the user named: the surfaces if any
  if (shown.empty()) {
    for (const Object& object : doc.objects) shown.push_back(object.name);
  }
  std::string names;
  for (std::size_t i = 0; i < shown.size() && i < 10; ++i) names += (i > 0 ? ", " : "") + shown[i];
  if (shown.size() > 10) names += ", ... (" + std::to_string(shown.size() - 10) + " more)";
  std::string counts = counted(curves, "curve");
  if (!surfaces.empty()) counts += ", " + counted(surfaces.size(), "surface");
  std::printf("wrote %s (%s: %s)\n", choice.swp.c_str(), counts.c_str(), names.c_str());
  return std::fflush(stdout) == 0 ? 0 : 1;
}

}  // namespace

void add_import_command(CLI::App& app, Action& action) {
  auto choice = std::make_shared<ImportChoice>();
  CLI::App* command = app.add_subcommand(
      "import",
      "Convert a Wavefront OBJ polygon mesh (all its faces, positions only) into one `mesh` object in OUT, or an SVG "
      "drawing's paths and shapes (a .svg file) into bez2 curves, one per subpath, with --revolve each turned into a "
      "surface of revolution");
  command->add_option("obj", choice->obj, "OBJ or SVG file to read")->required();
  command->add_option("out", choice->swp, "SWP file to write (replaced)")->required();
  add_threads_option(command);
  choice->name_option =
      command->add_option("--name", choice->name,
                          "Name of the mesh object, or of SVG curves whose element has no id (default: the file's "
                          "name without extension)");
  choice->scale_option = command->add_option(
      "--scale", choice->scale,
      "SVG only: SWP units per millimetre (per pixel in a drawing without physical units); default 1");
  command->add_flag("--revolve", choice->revolve,
                    "SVG only: make each curve NAME the profile of a surface of revolution about the y axis: the "
                    "curve becomes NAME_profile, followed by `srev NAME " +
                        std::to_string(io::kRevolvedSteps) +
                        " NAME_profile` (draw a vase's outline from the axis, x = 0, outwards)");
  command->callback([choice, &action] {
    action = [choice] { return is_svg(choice->obj) ? import_svg(*choice) : import_obj(*choice); };
  });
}

}  // namespace sweep::app
