// The two panel windows, placed where this frame's layout says (never read back to lay out the
// view), the timeline strip, the status bar, the Help window, then the error panel and the modal
// questions.
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"
#include "app/viewer/viewer_state.hpp"

#include <imgui.h>

#include <algorithm>
#include <utility>

namespace sweep::viewer::panels {
namespace {

void main_panel(ViewerState& s, editor::CommandTable& commands) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float margin = s.layout.margin;
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + margin, viewport->WorkPos.y + margin), ImGuiCond_Always);
  const float height = viewport->WorkSize.y - 2.0f * margin - s.layout.status_height;
  ImGui::SetNextWindowSize(ImVec2(s.layout.panel_width, std::max(120.0f, height)), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.88f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_MenuBar | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize;
  if (ImGui::Begin("Sweep", nullptr, flags)) {
    menu_bar(s, commands);
    // What a new user needs first, open, at the top (at 1280x800 all of File and Create show
    // without scrolling); then the long, rarer panels, closed (their settings are also in the
    // menus), so their headers show too; last the outliner, whose list may run on below.
    file_panel(s, commands);
    create_panel(s);
    pen_panel(s, commands);
    if (std::exchange(s.fields.frame_added, false)) commands.run(editor::CommandId::FrameSelection);
    display_panel(s, commands);
    export_panel(s, commands);
    material_panel(s);
    stats_panel(s);
    objects_panel(s);
  }
  ImGui::End();
}

/// Fixed to the top right, as tall as its contents (at most the window).
void edit_window(ViewerState& s, editor::CommandTable& commands) {
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float margin = s.layout.margin;
  const float width = s.layout.edit_width;
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + viewport->WorkSize.x - margin, viewport->WorkPos.y + margin),
                          ImGuiCond_Always, ImVec2(1.0f, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);
  // Above the timeline strip, when there is one.
  const float strip = s.layout.timeline_height > 0.0f ? s.layout.timeline_height + margin : 0.0f;
  const float height = viewport->WorkSize.y - 2.0f * margin - s.layout.status_height - strip;
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 60.0f), ImVec2(width, std::max(120.0f, height)));
  ImGui::SetNextWindowBgAlpha(0.88f);
  if (ImGui::Begin("Edit", nullptr, ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoCollapse)) edit_panel(s, commands);
  mark_window(s, "edit");  // scripted tests wait for its lower edge to settle
  ImGui::End();
}

}  // namespace

void draw_all(ViewerState& s, editor::CommandTable& commands) {
  if (s.show_ui) {
    main_panel(s, commands);
    edit_window(s, commands);
    timeline_panel(s, commands);
    status_bar(s);
  }
  progress_panel(s);
  help_window(s, commands);
  error_panel(s);
  modals(s);
  png_dialog(s);
  file_browser(s);
}

}  // namespace sweep::viewer::panels
