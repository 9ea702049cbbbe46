// Display: surface and curve modes, control points, the profile view, projection and preset
// views, how sweeps are framed, and the threads the work uses.
#include "app/viewer/actions.hpp"
#include "app/viewer/panels/number_field.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"
#include "app/viewer/panels/value_slider.hpp"

#include "base/number_text.hpp"
#include "editor/curvature_comb.hpp"
#include "editor/overlay_builder.hpp"
#include "geometry/mesh/colormap.hpp"
#include "geometry/thread_pool.hpp"

#include <imgui.h>

#include <algorithm>
#include <thread>
#include <utility>

namespace sweep::viewer::panels {
namespace {

using editor::CommandId;
constexpr int kOneThread = 1;

/// Curvature modes: the cool-warm bar with its range (the same range for every surface).
void color_legend(const ViewerState& s) {
  if (s.display.color != render::ColorMode::Gaussian && s.display.color != render::ColorMode::Mean) return;
  const float range = s.stats.render.color_range;
  const ImVec2 origin = ImGui::GetCursorScreenPos();
  const float width = ImGui::GetContentRegionAvail().x;
  const float height = ImGui::GetTextLineHeight();
  ImDrawList* draw = ImGui::GetWindowDrawList();
  constexpr int kSteps = 32;
  for (int k = 0; k < kSteps; ++k) {
    const float t0 = -1.0f + 2.0f * static_cast<float>(k) / kSteps;
    const float t1 = -1.0f + 2.0f * static_cast<float>(k + 1) / kSteps;
    const glm::vec3 a = cool_warm(t0);
    const glm::vec3 b = cool_warm(t1);
    const ImU32 ca = ImGui::GetColorU32(ImVec4(a.x, a.y, a.z, 1.0f));
    const ImU32 cb = ImGui::GetColorU32(ImVec4(b.x, b.y, b.z, 1.0f));
    const float x0 = origin.x + width * static_cast<float>(k) / kSteps;
    const float x1 = origin.x + width * static_cast<float>(k + 1) / kSteps;
    draw->AddRectFilledMultiColor(ImVec2(x0, origin.y), ImVec2(x1, origin.y + height), ca, cb, cb, ca);
  }
  ImGui::Dummy(ImVec2(width, height));
  ImGui::Text("%-10.3g %s 0 %10.3g", static_cast<double>(-range),
              s.display.color == render::ColorMode::Gaussian ? "  Gaussian (1/length^2)" : "  mean (1/length)",
              static_cast<double>(range));
}

void mode_controls(ViewerState& s, const editor::CommandTable& commands) {
  int surface = static_cast<int>(s.display.surface);
  const std::string surfaces = with_shortcut(commands, CommandId::CycleSurfaces, "Surfaces");
  if (ImGui::Combo(surfaces.c_str(), &surface, "Smooth shaded\0Wireframe\0Off\0")) {
    s.display.surface = static_cast<render::SurfaceMode>(surface);
  }
  int curves = static_cast<int>(s.display.curves);
  const std::string curves_label = with_shortcut(commands, CommandId::CycleCurves, "Curves");
  if (ImGui::Combo(curves_label.c_str(), &curves, "Curves\0Curves + frames\0Off\0")) {
    s.display.curves = static_cast<render::CurveMode>(curves);
  }
  ImGui::Checkbox(with_shortcut(commands, CommandId::ToggleNormals, "Normals").c_str(), &s.display.normals);
  mark_item(s, "normals");
  ImGui::Checkbox(with_shortcut(commands, CommandId::TogglePoints, "Control points").c_str(),
                  &s.display.control_points);
  ImGui::Checkbox(with_shortcut(commands, CommandId::ToggleGrid, "Grid and axes").c_str(), &s.display.grid);
  int color = static_cast<int>(s.display.color);
  if (ImGui::Combo("Colour", &color, "Materials\0Gaussian curvature\0Mean curvature\0Normals\0Texture coordinates\0")) {
    set_color_mode(s, static_cast<render::ColorMode>(color));
  }
  color_legend(s);
}

void camera_controls(ViewerState& s, editor::CommandTable& commands) {
  bool profile = s.profile_view;
  if (ImGui::Checkbox(with_shortcut(commands, CommandId::ProfileView, "Profile view (xy)").c_str(), &profile)) {
    set_profile_view(s, profile);
  }
  if (!s.profile_view) {
    bool ortho = s.camera.projection == render::Projection::Orthographic;
    ImGui::SameLine();
    if (ImGui::Checkbox("Orthographic", &ortho)) {
      s.camera.projection = ortho ? render::Projection::Orthographic : render::Projection::Perspective;
    }
    for (const auto& [id, name] : {std::pair{CommandId::ViewFront, "Front"}, std::pair{CommandId::ViewTop, "Top"},
                                   std::pair{CommandId::ViewSide, "Side"}}) {
      command_button(commands, id, name);
      ImGui::SameLine();
    }
  }
  command_button(commands, CommandId::ResetCamera, "Reset");
}

/// The mitre limit, dragged or typed (a double-click or Ctrl+click): at least 1, as
/// `--mitre-limit` takes it. Returns whether `evaluation` changed.
bool mitre_field(ViewerState& s, EvaluationOptions& evaluation) {
  bool changed = false;
  setting_field(s, {"Mitre limit", "mitre limit", evaluation.mitre_limit, false, "mitre limit"},
                float_slider("Mitre limit", 1.0f, 10.0f, "%.2f"), [&](double limit) {
                  if (!(limit >= 1.0)) return "expected a mitre limit of at least 1, found " + number_text(limit);
                  evaluation.mitre_limit = limit;
                  changed = true;
                  return std::string();
                });
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Sharp corners of a sweep are mitred up to this stretch of the profile and bevelled past it\n(SVG's "
        "stroke-miterlimit; 4 by default, 1 bevels every corner)");
  return changed;
}

void frame_controls(ViewerState& s) {
  EvaluationOptions evaluation = s.session.evaluation();
  int method = evaluation.frames.method == FrameMethod::RotationMinimizing ? 0 : 1;
  int seam = evaluation.seam == SeamMode::Symmetric                     ? 1
             : evaluation.frames.seam_spread == SeamSpread::SampleIndex ? 2
                                                                        : 0;
  bool changed = ImGui::Combo("Frames", &method, "rotation-minimizing\0projection (original)\0");
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("How 3D sweep curves carry their frames");
  changed |= ImGui::Combo("Seam", &seam, "full\0symmetric\0by index (course)\0");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "How a tube along a closed sweep closes: spread the whole seam angle by arc length, only\nwhat the "
        "profile's rotational symmetry does not absorb, or the whole angle evenly by\nsample index (the course's "
        "reference tool)");
  changed |= mitre_field(s, evaluation);
  if (!changed) return;
  evaluation.frames.method = method == 0 ? FrameMethod::RotationMinimizing : FrameMethod::Projection;
  evaluation.seam = seam == 1 ? SeamMode::Symmetric : SeamMode::Full;
  evaluation.frames.seam_spread = seam == 2 ? SeamSpread::SampleIndex : SeamSpread::ArcLength;
  set_evaluation(s, evaluation);
}

/// The threads re-meshing, subdivision and exports use (as --threads): at most the cores, or
/// what SWEEP_THREADS asked for when that is more.
void thread_control() {
  int threads = worker_count();
  const int high = std::max({default_worker_count(), static_cast<int>(std::thread::hardware_concurrency()), 1});
  if (high <= 1) return;  // nothing to choose
  if (value_slider("Threads", ImGuiDataType_S32, &threads, &kOneThread, &high, "%d")) {
    set_worker_count(std::clamp(threads, 1, high));
  }
  if (ImGui::IsItemHovered()) {
    ImGui::SetTooltip(
        "Threads for re-meshing, subdivision and exports (as --threads); the meshes and files are "
        "the same whatever the count");
  }
}

/// One line of the legend: a swatch of `colour` and what it marks.
void legend_line(const glm::vec3& colour, const char* what) {
  ImGui::ColorButton(what, ImVec4(colour.r, colour.g, colour.b, 1.0f), ImGuiColorEditFlags_NoTooltip,
                     ImVec2(ImGui::GetFontSize(), ImGui::GetFontSize()));
  ImGui::SameLine();
  ImGui::TextWrapped("%s", what);
}

/// Every mark the view draws, named with its colour (issue 59: the magenta dots explained).
void legend(const ViewerState& s) {
  if (!ImGui::TreeNode("Legend: what the marks mean")) return;
  legend_line(editor::kHighlightColor, "the selected object");
  legend_line(editor::kHandleColor, "the selected curve's control points (its control polygon dimmer)");
  legend_line(editor::kHandleSelectedColor, "the selected point (and the points of a closed seam with it)");
  legend_line(editor::kHandleHoveredColor, "the point under the pointer");
  legend_line(editor::kFoldColor,
              "where a tube folds over itself: its sweep bends tighter than the profile's size (Stats)");
  legend_line(s.display.normal_color, "normals (N)");
  legend_line(s.display.wire_color, "the wireframe (S)");
  legend_line({1.0f, 0.0f, 0.0f}, "a frame's N, in frames mode (C)");
  legend_line({0.0f, 1.0f, 0.0f}, "a frame's B");
  legend_line({0.0f, 0.0f, 1.0f}, "a frame's T");
  legend_line(editor::kCombColor, "the curvature comb (K)");
  legend_line(editor::kGridColor, "the ground grid (Shift+G)");
  ImGui::TreePop();
}

}  // namespace

void display_panel(ViewerState& s, editor::CommandTable& commands) {
  if (!ImGui::CollapsingHeader("Display")) return;
  mode_controls(s, commands);
  camera_controls(s, commands);
  frame_controls(s);
  thread_control();
  legend(s);
  ImGui::TextDisabled(s.profile_view ? "drag: left/middle pan, right zoom"
                                     : "drag: left rotate, right zoom, middle pan");
}

}  // namespace sweep::viewer::panels
