// The error panel: the last error (a file:line:column message for a bad file) over the 3D view,
// between the panels, until dismissed.
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>

#include <algorithm>

namespace sweep::viewer::panels {

void error_panel(const ErrorParts& s) {
  if (s.error.empty()) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float left = viewport->WorkPos.x + float(s.layout.free_left());
  const float right = viewport->WorkPos.x + float(s.layout.free_right());
  const float width = std::max(200.0f, right - left - 24.0f);
  ImGui::SetNextWindowPos(ImVec2(left + 12.0f, viewport->WorkPos.y + 12.0f), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(std::min(720.0f, width), 0.0f), ImGuiCond_Always);
  if (ImGui::Begin("Error", nullptr, ImGuiWindowFlags_NoCollapse)) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextWrapped("%s", s.error.c_str());
    ImGui::PopStyleColor();
    if (ImGui::Button("Dismiss")) s.error.clear();
  }
  ImGui::End();
}

}  // namespace sweep::viewer::panels
