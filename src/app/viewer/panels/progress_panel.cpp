// The progress of a background evaluation (EditSession::set_background): after a short delay, a
// bar over the bottom of the view with what is being evaluated, how far it got, and Cancel, which
// takes the document back to what the view shows. Quick edits never show it.
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>

#include <cstdio>

namespace sweep::viewer::panels {

void progress_panel(ViewerState& s) {
  editor::EditSession& session = s.session;
  if (!session.evaluating() || session.evaluation_seconds() < kProgressDelay) return;
  const editor::ViewportLayout& layout = s.layout;
  const ImVec2 size(420.0f * layout.ui_scale, 0.0f);
  const ImVec2 centre(static_cast<float>(layout.free_origin.x + 0.5 * layout.free_size.x),
                      static_cast<float>(layout.free_origin.y + layout.free_size.y) - layout.margin);
  ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowSize(size, ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.92f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav;
  if (ImGui::Begin("##evaluation progress", nullptr, flags)) {
    const std::size_t total = session.evaluation_objects();
    const auto done = static_cast<std::size_t>(session.evaluation_progress() * double(total) + 0.5);
    ImGui::Text("Re-meshing %zu object%s: %.1f s", total, total == 1 ? "" : "s", session.evaluation_seconds());
    ImGui::TextDisabled("the view shows the last complete meshes meanwhile");
    char overlay[64];
    std::snprintf(overlay, sizeof overlay, "%zu of %zu done", done, total);
    const bool can_cancel = session.can_cancel_evaluation();
    const float button = can_cancel ? ImGui::CalcTextSize("Cancel").x + 2.0f * ImGui::GetStyle().FramePadding.x : 0.0f;
    ImGui::ProgressBar(static_cast<float>(session.evaluation_progress()),
                       ImVec2(ImGui::GetContentRegionAvail().x - button - ImGui::GetStyle().ItemSpacing.x, 0.0f),
                       overlay);
    if (can_cancel) {
      ImGui::SameLine();
      const bool cancel = ImGui::Button("Cancel");
      mark_item(s, "cancel evaluation");
      if (cancel) {
        session.cancel_evaluation();
        s.status = "cancelled: back to what the view showed";
      }
    }
  }
  ImGui::End();
}

}  // namespace sweep::viewer::panels
