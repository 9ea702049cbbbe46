// `sweep import CAGE.obj OUT.swp [--name NAME]`: a Wavefront OBJ polygon mesh as one `mesh` object.
#include "app/commands.hpp"

#include "geometry/limits.hpp"
#include "io/obj_import.hpp"
#include "io/swp_writer.hpp"
#include "model/document.hpp"

#include <cstdio>
#include <memory>
#include <string>

namespace sweep::app {
namespace {

struct ImportChoice {
  std::string obj;
  std::string swp;
  std::string name;
  CLI::Option* name_option = nullptr;
};

/// Reads the OBJ and writes the SWP (atomically: on any error nothing is written). A problem with
/// the OBJ is printed as its one line ("FILE:LINE: ..." or "FILE: ..."); a failed write reaches main.
int import_obj(const ImportChoice& choice) {
  const bool named = choice.name_option->count() > 0;
  const std::string name = named ? choice.name : object_name_from_path(choice.obj);
  if (!is_valid_object_name(name)) {
    std::fprintf(stderr,
                 "sweep: --name: expected a name (a letter or '_', then letters, digits, '_', '-' or '.', at most "
                 "%zu bytes), found '%s'\n",
                 limits::kMaxNameLength, printable_excerpt(name, 40).c_str());
    return 1;
  }
  Document doc;
  try {
    doc.objects.push_back(import_obj_cage(choice.obj, name));
  } catch (const ImportError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  save_swp_file(choice.swp, doc);
  const Object& mesh = doc.objects.front();
  std::printf("wrote %s (mesh %s: %zu vertices, %zu faces)\n", choice.swp.c_str(), mesh.name.c_str(),
              mesh.as<PointsPart>().points.size(), mesh.as<PolygonMeshSurface>().face_sizes.size());
  return std::fflush(stdout) == 0 ? 0 : 1;
}

}  // namespace

void add_import_command(CLI::App& app, Action& action) {
  auto choice = std::make_shared<ImportChoice>();
  CLI::App* command = app.add_subcommand(
      "import", "Convert a Wavefront OBJ polygon mesh (all its faces, positions only) into one `mesh` object in OUT");
  command->add_option("obj", choice->obj, "OBJ file to read")->required();
  command->add_option("out", choice->swp, "SWP file to write (replaced)")->required();
  choice->name_option = command->add_option("--name", choice->name,
                                            "Name of the mesh object (default: the OBJ file's name without extension)");
  command->callback([choice, &action] { action = [choice] { return import_obj(*choice); }; });
}

}  // namespace sweep::app
