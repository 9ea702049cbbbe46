#include "app/viewer/actions.hpp"

#include "app/viewer/dialog_actions.hpp"

#include "app/viewer/file_safety.hpp"
#include "app/viewer/selected_curve.hpp"
#include "base/precondition.hpp"
#include "editor/adaptive_stats.hpp"
#include "geometry/curves/adaptive.hpp"
#include "io/surface_export.hpp"
#include "io/swp/read.hpp"
#include "model/edit/edit.hpp"
#include "model/evaluation/curve_evaluation.hpp"
#include "model/evaluation/riders.hpp"
#include "render/draw_list.hpp"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <utility>

namespace sweep::viewer {
namespace {

/// The fields that follow the current file's name.
/// The export and PNG fields show names relative to output_folder (the file's stem), which is
/// also where an untitled document's outputs go next (s.last_folder).
void after_file_change(ViewerState& s) {
  const std::string& path = s.session.file();
  s.fields.open.set(path);
  s.fields.save_as.set(path);
  const std::string stem = default_output_stem(s);
  s.fields.export_prefix.set(stem);
  s.fields.screenshot.set(stem + ".png");
  if (!path.empty()) s.last_folder = output_folder(s);
}

/// The process's working folder ("/" if it cannot be found, e.g. it was removed).
std::filesystem::path working_folder() {
  std::error_code ec;
  std::filesystem::path here = std::filesystem::current_path(ec);
  return ec ? std::filesystem::path("/") : here;
}

/// `folder` normalised, without a trailing separator ("/a/b/../" is "/a").
std::filesystem::path normal_folder(const std::filesystem::path& folder) {
  std::filesystem::path normal = folder.lexically_normal();
  if (normal.has_relative_path() && !normal.has_filename()) normal = normal.parent_path();
  return normal;
}

/// After any change of the document: the selection, the name field and the timing.
void after_edit(ViewerState& s) {
  // What the status said was about the document before this edit: the caller says what it did.
  s.status.clear();
  s.fields.rename_for = editor::kNoObject;  // the name field shows the name as it now is
  s.selection.fix(s.session);
  s.stats.remesh_ms.push_back(s.session.last_remesh_ms());
  if (s.session.take_history_notice()) {
    s.status +=
        "\nthe undo history is full (1000 steps or 2 million stored points): from now on the oldest steps are "
        "forgotten";
  }
}

/// Objects the tolerance is too small for (sampled otherwise) go to the error panel, once
/// per change of the evaluation or file; the stats panel keeps listing them. When none is left,
/// an error that said so goes away.
void report_over_limit(ViewerState& s) {
  std::string text;
  for (const std::string& message :
       editor::over_limit_messages(s.doc(), s.session.scene(), s.session.evaluation().tolerance)) {
    text += (text.empty() ? "" : "\n") + message;
  }
  if (!text.empty()) {
    s.error = text;
  } else if (!s.over_limit_error.empty() && s.error == s.over_limit_error) {
    s.error.clear();
  }
  s.over_limit_error = text;
}

/// A viewer tolerance below the floor of `doc`'s scene (another file is opened) is raised to it,
/// so the sample caps are never what stops the sampling. Evaluates the current document by
/// STEPS first, so that neither scene is ever sampled for a tolerance far below its floor.
void fit_tolerance_to(ViewerState& s, const Document& doc) {
  EvaluationOptions options = s.session.evaluation();
  const double floor = editor::tolerance_range(document_extent(doc)).low;
  if (!(options.tolerance > 0.0) || options.tolerance >= floor) return;
  options.tolerance = 0.0;
  s.session.set_evaluation(options);
  options.tolerance = floor;
  s.session.set_evaluation(options);
}

/// The layout of this frame again, with the timeline strip if the document now has riders, so a
/// file opened is framed in the part the strip leaves free (the next frame's layout has it too).
void fit_layout_to_timeline(ViewerState& s) {
  const editor::ViewportLayout& old = s.layout;
  const glm::ivec2 window(old.window);
  const glm::ivec2 framebuffer(glm::round(old.window * double(old.pixel_ratio)));
  s.layout = editor::compute_layout(window, framebuffer, old.ui_scale, s.show_ui, !riders_of(s.doc()).empty());
}

/// Where the browser starts: the current file's folder, or the working folder.
std::filesystem::path browser_start(const ViewerState& s) {
  if (!s.session.file().empty()) return s.session.file();
  return working_folder();
}

}  // namespace

void TextField::set(const std::string& value) {
  const std::size_t n = std::min(value.size(), text.size() - 1);
  std::copy_n(value.begin(), n, text.begin());
  text[n] = '\0';
}

bool show_document(ViewerState& s, Document doc, const std::string& path) {
  const EvaluationOptions before = s.session.evaluation();
  try {
    fit_tolerance_to(s, doc);
    s.session.load(std::move(doc), path);
  } catch (const std::exception& e) {  // e.g. out of memory while evaluating
    s.error = path + ": " + e.what();
    return false;
  }
  s.views.clear();
  s.curve_editing.joints.clear();
  s.selection.clear();
  s.playback = {};
  stop_riding(s);
  fit_layout_to_timeline(s);
  reset_camera(s);
  s.frame_when_evaluated = s.session.evaluating();
  s.error.clear();
  s.status = "opened " + path;
  if (s.session.evaluation().tolerance != before.tolerance) {
    s.status +=
        "\ntolerance raised to " + editor::tolerance_text(s.session.evaluation().tolerance) + " (this scene's floor)";
  }
  s.over_limit_error.clear();
  report_over_limit(s);
  // The reader's warnings (images not found, drawn as magenta checkers), under any error.
  for (const MissingImage& missing : s.doc().missing_images) {
    s.error += (s.error.empty() ? "" : "\n") + missing.warning;
  }
  if (!path.empty()) remember_recent_file(s, path);
  after_file_change(s);
  after_document_shown(s);
  return true;
}

bool save_to(ViewerState& s, const std::string& path) {
  if (s.session.in_step()) s.session.end_step();  // a field still being typed in counts
  const std::string previous = s.session.file();
  if (!s.session.save(path)) {
    s.error = s.session.error();
    return false;
  }
  // The full path: the user sees where the file went, whatever was typed.
  std::error_code ec;
  const std::filesystem::path absolute = std::filesystem::absolute(path, ec);
  const std::string full = ec ? path : absolute.lexically_normal().string();
  s.status = "saved " + full;
  s.error.clear();
  remember_recent_file(s, path);
  after_file_change(s);
  after_saved(s, previous);
  if (s.report_saves) {
    std::printf("saved %s\n", full.c_str());
    std::fflush(stdout);
  }
  return true;
}

void ask_save_path(ViewerState& s) {
  // The name alone: the field is taken relative to the folder the browser shows.
  const std::string& file = s.session.file();
  s.fields.save_as.set(file.empty() ? "untitled.swp" : std::filesystem::path(file).filename().string());
  s.browser.open_at(browser_start(s));
  s.unsaved.ask_path();
}

void open_browser(ViewerState& s, BrowserPurpose purpose) {
  if (purpose == BrowserPurpose::Open && start_open_dialog(s)) return;
  s.browser.open_at(browser_start(s));
  s.browser_for = purpose;
}

void save_current(ViewerState& s) {
  if (s.session.file().empty()) {
    ask_save_path(s);
  } else if (s.safety.changed_on_disk) {
    s.safety.question = FileSafety::Question::Overwrite;  // kept edits over a changed file
    if (s.report_saves) {
      std::printf("question overwrite\n");
      std::fflush(stdout);
    }
  } else {
    save_to(s, s.session.file());
  }
}

void request_open(ViewerState& s, const std::string& path) {
  s.unsaved.request(editor::PendingAction::Open, path, s.session.dirty());
}

void request_new(ViewerState& s) {
  s.unsaved.request(editor::PendingAction::New, "", s.session.dirty());
}

void request_quit(ViewerState& s) {
  s.unsaved.request(editor::PendingAction::Quit, "", s.session.dirty());
}

void run_ready_action(ViewerState& s) {
  const std::string path = s.unsaved.path();
  switch (s.unsaved.take_ready()) {
    case editor::PendingAction::Open:
      open_file(s, path);
      break;
    case editor::PendingAction::New:
      if (show_document(s, Document{}, "")) s.status = "new untitled document";
      break;
    case editor::PendingAction::Quit:
      s.quit = true;
      break;
    case editor::PendingAction::None:
      break;
  }
}

std::filesystem::path output_folder(const std::string& file, const std::filesystem::path& last_folder,
                                    const std::filesystem::path& working) {
  if (file.empty()) return normal_folder(last_folder.empty() ? working : last_folder);
  return normal_folder((working / file).parent_path());  // an absolute file replaces `working`
}

std::filesystem::path output_folder(const ViewerState& s) {
  return output_folder(s.session.file(), s.last_folder, working_folder());
}

std::filesystem::path resolve_output_path(const std::string& typed, const std::filesystem::path& folder,
                                          const std::string& fallback) {
  return (folder / (typed.empty() ? fallback : typed)).lexically_normal();  // an absolute one replaces `folder`
}

std::string default_output_stem(const ViewerState& s) {
  const std::string& file = s.session.file();
  return file.empty() ? std::string("untitled") : std::filesystem::path(file).stem().string();
}

void request_screenshot(ViewerState& s, const std::string& name, bool with_panels) {
  std::filesystem::path path = resolve_output_path(name, output_folder(s), default_output_stem(s) + ".png");
  if (!path.has_extension()) path += ".png";
  s.pending_screenshot = {path, with_panels, with_panels ? 1 : 0};
}

const std::vector<PngSize>& png_sizes() {
  static const std::vector<PngSize> sizes = {{"the view's size", {0, 0}},
                                             {"1920 x 1080 (full HD)", {1920, 1080}},
                                             {"1280 x 800 (the viewer's window)", {1280, 800}},
                                             {"800 x 600 (sweep render)", {800, 600}},
                                             {"320 x 240 (sweep snapshot)", {320, 240}}};
  return sizes;
}

void open_png_dialog(ViewerState& s) {
  s.png_dialog = {true, 0, s.display.control_points, s.display.curves != render::CurveMode::Off, s.display.grid};
}

void request_view_png(ViewerState& s, const std::string& name) {
  request_screenshot(s, name, false);
  const PngDialog& answers = s.png_dialog;
  const std::vector<PngSize>& sizes = png_sizes();
  const auto choice = static_cast<std::size_t>(answers.size_choice);
  s.pending_screenshot.size = choice < sizes.size() ? sizes[choice].pixels : glm::ivec2(0, 0);
  s.pending_screenshot.control_points = answers.control_points;
  s.pending_screenshot.curves = answers.curves;
  s.pending_screenshot.grid = answers.grid;
  s.png_dialog.open = false;
}

PixelRect view_rect(const editor::ViewportLayout& layout, glm::ivec2 framebuffer) {
  SWEEP_EXPECTS(framebuffer.x > 0 && framebuffer.y > 0, "framebuffer > 0 both ways");
  const double ratio = double(layout.pixel_ratio);
  // [begin, end) of the pixels wholly inside [from, to) screen units, within [0, size).
  const auto inwards = [ratio](double from, double to, int size) {
    const int begin = std::clamp(int(std::ceil(from * ratio - 1e-6)), 0, size);
    const int end = std::clamp(int(std::floor(to * ratio + 1e-6)), begin, size);
    return std::pair{begin, end};
  };
  const auto [left, right] = inwards(layout.free_left(), layout.free_right(), framebuffer.x);
  const auto [top, bottom] = inwards(layout.free_origin.y, layout.free_origin.y + layout.free_size.y, framebuffer.y);
  return {left, top, right - left, bottom - top};
}

void open_dropped(ViewerState& s, const std::vector<std::string>& paths) {
  std::string chosen;
  for (const std::string& path : paths) {
    if (std::filesystem::path(path).extension() == ".swp") {
      chosen = path;
    } else {
      s.status = "not an SWP file: " + path;
    }
  }
  if (!chosen.empty()) request_open(s, chosen);
}

bool run_edit(ViewerState& s, const std::string& label, const editor::EditSession::Operation& operation) {
  if (!s.session.edit(label, operation)) {
    s.error = s.session.error();
    return false;
  }
  s.error.clear();
  after_edit(s);
  return true;
}

bool apply_continuous(ViewerState& s, const editor::EditSession::Operation& operation) {
  if (!s.session.apply(operation)) {
    s.error = s.session.error();
    return false;
  }
  after_edit(s);
  return true;
}

void undo(ViewerState& s) {
  const std::string step = s.session.undo_label();
  if (!s.session.undo()) return;
  after_edit(s);
  s.status = "undone: " + step;
}

void redo(ViewerState& s) {
  const std::string step = s.session.redo_label();
  if (!s.session.redo()) return;
  after_edit(s);
  s.status = "redone: " + step;
}

const Object* selected_control_curve(const ViewerState& s) {
  return control_curve(s.session, s.selection);
}

void delete_selected_point(ViewerState& s) {
  const int point = s.selection.point;
  if (selected_control_curve(s) == nullptr || point < 0) return;
  const int object = s.selected();
  if (run_edit(s, "delete point", [object, point](Document& d) { return delete_point(d, object, point); })) {
    s.selection.point = std::min(point, int(s.doc().objects[std::size_t(object)].as<PointsPart>().points.size()) - 1);
    s.status = "deleted point " + std::to_string(point);
  }
}

/// I at an end of an open curve: extends the curve there (extend_curve) and selects the new end.
void extend_at_selected_end(ViewerState& s, CurveEnd end) {
  const int object = s.selected();
  const bool bezier = point_layout(s.doc().objects[std::size_t(object)].kind()).has_joints();
  if (!run_edit(s, bezier ? "add piece" : "add point",
                [object, end](Document& d) { return extend_curve(d, object, end); })) {
    return;
  }
  s.selection.point = end_point(s.doc().objects[std::size_t(object)], end);
  s.status = std::string(bezier ? "added a piece" : "added a point") +
             (end == CurveEnd::Start ? " before the start" : " after the end");
}

std::string insert_label(const ViewerState& s) {
  const Object* curve = selected_control_curve(s);
  if (curve == nullptr || s.selection.point < 0) return "Insert point after the selected one";
  const bool bezier = point_layout(curve->kind()).has_joints();
  if (const std::optional<CurveEnd> end = end_at(*curve, s.selection.point)) {
    return std::string(bezier ? "Add a piece" : "Add a point") +
           (*end == CurveEnd::Start ? " before the start" : " after the end");
  }
  return bezier ? "Insert: select an end to add a piece (or split a piece)" : "Insert point after the selected one";
}

void insert_after_selected_point(ViewerState& s) {
  const Object* curve = selected_control_curve(s);
  if (curve == nullptr || s.selection.point < 0) return;
  if (const std::optional<CurveEnd> end = end_at(*curve, s.selection.point)) {
    extend_at_selected_end(s, *end);
    return;
  }
  const PointLayout& layout = point_layout(curve->kind());
  if (layout.unit != EditUnit::Point && layout.unit != EditUnit::PointAndTangent) {
    s.error = "a Bezier curve grows at its ends: select its first or last point, or split a piece to add a joint";
    return;
  }
  // Between the selected group's point and the next one (a Hermite point's tangent is not a place).
  const std::vector<glm::dvec3>& points = curve->as<PointsPart>().points;
  const std::size_t stride = layout.stride;
  const std::size_t i = std::size_t(s.selection.point) - std::size_t(s.selection.point) % stride;
  const glm::dvec3 position = i + stride < points.size() ? 0.5 * (points[i] + points[i + stride])
                              : i >= stride              ? points[i] + 0.5 * (points[i] - points[i - stride])
                                                         : points[i];
  const int object = s.selected();
  const int before = int(i + stride);
  if (run_edit(s, "insert point",
               [object, before, position](Document& d) { return insert_bspline_point(d, object, before, position); })) {
    s.selection.point = before;
    s.status = "inserted point " + std::to_string(before);
  }
}

bool select_by_name(ViewerState& s, const std::string& name) {
  for (std::size_t i = 0; i < s.doc().objects.size(); ++i) {
    if (display_name(s.doc(), static_cast<int>(i)) == name) {
      s.selection.select(s.session.id_of(static_cast<int>(i)));
      return true;
    }
  }
  return false;
}

void set_evaluation(ViewerState& s, const EvaluationOptions& options) {
  try {
    s.session.set_evaluation(options);
  } catch (const std::exception& e) {
    s.error = std::string("cannot re-evaluate: ") + e.what();
    return;
  }
  s.stats.remesh_ms.push_back(s.session.last_remesh_ms());  // the stats panel shows it
  report_over_limit(s);
}

void set_color_mode(ViewerState& s, render::ColorMode mode) {
  s.display.color = mode;
  EvaluationOptions evaluation = s.session.evaluation();
  const TextureCoordinates drawn = render::texture_coordinates_drawn(mode);
  if (evaluation.texture_coordinates == drawn) return;
  evaluation.texture_coordinates = drawn;
  set_evaluation(s, evaluation);
}

}  // namespace sweep::viewer
