// Save PNG of the view...: asks for the file name, the size (the view's own by default, 1920 x
// 1080 and the sizes of `sweep render`, the viewer and `sweep snapshot` offered) and whether the
// control points, the curves and the ground grid are in it, as `sweep render`'s options do.
#include "app/viewer/actions.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>
#include <glm/common.hpp>

#include <cstddef>
#include <string>

namespace sweep::viewer::panels {
namespace {

constexpr const char* kTitle = "Save PNG of the view";

/// "the view's size (1056 x 752)" for the first choice, the label itself for the others.
std::string size_label(const ViewerState& s, std::size_t choice) {
  const PngSize& size = png_sizes()[choice];
  if (size.pixels.x > 0) return size.label;
  const glm::dvec2 pixels = s.layout.window * double(s.layout.pixel_ratio);
  const PixelRect view = view_rect(s.layout, glm::max(glm::ivec2(glm::round(pixels)), glm::ivec2(1)));
  return std::string(size.label) + " (" + std::to_string(view.width) + " x " + std::to_string(view.height) + ")";
}

void size_combo(ViewerState& s) {
  int& choice = s.png_dialog.size_choice;
  ImGui::SetNextItemWidth(320.0f * ImGui::GetIO().FontGlobalScale);
  if (ImGui::BeginCombo("Size", size_label(s, static_cast<std::size_t>(choice)).c_str())) {
    for (std::size_t i = 0; i < png_sizes().size(); ++i) {
      if (ImGui::Selectable(size_label(s, i).c_str(), static_cast<int>(i) == choice)) choice = static_cast<int>(i);
      mark_item(s, "png-size-" + std::to_string(i));
    }
    ImGui::EndCombo();
  }
  mark_item(s, "png-size");
}

void ask_png(ViewerState& s) {
  ImGui::TextDisabled("NAME.png in %s (an absolute path is used as it is)", output_folder(s).string().c_str());
  ImGui::SetNextItemWidth(320.0f * ImGui::GetIO().FontGlobalScale);
  const bool enter = ImGui::InputText("Name", s.fields.screenshot.text.data(), s.fields.screenshot.text.size(),
                                      ImGuiInputTextFlags_EnterReturnsTrue | kTextFieldFlags);
  mark_item(s, "png-dialog-name");
  size_combo(s);
  PngDialog& answers = s.png_dialog;
  ImGui::Checkbox("Control points", &answers.control_points);
  mark_item(s, "png-points");
  ImGui::SameLine();
  ImGui::Checkbox("Curves", &answers.curves);
  mark_item(s, "png-curves");
  ImGui::SameLine();
  ImGui::Checkbox("Ground grid", &answers.grid);
  mark_item(s, "png-grid");
  ImGui::TextDisabled("Drawn again without the selection or the panels.");
  const bool save = ImGui::Button("Save");
  mark_item(s, "png-save");
  if (save || enter) request_view_png(s, s.fields.screenshot.get());
  ImGui::SameLine();
  const bool escape = !ImGui::IsWindowAppearing() && ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape));
  if (ImGui::Button("Cancel") || escape) answers.open = false;
  if (!answers.open) ImGui::CloseCurrentPopup();
}

}  // namespace

void png_dialog(ViewerState& s) {
  if (s.png_dialog.open && !ImGui::IsPopupOpen(kTitle)) ImGui::OpenPopup(kTitle);
  ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
  if (!ImGui::BeginPopupModal(kTitle, nullptr, ImGuiWindowFlags_AlwaysAutoResize)) return;
  ask_png(s);
  ImGui::EndPopup();
}

}  // namespace sweep::viewer::panels
