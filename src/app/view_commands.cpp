// `sweep view` (the GLFW window) and `sweep render` (the same renderer through OSMesa): their
// options, checks and file loading. The drawing runs in the sweep_gui module (gui_module.cpp),
// opened only when one of these actions runs.
#include "app/commands.hpp"

#include "app/gui_module.hpp"
#include "app/viewer/viewer.hpp"
#include "geometry/curves/adaptive.hpp"
#include "io/swp/read.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/riders.hpp"
#include "model/evaluation/scene.hpp"
#include "model/material.hpp"
#include "render/camera.hpp"
#include "render/display_settings.hpp"
#include "render/draw_list.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sweep::app {
namespace {

/// Options shared by both commands: what to draw.
struct ModeOptions {
  std::string surface = "smooth";
  std::string curves = "on";
  std::string points = "off";
  std::string color = "material";
};

struct RenderOptions {
  std::string file;
  std::string output;
  std::string size = "800x600";
  ModeOptions modes;
  double yaw = render::Camera::kDefaultYaw;
  double pitch = render::Camera::kDefaultPitch;
  double distance = 0.0;  // 0: framed
  bool ortho = false;
  bool grid = false;  // the viewer's ground grid and axes (off: the pictures stay as they were)
  EvaluationChoice evaluation;
  double time = 0.0;
  std::string sequence;
  double fps = 24.0;
  double seconds = 0.0;  // 0: the longest rider's loop
  std::string ride;
  std::string ride_view = "chase";
};

struct ViewOptions {
  std::string file;
  std::string size = "1280x800";
  ModeOptions modes{"smooth", "on", "on"};  // the viewer starts with the control points shown
  std::string screenshot;
  int frame_count = 0;
  EvaluationChoice evaluation;
  int samples = 4;
  bool frame_time = false;
  bool no_ui = false;
  bool no_reload = false;
  std::string select;
  bool play = false;
  std::string ride;
  std::string ride_view = "chase";
};

/// Riders: the time of a still, or a sequence of frames, and a camera riding along.
void add_time_options(CLI::App* command, RenderOptions& options) {
  command->add_option("--time", options.time, "Draw the riders where they are at T seconds")
      ->check(CLI::Range(-1e9, 1e9))
      ->capture_default_str();
  command->add_option("--sequence", options.sequence,
                      "Write DIR/frame_0000.png, ... for a whole loop (the longest rider's seconds) instead of -o");
  command->add_option("--fps", options.fps, "Frames per second of --sequence")
      ->check(CLI::Range(1.0, 240.0))
      ->capture_default_str();
  command->add_option("--seconds", options.seconds, "Length of --sequence in seconds (default: the longest loop)")
      ->check(CLI::Range(1e-3, 3600.0));
  command->add_option("--ride", options.ride, "Ride along with rider NAME (the camera follows it)");
  command->add_option("--ride-view", options.ride_view, "How --ride looks: chase (behind and above) or first-person")
      ->check(CLI::IsMember({"chase", "first-person"}))
      ->capture_default_str();
}

void add_mode_options(CLI::App* command, ModeOptions& modes) {
  command->add_option("--surface", modes.surface, "Surfaces: smooth, wire (wireframe + normals) or off")
      ->check(CLI::IsMember({"smooth", "wire", "off"}))
      ->capture_default_str();
  command->add_option("--curves", modes.curves, "Curves: on, frames (with N red, B green, T blue) or off")
      ->check(CLI::IsMember({"on", "frames", "off"}))
      ->capture_default_str();
  command->add_option("--points", modes.points, "Control points and polygons: on or off")
      ->check(CLI::IsMember({"on", "off"}))
      ->capture_default_str();
  command
      ->add_option("--color", modes.color,
                   "Surface colours: material, gaussian or mean (curvature, blue < 0 < red), normals or uv")
      ->check(CLI::IsMember({"material", "gaussian", "mean", "normals", "uv"}))
      ->capture_default_str();
}

render::DisplaySettings display_settings(const ModeOptions& modes) {
  render::DisplaySettings settings;
  render::show_surface(settings, render::surface_mode_from_name(modes.surface).value_or(render::SurfaceMode::Smooth));
  settings.curves = render::curve_mode_from_name(modes.curves).value_or(render::CurveMode::Curves);
  settings.control_points = modes.points == "on";
  settings.color = render::color_mode_from_name(modes.color).value_or(render::ColorMode::Material);
  return settings;
}

/// The rider `name` of `doc`, or -1 with a message naming the riders there are.
int find_rider(const Document& doc, const std::string& file, const std::string& name) {
  const int index = doc.find(name);
  if (index >= 0 && is_rider(doc.objects[static_cast<std::size_t>(index)].kind())) return index;
  std::string riders;
  for (const int r : riders_of(doc)) riders += (riders.empty() ? "" : ", ") + doc.objects[std::size_t(r)].name;
  std::fprintf(stderr, "sweep: --ride: %s has no rider '%s' (%s)\n", file.c_str(), name.c_str(),
               riders.empty() ? "it has no riders" : ("its riders: " + riders).c_str());
  return -1;
}

/// The time options of `sweep render` into the request; false (with a message) if they do not fit.
bool set_time_options(const RenderOptions& options, const Document& doc, PictureRequest& request) {
  if (options.output.empty() == options.sequence.empty()) {
    std::fprintf(stderr, "sweep: render: give either -o FILE.png (a still) or --sequence DIR (frames)\n");
    return false;
  }
  request.time = options.time;
  request.sequence = options.sequence;
  request.fps = options.fps;
  request.seconds = options.seconds > 0.0 ? options.seconds : longest_loop(doc);
  if (!options.sequence.empty() && request.seconds <= 0.0) {
    std::fprintf(stderr, "sweep: --sequence: %s has no riders; give --seconds S\n", options.file.c_str());
    return false;
  }
  request.ride_view = options.ride_view == "first-person" ? render::RideView::FirstPerson : render::RideView::Chase;
  if (options.ride.empty()) return true;
  request.ride = find_rider(doc, options.file, options.ride);
  return request.ride >= 0;
}

int render_png(const RenderOptions& options) {
  const glm::ivec2 size = parse_size(options.size).value_or(glm::ivec2(800, 600));
  Document doc;
  Scene scene;
  render::DisplaySettings display = display_settings(options.modes);
  display.grid = options.grid;
  EvaluationOptions evaluation = options.evaluation.options();
  evaluation.texture_coordinates = render::texture_coordinates_drawn(display.color);
  if (!load_and_evaluate(options.file, evaluation, doc, scene)) return 1;

  PictureRequest request;
  request.doc = &doc;
  request.scene = &scene;
  request.camera.reset(render::scene_bounds(scene), double(size.x) / double(size.y));
  request.camera.set_yaw_pitch(options.yaw, options.pitch);
  if (options.distance > 0.0) request.camera.distance = options.distance;
  if (options.ortho) request.camera.projection = render::Projection::Orthographic;
  request.size = size;
  request.display = display;
  request.image_base = image_base(options.file);
  request.output = options.output;
  if (!set_time_options(options, doc, request)) return 1;
  const GuiEntryPoints* gui = load_gui_module();
  return gui ? gui->render_picture(request) : 1;
}

/// Runs the viewer from the sweep_gui module (loaded only now).
int run_gui_viewer(const viewer::ViewerOptions& options) {
  const GuiEntryPoints* gui = load_gui_module();
  return gui ? gui->run_viewer(options) : 1;
}

/// --tolerance below the floor of FILE's scene is refused before a window opens (a file that does
/// not parse opens anyway: the viewer shows its error and can fix it).
bool scene_tolerance_fits(const std::string& file, double tolerance) {
  if (tolerance <= 0.0 || file.empty()) return true;
  try {
    return tolerance_fits(file, tolerance, document_extent(io::load_swp_file(file)), "the scene");
  } catch (const io::ParseError&) {
    return true;
  }
}

int view(const ViewOptions& options) {
  if (!scene_tolerance_fits(options.file, options.evaluation.tolerance)) return 1;
  viewer::ViewerOptions viewer_options;
  viewer_options.file = options.file;
  viewer_options.window_size = parse_size(options.size).value_or(glm::ivec2(1280, 800));
  viewer_options.samples = options.samples;
  viewer_options.display = display_settings(options.modes);
  viewer_options.display.grid = true;  // the ground grid and axes; G toggles them
  viewer_options.screenshot = options.screenshot;
  viewer_options.evaluation = options.evaluation.options();
  viewer_options.evaluation.texture_coordinates = render::texture_coordinates_drawn(viewer_options.display.color);
  // A screenshot without a frame count is taken once the UI has settled (it lays out over a few frames).
  viewer_options.frame_count = options.frame_count > 0 ? options.frame_count : (options.screenshot.empty() ? 0 : 5);
  viewer_options.print_frame_time = options.frame_time;
  viewer_options.show_ui = !options.no_ui;
  viewer_options.select = options.select;
  viewer_options.live_reload = !options.no_reload;
  viewer_options.play = options.play;
  viewer_options.ride = options.ride;
  viewer_options.first_person = options.ride_view == "first-person";
  return run_gui_viewer(viewer_options);
}

}  // namespace

