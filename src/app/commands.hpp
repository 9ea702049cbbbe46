#pragma once
// The sweep command line is put together from these; each adds its subcommand(s) to the app.
#include "io/surface_export.hpp"
#include "model/evaluation/scene.hpp"

#include <CLI/CLI.hpp>

#include <glm/vec2.hpp>

#include <functional>
#include <optional>
#include <string>

namespace sweep::app {

/// Work to run after parsing; returns the process exit code.
using Action = std::function<int()>;

/// How curves and surfaces are evaluated, as typed on the command line.
struct EvaluationChoice {
  std::string frames = "rmf";        // rmf | projection
  std::string seam = "full";         // full | symmetric | none
  double tolerance = 0.0;            // > 0: --tolerance D (adaptive sampling)
  double mitre_limit = kMitreLimit;  // --mitre-limit L (>= 1)
  /// The options these choices name. Precondition: the strings passed the options' checks.
  EvaluationOptions options() const;
};

/// Help text of --frames and --seam (shared by every command that evaluates a file).
inline constexpr const char* kFramesHelp =
    "Frames along 3D sweep curves: rmf (rotation-minimizing, double reflection; the default) or projection "
    "(the original tool's N = B x T update)";
inline constexpr const char* kSeamHelp =
    "How a tube along a closed sweep closes: full (end frame = start frame, the twist spread along the sweep by "
    "arc length), symmetric (for a k-fold symmetric profile spread only the twist modulo 1/k turn), index (the "
    "twist spread evenly by sample index, as the course's reference tool does) or none (no correction, for "
    "comparisons)";

inline constexpr const char* kMitreLimitHelp =
    "Sharp corners of a sweep are mitred (the profile in the plane bisecting the bend, stretched by 1/cos(half "
    "the turn)) up to this stretch and bevelled past it (the tube cut square at the corner on both sides, joined "
    "by a flat strip), as SVG's stroke-miterlimit; at least 1 (1 bevels every corner)";

inline constexpr const char* kToleranceHelp =
    "Sample every curve and surface adaptively so it stays within D (model units) of the exact one, instead "
    "of by STEPS (overrides the curves' own tolerance clauses); at least 1e-6 of the scene's size";

/// Adds --frames rmf|projection, --seam full|symmetric|index|none, --mitre-limit L and --tolerance D
/// to `command`.
void add_evaluation_options(CLI::App* command, EvaluationChoice& choice);
/// --threads N (1..kMaxWorkers): set_worker_count for the command's work. add_evaluation_options
/// adds it; commands without those options add it themselves.
void add_threads_option(CLI::App* command);

/// True if --tolerance `tolerance` (0: none) may be used on something of size `extent` in FILE
/// (`what`: "the scene" or "the curve"); else prints "sweep: FILE: expected ..., found D" and
/// returns false. cli_commands.cpp
bool tolerance_fits(const std::string& file, double tolerance, double extent, const char* what);

/// Reads and evaluates FILE for `options` into doc and scene. On a parse error (file:line:column),
/// a tolerance below the floor or one too small for an object (the sample caps), prints the one
/// message and returns false. cli_commands.cpp
bool load_and_evaluate(const std::string& file, const EvaluationOptions& options, Document& doc, Scene& scene);

/// The plain form `sweep FILE.swp [PREFIX] [--frames M] [--seam S]`: parses argv (argv[1] is the
/// file) and runs it. cli_commands.cpp
int run_plain_command_line(int argc, char** argv);

/// `sweep export FILE.swp PREFIX`, `sweep info FILE.swp` and `sweep frames FILE.swp CURVE` (core
/// only). cli_commands.cpp
void add_core_commands(CLI::App& app, Action& action);

/// --height MM and --min-wall MM of the print exports and `sweep check` into `print`, their help
/// starting with `scope` ("3mf and stl only: " for export). print_command.cpp
void add_print_options(CLI::App* command, io::PrintOptions& print, const std::string& scope);

/// For `sweep export` with --format `format`: "--quantize: expected --format glb, found --format
/// stl" when an option given belongs to another format (--quantize: glb; --height, --min-wall:
/// 3mf or stl; --merge: stl), else nullopt. print_command.cpp
std::optional<std::string> option_for_another_format(const CLI::App& export_command, const std::string& format);

/// `sweep check FILE [--height MM] [--min-wall MM]`: the printability checks of a 3MF export,
/// without writing; exit 1 when one fails. print_command.cpp
void add_check_command(CLI::App& app, Action& action);

/// `sweep import CAGE.obj OUT.swp [--name NAME]`: an OBJ polygon mesh as one `mesh` object;
/// `sweep import DRAWING.svg OUT.swp [--scale S] [--name NAME] [--revolve]`: an SVG's curves.
/// import_command.cpp
void add_import_command(CLI::App& app, Action& action);

/// `sweep convert FILE CURVE --to KIND [-o OUT] [--tolerance D]`: one curve as another kind, the
/// rest of the file as it was. convert_command.cpp
void add_convert_command(CLI::App& app, Action& action);

/// The largest picture side of `sweep render` (`sweep snapshot`: snapshot::kMaxSnapshotSide).
inline constexpr int kMaxImageSide = 16384;
/// Parses "WxH" with both sides in [1, kMaxImageSide]. view_commands.cpp
std::optional<glm::ivec2> parse_size(const std::string& text);
/// CLI11's check of a WxH option. view_commands.cpp
extern const CLI::Validator kSizeValidator;

/// `sweep snapshot`'s exit statuses, stated once for `sweep --help` (the man page) and
/// `sweep snapshot --help`.
inline constexpr const char* kSnapshotExitStatus =
    "0 all cases pass (warnings allowed), 1 a failure or an unaccepted new reference, 2 a usage, suite or input "
    "error.";

/// `sweep snapshot DIR`: screenshot regression of a folder of models (GL). snapshot_command.cpp
void add_snapshot_command(CLI::App& app, Action& action);

/// `sweep view FILE.swp` and `sweep render FILE.swp -o OUT.png` (GL). view_commands.cpp
void add_view_commands(CLI::App& app, Action& action);

/// Opens the viewer on `file` (used by the plain `sweep FILE.swp [PREFIX]` form).
/// Without a display, prints one line saying so and pointing to `sweep render`, returns 1.
int open_viewer(const std::string& file, const EvaluationOptions& options);

/// The plain form: exports OBJ (when prefix is not empty) then opens the viewer if a display is
/// available. cli_commands.cpp
int run_plain(const std::string& file, const std::string& prefix, const EvaluationOptions& options);

}  // namespace sweep::app
