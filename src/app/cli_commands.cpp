// `sweep export`, `sweep info` and the original two-argument form: everything that needs only the
// core library.
#include "app/commands.hpp"

#include "base/precondition.hpp"
#include "geometry/curves/adaptive.hpp"
#include "geometry/surfaces/rider_track.hpp"
#include "geometry/thread_pool.hpp"
#include "io/surface_export.hpp"
#include "io/svg/export.hpp"
#include "io/swp/read.hpp"
#include "model/diagnostics_text.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/scene.hpp"
#include "model/file_limits.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>
#include <vector>

namespace sweep::app {
namespace {

/// Reads FILE into `doc`; a ParseError is printed (FILE:LINE:COLUMN: ...) and gives false. The
/// reader's warnings (images not found, drawn as placeholders) go to stderr.
bool read_swp(const std::string& file, Document& doc) {
  try {
    doc = io::load_swp_file(file);
  } catch (const io::ParseError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return false;
  }
  for (const MissingImage& missing : doc.missing_images) std::fprintf(stderr, "%s\n", missing.warning.c_str());
  return true;
}

struct Loaded {
  Document doc;
  Scene scene;
};

/// Loads and evaluates a file; a problem is printed (load_and_evaluate) and yields nullptr.
std::unique_ptr<Loaded> load(const std::string& file, const EvaluationOptions& options) {
  auto loaded = std::make_unique<Loaded>();
  if (!load_and_evaluate(file, options, loaded->doc, loaded->scene)) return nullptr;
  return loaded;
}

/// Appends x,y,z (shortest round-trip digits) and a separator.
void append_vector(std::string& out, const glm::dvec3& v, char end) {
  char buffer[80];
  char* p = buffer;
  for (int i = 0; i < 3; ++i) {
    p = std::to_chars(p, buffer + sizeof buffer, v[i] + 0.0).ptr;  // + 0.0: no "-0"
    *p++ = i < 2 ? ',' : end;
  }
  out.append(buffer, p);
}

/// `sweep frames FILE CURVE`: the curve's samples as CSV, one line per sample.
int print_frames(const std::string& file, const std::string& name, const EvaluationOptions& options) {
  Document doc;
  if (!read_swp(file, doc)) return 1;
  const int index = doc.find(name);
  if (index < 0 || !is_curve(doc.objects[static_cast<std::size_t>(index)].kind())) {
    std::string curves;
    for (const Object& o : doc.objects) {
      if (is_curve(o.kind()) && !o.name.empty()) curves += (curves.empty() ? "" : ", ") + o.name;
    }
    std::fprintf(stderr, "sweep: %s: expected the name of a curve (%s), found '%s'\n", file.c_str(),
                 curves.empty() ? "it has no named curves" : curves.c_str(),
                 printable_excerpt(name, limits::kMaxNameLength).c_str());
    return 1;
  }
  const Object& curve = doc.objects[static_cast<std::size_t>(index)];
  if (!tolerance_fits(file, options.tolerance, curve_extent(curve), "the curve")) return 1;
  const CurveSamples samples = evaluate_curve(curve, options.frames, {options.tolerance, 0.0});
  if (samples.capped) {
    std::fprintf(stderr, "sweep: %s: tolerance %s is too small for curve '%s': it needs more than %lld samples\n",
                 file.c_str(), number_text(options.tolerance).c_str(), name.c_str(),
                 static_cast<long long>(limits::kMaxCurveSamples));
    return 1;
  }
  // s: the arc length from the start (the riders' clock, geometry/surfaces/rider_track.hpp).
  const std::vector<double> lengths = make_rider_track(describe_curve(curve), samples).lengths;
  std::string out = "t,x,y,z,tx,ty,tz,nx,ny,nz,bx,by,bz,s\n";
  out.reserve(out.size() + samples.frames.size() * 180);
  for (std::size_t i = 0; i < samples.frames.size(); ++i) {
    char buffer[32];
    const double t = i < samples.parameters.size() ? samples.parameters[i] : 0.0;
    out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, t).ptr);
    out += ',';
    const Frame& f = samples.frames[i];
    append_vector(out, f.V, ',');
    append_vector(out, f.T, ',');
    append_vector(out, f.N, ',');
    append_vector(out, f.B, ',');
    out.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, lengths[i]).ptr);
    out += '\n';
  }
  std::fwrite(out.data(), 1, out.size(), stdout);
  return std::fflush(stdout) == 0 ? 0 : 1;
}

