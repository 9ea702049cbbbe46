// `sweep export`, `sweep info` and the original two-argument form: everything that needs only the
// core library.
#include "app/commands.hpp"

#include "core/scene.hpp"
#include "core/swp_parser.hpp"
#include "editor/diagnostics_text.hpp"
#include "editor/surface_export.hpp"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace sweep::app {
namespace {

struct Loaded {
  Document doc;
  Scene scene;
};

/// Loads and evaluates a file; a parse error is printed as file:line:column and yields nullptr.
std::unique_ptr<Loaded> load(const std::string& file, const EvaluationOptions& options) {
  try {
    auto loaded = std::make_unique<Loaded>();
    loaded->doc = load_swp_file(file);
    loaded->scene = evaluate_document(loaded->doc, options);
    return loaded;
  } catch (const ParseError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return nullptr;
  }
}

int export_obj(const std::string& file, const std::string& prefix, const EvaluationOptions& options) {
  const auto loaded = load(file, options);
  if (!loaded) return 1;
  editor::ExportReport report;
  try {
    report = editor::export_surfaces(loaded->doc, loaded->scene, file, prefix);
  } catch (const editor::ExportError& e) {  // file:line:column; a failed write reaches main
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  if (report.files.empty()) std::printf("%s\n", editor::no_surfaces_message(file).c_str());
  for (const editor::ExportedFile& f : report.files) {
    std::printf("wrote %s (%zu vertices, %zu triangles)\n", f.path.c_str(), f.vertices, f.triangles);
  }
  std::fflush(stdout);
  for (const std::string& warning : report.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
  return 0;
}

int print_info(const std::string& file, const EvaluationOptions& options) {
  const auto loaded = load(file, options);
  if (!loaded) return 1;
  std::fputs(editor::document_summary(loaded->doc, loaded->scene, file).c_str(), stdout);
  return 0;
}

bool has_display() {
  const char* x = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (wayland && *wayland);
}

}  // namespace

EvaluationOptions EvaluationChoice::options() const {
  EvaluationOptions options;
  options.frames.method = frames == "projection" ? FrameMethod::Projection : FrameMethod::RotationMinimizing;
  options.seam = seam == "symmetric" ? SeamMode::Symmetric : SeamMode::Full;
  options.frames.close_seam = seam != "none";
  return options;
}

void add_seam_option(CLI::App* command, EvaluationChoice& choice) {
  command->add_option("--seam", choice.seam, kSeamHelp)
      ->check(CLI::IsMember({"full", "symmetric", "none"}))
      ->capture_default_str();
}

void add_evaluation_options(CLI::App* command, EvaluationChoice& choice) {
  command->add_option("--frames", choice.frames, kFramesHelp)
      ->check(CLI::IsMember({"rmf", "projection"}))
      ->capture_default_str();
  add_seam_option(command, choice);
}

void add_core_commands(CLI::App& app, Action& action) {
  auto files = std::make_shared<std::pair<std::string, std::string>>();
  auto choice = std::make_shared<EvaluationChoice>();

  CLI::App* export_cmd = app.add_subcommand("export", "Write PREFIX_NAME.obj for every named surface of FILE");
  export_cmd->add_option("file", files->first, "SWP file to read")->required()->check(CLI::ExistingFile);
  export_cmd->add_option("prefix", files->second, "Output prefix: writes PREFIX_NAME.obj")->required();
  add_evaluation_options(export_cmd, *choice);
  export_cmd->callback([files, choice, &action] {
    action = [files, choice] { return export_obj(files->first, files->second, choice->options()); };
  });

  CLI::App* info_cmd =
      app.add_subcommand("info", "List the objects of FILE with their sample, vertex and triangle counts");
  info_cmd->add_option("file", files->first, "SWP file to read")->required()->check(CLI::ExistingFile);
  add_evaluation_options(info_cmd, *choice);
  info_cmd->callback(
      [files, choice, &action] { action = [files, choice] { return print_info(files->first, choice->options()); }; });
}

int run_plain(const std::string& file, const std::string& prefix, const EvaluationOptions& options) {
  if (!prefix.empty()) {
    const int status = export_obj(file, prefix, options);
    if (status != 0 || !has_display()) return status;
  }
  return open_viewer(file, options);
}

int run_plain_command_line(int argc, char** argv) {
  CLI::App plain{"The original form of `sweep export` (and the viewer when there is a display).",
                 "sweep FILE.swp [PREFIX]"};
  std::string file;
  std::string prefix;
  EvaluationChoice choice;
  plain.add_option("file", file, "SWP file to read")->required();
  plain.add_option("prefix", prefix, "Output prefix: writes PREFIX_NAME.obj");
  add_evaluation_options(&plain, choice);
  try {
    plain.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return plain.exit(e);
  }
  return run_plain(file, prefix, choice.options());
}

}  // namespace sweep::app
