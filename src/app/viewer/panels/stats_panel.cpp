// Stats: what the last frame drew (with adaptive sampling, beside what STEPS would give), frame
// and re-mesh times, each sweep's diagnostics (the same text as `sweep info`) and the GL renderer.
#include "app/viewer/panels/panels.hpp"
#include "editor/adaptive_stats.hpp"
#include "editor/overlay_builder.hpp"
#include "model/diagnostics_text.hpp"

#include <imgui.h>

namespace sweep::viewer::panels {
namespace {

void sweep_diagnostics(const StatsParts& s) {
  const Scene& scene = s.session.scene();
  for (std::size_t i = 0; i < s.doc().objects.size() && i < scene.objects.size(); ++i) {
    if (s.doc().objects[i].kind() != ObjectKind::GeneralizedCylinder) continue;
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

/// A count as sampled, what sampling by STEPS gives and the share.
void count_row(const char* what, std::int64_t sampled, std::int64_t by_steps) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(what);
  ImGui::TableNextColumn();
  ImGui::Text("%lld", static_cast<long long>(sampled));
  ImGui::TableNextColumn();
  ImGui::Text("%lld", static_cast<long long>(by_steps));
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(editor::share_text(sampled, by_steps).c_str());
}

/// The counts both ways, in the table the caller began.
void sampling_table(const editor::SamplingSummary& summary) {
  ImGui::TableSetupColumn("");
  ImGui::TableSetupColumn("adaptive");
  ImGui::TableSetupColumn("by STEPS");
  ImGui::TableSetupColumn("share");
  ImGui::TableHeadersRow();
  const editor::SamplingCounts& a = summary.sampled;
  const editor::SamplingCounts& b = summary.by_steps;
  count_row("vertices", a.vertices, b.vertices);
  count_row("triangles", a.triangles, b.triangles);
  count_row("curve samples", a.curve_samples, b.curve_samples);
  ImGui::EndTable();
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Visible objects: sampled for the tolerance, and by their STEPS as without Adaptive");
}

/// What was drawn. With adaptive sampling (the Adaptive toggle or a curve's tolerance clause),
/// the visible objects' counts beside what sampling them by STEPS gives (count formulas, no
/// evaluation), so the saving shows; and every object the tolerance is too small for.
void sampling_counts(const StatsParts& s, const render::RenderStats& stats) {
  const editor::SamplingSummary summary =
      editor::sampling_summary(s.doc(), s.session.scene(), s.session.evaluation(), s.views.visibility(s.doc()));
  if (!summary.adaptive) {
    ImGui::Text("vertices   %zu", stats.vertices);
    ImGui::Text("triangles  %zu", stats.triangles);
    ImGui::Text("curve samples %zu", stats.curve_samples);
  } else {
    ImGui::PushStyleVar(ImGuiStyleVar_CellPadding, ImVec2(8.0f, ImGui::GetStyle().CellPadding.y));
    const bool table = ImGui::BeginTable("sampling", 4, ImGuiTableFlags_SizingFixedFit);
    ImGui::PopStyleVar();
    if (table) sampling_table(summary);
  }
  for (const std::string& message : summary.over_limit) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));  // as the error panel
    ImGui::TextWrapped("%s", message.c_str());
    ImGui::PopStyleColor();
  }
}

}  // namespace

void stats_panel(const StatsParts& s) {
  if (!ImGui::CollapsingHeader("Stats")) return;
  const render::RenderStats& stats = s.stats.render;
  double mean = 0.0;
  for (double ms : s.stats.frame_ms) mean += ms;
  if (!s.stats.frame_ms.empty()) mean /= double(s.stats.frame_ms.size());
  sampling_counts(s, stats);
  ImGui::Text("frame time %.2f ms (drawing, last frames)", mean);
  if (s.stats.remesh_ms.empty()) {
    ImGui::TextDisabled("re-mesh: no edit yet");
  } else {  // the last edit, undo, redo or change of frames, seam or tolerance
    const std::size_t objects = s.session.last_remesh_objects();
    ImGui::Text("re-mesh %.2f ms (last change, %zu object%s)", s.session.last_remesh_ms(), objects,
                objects == 1 ? "" : "s");
  }
  sweep_diagnostics(s);
  ImGui::TextDisabled("%s", s.stats.gl_description.c_str());
}

}  // namespace sweep::viewer::panels