int export_obj(const std::string& file, const std::string& prefix, const EvaluationOptions& options,
               io::ExportFormat format = io::ExportFormat::Obj, io::GlbEncoding encoding = io::GlbEncoding::Float,
               const io::PrintOptions& print = {}) {
  const auto loaded = load(file, io::export_evaluation(options, format));
  if (!loaded) return 1;
  io::ExportReport report;
  try {
    report = io::export_surfaces(loaded->doc, loaded->scene, file, prefix, format, encoding, print);
  } catch (const io::ExportError& e) {  // file:line:column; a failed write reaches main
    std::fprintf(stderr, "%s\n", e.what());
    return 1;
  }
  // Nothing to write is not a failure (docs/exports-and-imports.md, "Exit status"): said on
  // stderr, exit 0, as a folder of files exported in a loop needs.
  if (report.files.empty()) std::fprintf(stderr, "%s\n", io::no_surfaces_message(file).c_str());
  for (const std::string& line : io::written_lines(report)) std::printf("%s\n", line.c_str());
  for (const std::string& warning : report.warnings) std::fprintf(stderr, "%s\n", warning.c_str());
  return std::fflush(stdout) == 0 ? 0 : 1;
}

/// `sweep export FILE PREFIX --format svg`: the planar curves, exactly, so nothing is evaluated.
int export_svg(const std::string& file, const std::string& prefix) {
  Document doc;
  if (!read_swp(file, doc)) return 1;
  const io::SvgExport written = io::export_curves_svg(doc, file, prefix);  // a failed write reaches main
  if (written.curves == 0) {                                               // as export_obj: said on stderr, exit 0
    std::fprintf(stderr, "%s\n", io::no_planar_curves_message(file).c_str());
    return 0;
  }
  std::printf("%s\n", io::written_line(written).c_str());
  return std::fflush(stdout) == 0 ? 0 : 1;
}

int print_info(const std::string& file, const EvaluationOptions& options) {
  const auto loaded = load(file, options);
  if (!loaded) return 1;
  std::fputs(editor::document_summary(loaded->doc, loaded->scene, file, options).c_str(), stdout);
  return 0;
}

bool has_display() {
  const char* x = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  return (x && *x) || (wayland && *wayland);
}

}  // namespace

EvaluationOptions EvaluationChoice::options() const {
  return evaluation_options(frames, seam, tolerance, mitre_limit);
}

/// A validator of a finite number for which `accepts` holds; otherwise `expected` and the text.
template <typename Accepts>
CLI::Validator number_validator(Accepts accepts, const std::string& expected, const std::string& description,
                                const std::string& name) {
  return CLI::Validator(
      [accepts, expected](std::string& value) {
        double d = 0.0;
        const auto r = std::from_chars(value.data(), value.data() + value.size(), d);
        const bool number = r.ec == std::errc{} && r.ptr == value.data() + value.size();
        return number && std::isfinite(d) && accepts(d) ? std::string() : expected + value;
      },
      description, name);
}

void add_threads_option(CLI::App* command) {
  command
      ->add_option_function<int>(
          "--threads", [](int threads) { set_worker_count(threads); },
          "Threads for subdivision, evaluation and writing files (default: SWEEP_THREADS, else every core); "
          "the files are the same whatever the count")
      ->type_name("N")
      ->check(
          number_validator([](double d) { return d >= 1.0 && d <= kMaxWorkers && d == std::floor(d); },
                           "expected a whole number of threads from 1 to " + std::to_string(kMaxWorkers) + ", found ",
                           "1 <= N <= " + std::to_string(kMaxWorkers), "threads"));
}

void add_evaluation_options(CLI::App* command, EvaluationChoice& choice) {
  add_threads_option(command);
  command->add_option("--frames", choice.frames, kFramesHelp)
      ->check(CLI::IsMember({"rmf", "projection"}))
      ->capture_default_str();
  command->add_option("--seam", choice.seam, kSeamHelp)
      ->check(CLI::IsMember({"full", "symmetric", "index", "none"}))
      ->capture_default_str();
  command->add_option("--mitre-limit", choice.mitre_limit, kMitreLimitHelp)
      ->type_name("L")
      ->check(number_validator([](double d) { return d >= 1.0; }, "expected a mitre limit of at least 1, found ",
                               "L >= 1", "mitre limit"))
      ->capture_default_str();
  command->add_option("--tolerance", choice.tolerance, kToleranceHelp)
      ->type_name("D")
      ->check(
          number_validator([](double d) { return d > 0.0; }, "expected a tolerance > 0, found ", "D > 0", "tolerance"));
}

bool tolerance_fits(const std::string& file, double tolerance, double extent, const char* what) {
  if (tolerance <= 0.0) return true;
  const std::string problem = check_tolerance(tolerance, extent, what);
  if (problem.empty()) return true;
  std::fprintf(stderr, "sweep: %s: %s, found %s\n", file.c_str(), problem.c_str(), number_text(tolerance).c_str());
  return false;
}

