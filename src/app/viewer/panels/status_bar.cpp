// The status bar: the last thing done (ViewerState::status) along the bottom of the window, and
// the first line of an error in its colour, where no panel scrolls them out of sight.
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>

#include <algorithm>
#include <string>

namespace sweep::viewer::panels {

std::string status_line(const ViewerState& s) {
  const std::string& text = s.error.empty() ? s.status : s.error;
  std::string line = text.substr(0, text.find('\n'));
  const auto more = std::count(text.begin(), text.end(), '\n') - (text.ends_with('\n') ? 1 : 0);
  if (more <= 0) return line;
  if (!s.error.empty()) return line + "  (more in the Error panel)";
  return line + "  (and " + std::to_string(more) + " more: point here to see them)";
}

void status_bar(ViewerState& s) {
  if (s.layout.status_height <= 0.0f) return;
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x, viewport->WorkPos.y + viewport->WorkSize.y), ImGuiCond_Always,
                          ImVec2(0.0f, 1.0f));
  ImGui::SetNextWindowSize(ImVec2(viewport->WorkSize.x, s.layout.status_height), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.88f);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(8.0f, 3.0f));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowRounding, 0.0f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav;
  if (ImGui::Begin("##status", nullptr, flags)) {
    const std::string line = status_line(s);
    if (!s.error.empty()) ImGui::PushStyleColor(ImGuiCol_Text, ImVec4(1.0f, 0.45f, 0.4f, 1.0f));
    ImGui::TextUnformatted(line.empty() ? "Ready" : line.c_str());
    if (!s.error.empty()) ImGui::PopStyleColor();
    if (ImGui::IsWindowHovered() && !(s.error.empty() ? s.status : s.error).empty()) {
      ImGui::SetTooltip("%s", (s.error.empty() ? s.status : s.error).c_str());
    }
  }
  ImGui::End();
  ImGui::PopStyleVar(2);
}

}  // namespace sweep::viewer::panels
