// `sweep export`, `sweep info` and the original two-argument form: everything that needs only the
// core library.
#include "app/commands.hpp"

#include "core/obj_writer.hpp"
#include "core/scene.hpp"
#include "core/swp_parser.hpp"

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <numbers>
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

constexpr double kDegrees = 180.0 / std::numbers::pi;

/// "t = 1.20 to 1.45, t = 3.00 to 3.10": the parameter ranges of the folds.
std::string fold_ranges(const std::vector<FoldRange>& folds) {
  std::string text;
  for (const FoldRange& fold : folds) {
    char range[96];
    std::snprintf(range, sizeof range, "%st = %.2f to %.2f", text.empty() ? "" : ", ", fold.t_begin, fold.t_end);
    text += range;
  }
  return text;
}

int export_obj(const std::string& file, const std::string& prefix, const EvaluationOptions& options) {
  const auto loaded = load(file, options);
  if (!loaded) return 1;
  const Document& doc = loaded->doc;
  // Check every mesh before writing any file, so a bad one leaves nothing half-exported.
  int named = 0;
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const Object& o = doc.objects[i];
    if (!is_surface(o.kind) || o.name.empty()) continue;
    ++named;
    if (!mesh_is_finite(loaded->scene.objects[i].mesh)) {
      std::fprintf(stderr, "%s:%d:%d: surface '%s' has a NaN or infinite coordinate; nothing written\n", file.c_str(),
                   o.location.line, o.location.column, o.name.c_str());
      return 1;
    }
  }
  if (named == 0) {
    std::printf("%s has no named surfaces; nothing written\n", file.c_str());
    return 0;
  }
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const Object& o = doc.objects[i];
    if (!is_surface(o.kind) || o.name.empty()) continue;
    const Mesh& mesh = loaded->scene.objects[i].mesh;
    const std::string path = prefix + "_" + o.name + ".obj";
    save_obj_file(path, mesh, "sweep: " + o.name + " from " + file);
    std::printf("wrote %s (%zu vertices, %zu triangles)\n", path.c_str(), mesh.vertex_count(), mesh.triangle_count());
    const SweepDiagnostics& diagnostics = loaded->scene.objects[i].diagnostics;
    if (!diagnostics.folds.empty()) {
      std::fflush(stdout);
      std::fprintf(stderr,
                   "warning: surface '%s' folds over itself where the profile reaches beyond the sweep's radius of "
                   "curvature (%s)\n",
                   o.name.c_str(), fold_ranges(diagnostics.folds).c_str());
    }
  }
  return 0;
}

int print_info(const std::string& file, const EvaluationOptions& options) {
  const auto loaded = load(file, options);
  if (!loaded) return 1;
  const Document& doc = loaded->doc;
  std::printf("%s: %zu objects\n", file.c_str(), doc.objects.size());
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    const Object& o = doc.objects[i];
    const EvaluatedObject& e = loaded->scene.objects[i];
    const std::string name = display_name(doc, static_cast<int>(i));
    if (is_curve(o.kind)) {
      std::printf("  %-4s %-16s line %-4d steps %-6d", std::string(keyword(o.kind)).c_str(), name.c_str(),
                  o.location.line, o.steps);
      if (o.kind == ObjectKind::Circle) {
        std::printf(" radius %g", o.radius);
      } else {
        std::printf(" %zu control points", o.points.size());
      }
      std::printf(", %zu samples%s\n", e.curve.frames.size(), e.curve.closed ? ", closed" : "");
    } else {
      std::printf("  %-4s %-16s line %-4d", std::string(keyword(o.kind)).c_str(), name.c_str(), o.location.line);
      if (o.kind == ObjectKind::SurfaceOfRevolution) {
        std::printf(" steps %-6d profile %s", o.steps, display_name(doc, o.profile).c_str());
      } else {
        std::printf(" profile %s, sweep %s", display_name(doc, o.profile).c_str(), display_name(doc, o.sweep).c_str());
      }
      std::printf(": %zu vertices, %zu triangles\n", e.mesh.vertex_count(), e.mesh.triangle_count());
      if (o.kind == ObjectKind::GeneralizedCylinder) {
        const SweepDiagnostics& d = e.diagnostics;
        std::printf("       %s, seam angle %.2f deg, total twist %.2f deg, %s\n",
                    d.closed ? "closed sweep" : "open sweep", d.seam_angle * kDegrees, d.total_twist * kDegrees,
                    d.folds.empty() ? "no folds" : ("folds at " + fold_ranges(d.folds)).c_str());
      }
    }
  }
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
