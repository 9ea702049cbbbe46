// The progress of long work off the drawing thread, after a short delay, over the bottom of the
// view: a background task (a large file being opened, a large export) with its time and Cancel,
// or a background evaluation (EditSession::set_background) with how far it got and Cancel, which
// takes the document back to what the view shows. Quick work never shows it.
#include "app/viewer/actions.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>

#include <cstdio>

namespace sweep::viewer::panels {
namespace {

/// A borderless window centred over the bottom of the view.
bool begin_progress_window(const editor::ViewportLayout& layout) {
  const ImVec2 centre(static_cast<float>(layout.free_origin.x + 0.5 * layout.free_size.x),
                      static_cast<float>(layout.free_origin.y + layout.free_size.y) - layout.margin);
  ImGui::SetNextWindowPos(centre, ImGuiCond_Always, ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowSize(ImVec2(420.0f * layout.ui_scale, 0.0f), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.92f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav;
  return ImGui::Begin("##progress", nullptr, flags);
}

/// A bar as wide as the window leaves beside a Cancel button (when there is one), then the button.
/// Returns true when Cancel was clicked.
bool bar_and_cancel(ViewerState& s, float fraction, const char* overlay, bool can_cancel) {
  const ImGuiStyle& style = ImGui::GetStyle();
  const float button = can_cancel ? ImGui::CalcTextSize("Cancel").x + 2.0f * style.FramePadding.x : 0.0f;
  ImGui::ProgressBar(fraction, ImVec2(ImGui::GetContentRegionAvail().x - button - style.ItemSpacing.x, 0.0f), overlay);
  if (!can_cancel) return false;
  ImGui::SameLine();
  const bool cancel = ImGui::Button("Cancel");
  // The window's first frame fits its height and draws nothing; the button is where it stays after.
  if (!ImGui::IsWindowAppearing()) mark_item(s, "cancel progress");
  return cancel;
}

void task_progress(ViewerState& s) {
  const editor::BackgroundTask& task = *s.task;
  ImGui::Text("%s: %.1f s", task.label().c_str(), task.seconds());
  if (bar_and_cancel(s, 0.0f, "working", true)) cancel_task(s);
}

void evaluation_progress(ViewerState& s) {
  editor::EditSession& session = s.session;
  const std::size_t total = session.evaluation_objects();
  const auto done = static_cast<std::size_t>(session.evaluation_progress() * double(total) + 0.5);
  ImGui::Text("Re-meshing %zu object%s: %.1f s", total, total == 1 ? "" : "s", session.evaluation_seconds());
  ImGui::TextDisabled("the view shows the last complete meshes meanwhile");
  char overlay[64];
  std::snprintf(overlay, sizeof overlay, "%zu of %zu done", done, total);
  if (bar_and_cancel(s, static_cast<float>(session.evaluation_progress()), overlay, session.can_cancel_evaluation())) {
    session.cancel_evaluation();
    s.status = "cancelled: back to what the view showed";
  }
}

}  // namespace

void progress_panel(ViewerState& s) {
  const bool task = s.task && s.task->seconds() >= kProgressDelay;
  const bool evaluation = s.session.evaluating() && s.session.evaluation_seconds() >= kProgressDelay;
  if (!task && !evaluation) return;
  if (begin_progress_window(s.layout)) {
    if (task) {
      task_progress(s);
    } else {
      evaluation_progress(s);
    }
  }
  ImGui::End();
}

}  // namespace sweep::viewer::panels
