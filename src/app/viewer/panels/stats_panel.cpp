// Stats: what the last frame drew, frame and re-mesh times, each sweep's diagnostics (the same
// text as `sweep info`) and the GL renderer.
#include "app/viewer/panels/panels.hpp"
#include "editor/adaptive_stats.hpp"
#include "editor/diagnostics_text.hpp"
#include "editor/overlay_builder.hpp"

#include <imgui.h>

namespace sweep::viewer::panels {
namespace {

void sweep_diagnostics(const ViewerState& s) {
  const Scene& scene = s.session.scene();
  for (std::size_t i = 0; i < s.doc().objects.size() && i < scene.objects.size(); ++i) {
    if (s.doc().objects[i].kind != ObjectKind::GeneralizedCylinder) continue;
    const SweepDiagnostics& d = scene.objects[i].diagnostics;
    const std::string name = display_name(s.doc(), int(i));
    const ImVec4 colour = d.folds.empty()
                              ? ImGui::GetStyle().Colors[ImGuiCol_Text]
                              : ImVec4(editor::kFoldColor.r, editor::kFoldColor.g, editor::kFoldColor.b, 1.0f);
    ImGui::PushStyleColor(ImGuiCol_Text, colour);
    ImGui::TextWrapped("%s: %s", name.c_str(), editor::sweep_diagnostics_text(d).c_str());
    ImGui::PopStyleColor();
    if (!d.folds.empty() && ImGui::IsItemHovered())
      ImGui::SetTooltip(
          "The tube folds over itself where the sweep bends tighter than the profile's radius\n(shown as magenta "
          "sweep samples when curves are on)");
  }
}

/// What was drawn; with adaptive sampling on, beside what sampling by STEPS would give (so the
/// saving shows), and any object the tolerance is too small for.
void adaptive_counts(const ViewerState& s, const render::RenderStats& stats) {
  const double tolerance = s.session.evaluation().tolerance;
  const Scene& scene = s.session.scene();
  if (tolerance > 0.0) {
    const editor::SamplingCounts steps = editor::steps_counts(s.doc(), scene);
    ImGui::Text("vertices   %zu (by STEPS %lld)", stats.vertices, static_cast<long long>(steps.vertices));
    ImGui::Text("triangles  %zu (by STEPS %lld)", stats.triangles, static_cast<long long>(steps.triangles));
    ImGui::Text("curve samples %zu (by STEPS %lld)", stats.curve_samples, static_cast<long long>(steps.curve_samples));
  } else {
    ImGui::Text("vertices   %zu", stats.vertices);
    ImGui::Text("triangles  %zu", stats.triangles);
    ImGui::Text("curve samples %zu", stats.curve_samples);
  }
  for (const std::string& message : editor::over_limit_messages(s.doc(), scene, tolerance)) {
    ImGui::PushStyleColor(ImGuiCol_Text,
                          ImVec4(editor::kFoldColor.r, editor::kFoldColor.g, editor::kFoldColor.b, 1.0f));
    ImGui::TextWrapped("%s (sampled by STEPS instead)", message.c_str());
    ImGui::PopStyleColor();
  }
}

}  // namespace

void stats_panel(ViewerState& s) {
  if (!ImGui::CollapsingHeader("Stats", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const render::RenderStats& stats = s.stats.render;
  double mean = 0.0;
  for (double ms : s.stats.frame_ms) mean += ms;
  if (!s.stats.frame_ms.empty()) mean /= double(s.stats.frame_ms.size());
  adaptive_counts(s, stats);
  ImGui::Text("frame time %.2f ms (drawing, last frames)", mean);
  if (s.stats.remesh_ms.empty()) {
    ImGui::TextDisabled("re-mesh: no edit yet");
  } else {
    const std::size_t objects = s.session.last_remesh_objects();
    ImGui::Text("re-mesh %.2f ms (last edit, %zu object%s)", s.session.last_remesh_ms(), objects,
                objects == 1 ? "" : "s");
  }
  sweep_diagnostics(s);
  ImGui::TextDisabled("%s", s.stats.gl_description.c_str());
}

}  // namespace sweep::viewer::panels