bool load_and_evaluate(const std::string& file, const EvaluationOptions& options, Document& doc, Scene& scene) {
  if (!read_swp(file, doc)) return false;
  // The floor keeps the sample caps out of reach for sensible scenes; checked before any work.
  if (!tolerance_fits(file, options.tolerance, document_extent(doc), "the scene")) return false;
  scene = evaluate_document(doc, options);
  for (std::size_t i = 0; i < doc.objects.size(); ++i) {
    if (!scene.objects[i].over_limit) continue;
    std::fprintf(stderr, "sweep: %s: %s\n", file.c_str(),
                 editor::over_limit_message(doc, static_cast<int>(i), options.tolerance).c_str());
    return false;
  }
  return true;
}

void add_core_commands(CLI::App& app, Action& action) {
  auto files = std::make_shared<std::pair<std::string, std::string>>();
  auto choice = std::make_shared<EvaluationChoice>();

  CLI::App* export_cmd = app.add_subcommand(
      "export",
      "Write PREFIX_NAME.obj (or .stl, .glb) for every named surface of FILE, or PREFIX.svg of its planar curves");
  export_cmd->add_option("file", files->first, "SWP file to read")->required()->check(CLI::ExistingFile);
  export_cmd->add_option("prefix", files->second, "Output prefix: writes PREFIX_NAME.obj (svg: PREFIX.svg)")
      ->required();
  auto format = std::make_shared<std::string>("obj");
  export_cmd
      ->add_option("--format", *format,
                   "obj (Wavefront, the default; a surface with a material also gets PREFIX_NAME.mtl and its "
                   "images), stl (binary STL for 3D printing, a file per surface or --merge one; runs the printability "
                   "checks of `sweep check`), "
                   "glb (binary glTF 2.0 with the material and its texture embedded; with riders also PREFIX.glb, "
                   "one scene of the surfaces and every rider animated along its path), 3mf (one PREFIX.3mf of "
                   "every printable surface for slicers: millimetres, z up, standing on the plate) or svg (the planar "
                   "curves, not the surfaces, exactly as one file PREFIX.svg, 1 unit = 1 mm, for laser cutters "
                   "and plotters)")
      ->check(CLI::IsMember(std::vector<std::string>{"obj", "stl", "glb", "3mf", std::string(io::kSvgFormatName)}));
  auto print = std::make_shared<io::PrintOptions>();
  add_print_options(export_cmd, *print, "3mf and stl only: ");
  export_cmd->add_flag("--merge", print->merge,
                       "stl only: one PREFIX.stl of the whole model, placed as 3mf places it (millimetres, z up, "
                       "standing on the plate)");
  auto quantize = std::make_shared<bool>(false);
  export_cmd->add_flag("--quantize", *quantize,
                       "glb only: store vertices as small integers (KHR_mesh_quantization): positions 16-bit, "
                       "normals 8-bit, texture coordinates 16-bit; about half the size, within 1/65534 of the "
                       "largest coordinate");
  add_evaluation_options(export_cmd, *choice);
  export_cmd->callback([export_cmd, files, choice, format, quantize, print, &action] {
    if (const std::optional<std::string> misplaced = option_for_another_format(*export_cmd, *format)) {
      action = [message = *misplaced] {
        std::fprintf(stderr, "sweep: %s\n", message.c_str());
        return 1;
      };
      return;
    }
    if (*format == io::kSvgFormatName) {
      action = [files] { return export_svg(files->first, files->second); };
      return;
    }
    const io::ExportFormat kind = io::export_format_named(*format).value_or(io::ExportFormat::Obj);
    const io::GlbEncoding encoding = *quantize ? io::GlbEncoding::Quantized : io::GlbEncoding::Float;
    action = [files, choice, kind, encoding, print] {
      return export_obj(files->first, files->second, choice->options(), kind, encoding, *print);
    };
  });

  CLI::App* info_cmd =
      app.add_subcommand("info", "List the objects of FILE with their sample, vertex and triangle counts");
  info_cmd->add_option("file", files->first, "SWP file to read")->required()->check(CLI::ExistingFile);
  add_evaluation_options(info_cmd, *choice);
  info_cmd->callback(
      [files, choice, &action] { action = [files, choice] { return print_info(files->first, choice->options()); }; });

  CLI::App* frames_cmd = app.add_subcommand(
      "frames",
      "Print CURVE's samples as CSV: t,x,y,z,tx,ty,tz,nx,ny,nz,bx,by,bz,s (t: the curve parameter, s: the arc "
      "length from the start)");
  frames_cmd->add_option("file", files->first, "SWP file to read")->required()->check(CLI::ExistingFile);
  frames_cmd->add_option("curve", files->second, "Name of the curve")->required();
  add_evaluation_options(frames_cmd, *choice);
  frames_cmd->callback([files, choice, &action] {
    action = [files, choice] { return print_frames(files->first, files->second, choice->options()); };
  });
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
  plain.add_option("prefix", prefix, "Output prefix: writes PREFIX_NAME.obj (svg: PREFIX.svg)");
  add_evaluation_options(&plain, choice);
  try {
    plain.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return plain.exit(e);
  }
  return run_plain(file, prefix, choice.options());
}

}  // namespace sweep::app
