// The timeline strip, while the document has riders: play / pause, the time slider (scrubbing),
// the speed, the time as text, and riding along with a rider (chase or first person) or back to
// the orbit camera. It sits above the status bar, from the main panel to the window's right edge
// (the edit panel ends above it), where the layout keeps it out of the 3D view.
#include "app/viewer/actions.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"
#include "app/viewer/panels/value_slider.hpp"

#include "model/evaluation/riders.hpp"

#include <imgui.h>

#include <algorithm>
#include <string>
#include <vector>

namespace sweep::viewer::panels {
namespace {

using editor::CommandId;

/// Play or Pause (with its key), the time slider, the time as text and the speed.
void clock_row(ViewerState& s, editor::CommandTable& commands, double loop) {
  const bool enabled = commands.enabled(CommandId::PlayPause);
  const std::string play = with_shortcut(commands, CommandId::PlayPause, s.playback.playing() ? "Pause" : "Play");
  if (!enabled) ImGui::BeginDisabled();
  // One id for both labels, and as wide as the wider, so the slider does not jump.
  const float button = ImGui::CalcTextSize(with_shortcut(commands, CommandId::PlayPause, "Pause").c_str()).x +
                       2.0f * ImGui::GetStyle().FramePadding.x;
  if (ImGui::Button((play + "###play").c_str(), ImVec2(button, 0.0f))) commands.run(CommandId::PlayPause);
  if (!enabled) ImGui::EndDisabled();
  mark_item(s, "play");

  ImGui::SameLine();
  const float speed_width = 90.0f * s.layout.ui_scale;
  const float text_width = ImGui::CalcTextSize("/ 0000.00 s").x;
  const ImGuiStyle& style = ImGui::GetStyle();
  ImGui::SetNextItemWidth(
      std::max(60.0f, ImGui::GetContentRegionAvail().x - speed_width - text_width - 2.0f * style.ItemSpacing.x));
  double time = s.playback.time();
  const double zero = 0.0;
  if (value_slider("##time", ImGuiDataType_Double, &time, &zero, &loop, "%.2f s")) s.playback.scrub(time, loop);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Drag to scrub: where the riders are at this time");
  mark_item(s, "time");
  ImGui::SameLine();
  ImGui::Text("/ %.2f s", loop);

  ImGui::SameLine();
  ImGui::SetNextItemWidth(speed_width);
  float speed = static_cast<float>(s.playback.speed());
  if (value_slider_float("##speed", &speed, float(editor::Playback::kMinSpeed), float(editor::Playback::kMaxSpeed),
                         "%.2fx", ImGuiSliderFlags_Logarithmic)) {
    s.playback.set_speed(double(speed));
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Speed: times real time");
}

/// The rider the camera rides along with (or none: the orbit camera), the view, and Orbit.
void ride_row(ViewerState& s) {
  const std::vector<int> riders = riders_of(s.doc());
  int choice = riding(s) ? s.session.index_of(s.ride.rider) : -1;
  ImGui::SetNextItemWidth(150.0f * s.layout.ui_scale);
  if (curve_combo(s.doc(), "##ride", riders, choice, "orbit camera")) {
    ride_along(s, choice >= 0 ? s.session.id_of(choice) : editor::kNoObject);
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Ride along with a rider: the camera follows it");
  mark_item(s, "ride");
  ImGui::SameLine();
  int view = static_cast<int>(s.ride.view);
  ImGui::SetNextItemWidth(120.0f * s.layout.ui_scale);
  if (ImGui::Combo("##view", &view, "Chase\0First person\0")) s.ride.view = static_cast<render::RideView>(view);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Chase: behind and above it; first person: from its place");
  ImGui::SameLine();
  const bool can_leave = riding(s);
  if (!can_leave) ImGui::BeginDisabled();
  if (ImGui::Button("Orbit")) stop_riding(s);
  if (!can_leave) ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
    ImGui::SetTooltip("Back to the orbit camera (Space resets it; dragging in the view orbits from here)");
  }
  mark_item(s, "orbit");
}

}  // namespace

void timeline_panel(ViewerState& s, editor::CommandTable& commands) {
  if (s.layout.timeline_height <= 0.0f) return;
  const double loop = longest_loop(s.doc());
  if (!(loop > 0.0)) return;  // the layout is a frame behind an edit that took the riders away
  const ImGuiViewport* viewport = ImGui::GetMainViewport();
  const float margin = s.layout.margin;
  const float left = float(s.layout.free_left()) + margin;
  const float width = std::max(1.0f, viewport->WorkSize.x - left - margin);
  const float bottom = viewport->WorkPos.y + viewport->WorkSize.y - s.layout.status_height - margin;
  ImGui::SetNextWindowPos(ImVec2(viewport->WorkPos.x + left, bottom), ImGuiCond_Always, ImVec2(0.0f, 1.0f));
  ImGui::SetNextWindowSize(ImVec2(width, s.layout.timeline_height), ImGuiCond_Always);
  ImGui::SetNextWindowBgAlpha(0.88f);
  const ImGuiWindowFlags flags = ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                                 ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                                 ImGuiWindowFlags_NoNav;
  if (ImGui::Begin("##timeline", nullptr, flags)) {
    clock_row(s, commands, loop);
    ride_row(s);
  }
  ImGui::End();
}

}  // namespace sweep::viewer::panels
