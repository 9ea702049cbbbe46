// Material and light: the surface material, the lights, the background, and the lengths of
// frame axes and normals.
#include "app/viewer/panels/panels.hpp"

#include <imgui.h>

namespace sweep::viewer::panels {

void material_panel(ViewerState& s) {
  if (!ImGui::CollapsingHeader("Material and light")) return;
  render::Material& m = s.display.material;
  render::Lighting& l = s.display.lighting;
  ImGui::ColorEdit3("Colour", &m.color.x);
  ImGui::ColorEdit3("Specular", &m.specular.x);
  ImGui::SliderFloat("Shininess", &m.shininess, 1.0f, 256.0f, "%.0f", ImGuiSliderFlags_Logarithmic);
  ImGui::Checkbox("Two-sided lighting", &m.two_sided);
  ImGui::ColorEdit3("Key light", &l.key_color.x);
  ImGui::ColorEdit3("Fill light", &l.fill_color.x);
  ImGui::ColorEdit3("Ambient", &l.ambient.x);
  ImGui::ColorEdit3("Background", &s.display.background.x);
  ImGui::SliderFloat("Frame length", &s.display.frame_length, 0.005f, 0.5f, "%.3f", ImGuiSliderFlags_Logarithmic);
  ImGui::SliderFloat("Normal length", &s.display.normal_length, 0.005f, 0.5f, "%.3f", ImGuiSliderFlags_Logarithmic);
}

}  // namespace sweep::viewer::panels