/// Parses "WxH" with both sides in [1, kMaxImageSide].
std::optional<glm::ivec2> parse_size(const std::string& text) {
  const std::size_t x = text.find_first_of("xX");
  if (x == std::string::npos) return std::nullopt;
  glm::ivec2 size{0, 0};
  const char* begin = text.data();
  const char* end = text.data() + text.size();
  const auto w = std::from_chars(begin, begin + x, size.x);
  const auto h = std::from_chars(begin + x + 1, end, size.y);
  if (w.ec != std::errc{} || w.ptr != begin + x || h.ec != std::errc{} || h.ptr != end) return std::nullopt;
  if (size.x < 1 || size.y < 1 || size.x > kMaxImageSide || size.y > kMaxImageSide) return std::nullopt;
  return size;
}

const CLI::Validator kSizeValidator = CLI::Validator(
    [](std::string& value) {
      return parse_size(value) ? std::string() : "expected WxH with sides 1.." + std::to_string(kMaxImageSide);
    },
    "WxH", "size");

void add_view_commands(CLI::App& app, Action& action) {
  auto view_options = std::make_shared<ViewOptions>();
  CLI::App* view_cmd = app.add_subcommand("view", "Open FILE in the interactive viewer (needs a display)");
  view_cmd->add_option("file", view_options->file, "SWP file to open")->check(CLI::ExistingFile);
  view_cmd->add_option("--size", view_options->size, "Window size WxH in screen units")
      ->check(kSizeValidator)
      ->capture_default_str();
  add_mode_options(view_cmd, view_options->modes);
  view_cmd->add_option("--screenshot", view_options->screenshot,
                       "Save a PNG of the window after --frame-count N frames (default 5) and exit");
  view_cmd
      ->add_option("--frame-count", view_options->frame_count,
                   "Draw N frames without waiting for input, then exit (scripted runs, measurements)")
      ->check(CLI::Range(1, 1000000));
  add_evaluation_options(view_cmd, view_options->evaluation);
  view_cmd
      ->add_option("--samples", view_options->samples,
                   "Multisampling (MSAA) samples of the still picture (moving frames use none); 0 turns it off")
      ->check(CLI::Range(0, 16))
      ->capture_default_str();
  view_cmd->add_flag("--frame-time", view_options->frame_time,
                     "Draw continuously and print frame times on exit (moving and still frames apart)");
  view_cmd->add_flag("--no-ui", view_options->no_ui, "Hide the ImGui panels");
  view_cmd->add_flag("--no-reload", view_options->no_reload,
                     "Do not reload the file when another program changes it (the File panel's toggle)");
  view_cmd->add_flag("--play", view_options->play, "Start with the riders playing (Shift+Space pauses)");
  view_cmd->add_option("--ride", view_options->ride, "Start riding along with rider NAME (the camera follows it)");
  view_cmd->add_option("--ride-view", view_options->ride_view, "How --ride looks: chase or first-person")
      ->check(CLI::IsMember({"chase", "first-person"}))
      ->capture_default_str();
  view_cmd->add_option("--select", view_options->select,
                       "Select object NAME (or e.g. bez2#0) at start and print its handles' window positions "
                       "(for scripted GUI tests)");
  view_cmd->callback([view_options, &action] { action = [view_options] { return view(*view_options); }; });

  auto render_options = std::make_shared<RenderOptions>();
  CLI::App* render_cmd =
      app.add_subcommand("render", "Render FILE to a PNG without a display (OSMesa), as the viewer shows it");
  render_cmd->add_option("file", render_options->file, "SWP file to read")->required()->check(CLI::ExistingFile);
  render_cmd->add_option("-o,--output", render_options->output, "PNG file to write (or --sequence)");
  render_cmd->add_option("--size", render_options->size, "Image size WxH in pixels")
      ->check(kSizeValidator)
      ->capture_default_str();
  add_mode_options(render_cmd, render_options->modes);
  render_cmd->add_option("--yaw", render_options->yaw, "Camera yaw in degrees about +y")
      ->check(CLI::Range(-3600.0, 3600.0))
      ->capture_default_str();
  render_cmd->add_option("--pitch", render_options->pitch, "Camera pitch in degrees above the xz-plane")
      ->check(CLI::Range(-90.0, 90.0))
      ->capture_default_str();
  render_cmd
      ->add_option("--distance", render_options->distance,
                   "Camera distance from the scene centre (default: framed to fit)")
      ->check(CLI::PositiveNumber);
  render_cmd->add_flag("--ortho", render_options->ortho, "Orthographic projection");
  render_cmd->add_flag("--grid", render_options->grid, "Draw the viewer's ground grid (xz-plane) and axes");
  add_evaluation_options(render_cmd, render_options->evaluation);
  add_time_options(render_cmd, *render_options);
  render_cmd->callback(
      [render_options, &action] { action = [render_options] { return render_png(*render_options); }; });
}

int open_viewer(const std::string& file, const EvaluationOptions& evaluation) {
  viewer::ViewerOptions options;
  options.file = file;
  options.evaluation = evaluation;
  return run_gui_viewer(options);
}

}  // namespace sweep::app
