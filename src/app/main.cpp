// sweep: the command line. Subcommands come from commands.hpp; the original two-argument form
// `sweep FILE.swp [PREFIX]` is kept because files and scripts in the wild use it.
#include "app/commands.hpp"

#include <cstdio>
#include <exception>
#include <string>
#include <string_view>
#include <vector>

int main(int argc, char** argv) {
  // The original form: first argument is a file, not a subcommand (optionally followed by
  // --frames and --seam).
  if (argc >= 2) {
    std::string_view first = argv[1];
    if (first.size() > 4 && first.substr(first.size() - 4) == ".swp") {
      try {
        return sweep::app::run_plain_command_line(argc, argv);
      } catch (const std::exception& e) {
        std::fprintf(stderr, "sweep: %s\n", e.what());
        return 1;
      }
    }
  }

  CLI::App app{
      "Sweep: spline curves and swept surfaces.\n"
      "Reads SWP files, evaluates curves with moving frames, builds swept surfaces, patches and\n"
      "subdivision surfaces, shows them, renders them headless, checks them against reference\n"
      "pictures (sweep snapshot), exports OBJ (with MTL), STL, glb, 3MF and SVG, checks a model before\n"
      "3D printing (sweep check), and imports OBJ cages and SVG drawings. `sweep FILE.swp PREFIX` is\n"
      "the original form of\n"
      "`sweep export` (and opens the viewer when there is a display); it takes --frames and --seam too.",
      "sweep"};
  app.set_version_flag("--version", "sweep " SWEEP_VERSION);
  app.footer(
      "Exit status: 0 when done, also when a file has nothing for the format asked (no named surface,\n"
      "no planar curve, no shape: nothing is written and stderr says so); 1 for an error (unreadable\n"
      "or wrong input, a bad option, a failed write), with nothing half-written.\nExit status of sweep snapshot: " +
      std::string(sweep::app::kSnapshotExitStatus) +
      "\n"
      "The guide: README.md and docs/ in Sweep's source (viewer.md, swp-format.md, exports-and-imports.md,\n"
      "screenshot-regression.md, printing.md, library.md, python.md, performance.md, reliability.md); `sweep COMMAND "
      "--help` for each command.");
  app.require_subcommand(1);
  sweep::app::Action action;
  sweep::app::add_core_commands(app, action);
  sweep::app::add_import_command(app, action);
  sweep::app::add_check_command(app, action);
  sweep::app::add_convert_command(app, action);
  sweep::app::add_view_commands(app, action);
  sweep::app::add_snapshot_command(app, action);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    // `sweep snapshot` promises CI 0 (all pass), 1 (a failure) and 2 (usage or input errors).
    const bool snapshot = argc >= 2 && std::string_view(argv[1]) == "snapshot";
    return snapshot && code != 0 ? 2 : code;
  }
  try {
    return action ? action() : 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "sweep: %s\n", e.what());
    return 1;
  }
}
