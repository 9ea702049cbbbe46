// Material and light: the selected surface's material (chosen from the document's materials, or
// a new one) and that material's colour, shininess, texture or checker and bump, each an
// undoable edit saved with the file; then the default look of surfaces without a material, the
// lights, the background, and the lengths of frame axes and normals.
#include "app/viewer/actions.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"
#include "model/material.hpp"

#include <imgui.h>

#include <string>
#include <vector>

namespace sweep::viewer::panels {
namespace {

/// The material of the selection: the selected material, or the selected surface's; -1: none.
int material_in_view(const ViewerState& s) {
  const int index = s.selected();
  if (index < 0) return -1;
  const Object& o = s.doc().objects[std::size_t(index)];
  if (is_material(o.kind())) return index;
  return is_surface(o.kind()) ? o.as<MaterialPart>().material : -1;
}

/// The selected surface's material: the materials above it, or a new one.
void surface_choice(ViewerState& s, int surface) {
  const Object& o = s.doc().objects[std::size_t(surface)];
  std::vector<int> materials;
  for (int i = 0; i < surface; ++i) {
    if (is_material(s.doc().objects[std::size_t(i)].kind())) materials.push_back(i);
  }
  const std::string current = o.as<MaterialPart>().material >= 0 ? display_name(s.doc(), o.as<MaterialPart>().material)
                                                                 : std::string("(default look)");
  if (ImGui::BeginCombo("Material", current.c_str())) {
    if (ImGui::Selectable("(default look)", o.as<MaterialPart>().material < 0)) {
      run_edit(s, "set material", [surface](Document& d) { return set_surface_material(d, surface, -1); });
    }
    for (int m : materials) {
      if (ImGui::Selectable(display_name(s.doc(), m).c_str(), m == o.as<MaterialPart>().material)) {
        run_edit(s, "set material", [surface, m](Document& d) { return set_surface_material(d, surface, m); });
      }
    }
    ImGui::EndCombo();
  }
  TextField& name = s.fields.material_name;
  ImGui::SetNextItemWidth(-110.0f);
  ImGui::InputTextWithHint("##new material", "new material name", name.text.data(), name.text.size());
  ImGui::SameLine();
  if (ImGui::Button("New material") && !name.get().empty()) {
    const std::string text = name.get();
    // The material goes first in the file, so the surface (one further down now) can use it.
    if (run_edit(s, "new material", [surface, text](Document& d) {
          const int m = add_material(d, text);
          Change change = set_surface_material(d, surface + 1, m);
          change.structure = true;
          return change;
        })) {
      name.set("");
    }
  }
}

/// The look of material `index`, each field one undoable edit (a drag is one step).
void look_fields(ViewerState& s, int index) {
  const Object& m = s.doc().objects[std::size_t(index)];
  const std::filesystem::path folder = image_base(s.session.file());
  Object look = m;
  const auto edit = [&s, index, folder](const char* label, bool changed, const Object& next) {
    continuous_item(s, changed, label,
                    [index, next, folder](Document& d) { return set_material_look(d, index, next, folder); });
  };
  glm::vec3 color(m.as<MaterialLook>().color);
  edit("set colour", ImGui::ColorEdit3("Colour##material", &color.x), [&] {
    look.as<MaterialLook>().color = glm::dvec3(color);
    return look;
  }());
  look = m;
  float shininess = static_cast<float>(m.as<MaterialLook>().shininess);
  edit("set shininess",
       ImGui::SliderFloat("Shininess##material", &shininess, 1.0f, 1000.0f, "%.0f", ImGuiSliderFlags_Logarithmic), [&] {
         look.as<MaterialLook>().shininess = shininess;
         return look;
       }());
  look = m;
  int checker = m.as<MaterialLook>().checker;
  edit("set checker", ImGui::SliderInt("Checker cells", &checker, 0, 32), [&] {
    look.as<MaterialLook>().checker = checker;
    if (checker > 0) look.as<MaterialLook>().texture.clear();
    return look;
  }());
  TextField& texture = s.fields.material_texture;
  TextField& bump = s.fields.material_bump;
  if (s.fields.material_for != m.id) {
    texture.set(m.as<MaterialLook>().texture);
    bump.set(m.as<MaterialLook>().bump);
    s.fields.material_for = m.id;
  }
  if (ImGui::InputTextWithHint("Texture", "image.png (Enter)", texture.text.data(), texture.text.size(),
                               ImGuiInputTextFlags_EnterReturnsTrue)) {
    Object next = m;
    next.as<MaterialLook>().texture = texture.get();
    if (!next.as<MaterialLook>().texture.empty()) next.as<MaterialLook>().checker = 0;
    run_edit(s, "set texture",
             [index, next, folder](Document& d) { return set_material_look(d, index, next, folder); });
  }
  if (ImGui::InputTextWithHint("Bump", "height.png (Enter)", bump.text.data(), bump.text.size(),
                               ImGuiInputTextFlags_EnterReturnsTrue)) {
    Object next = m;
    next.as<MaterialLook>().bump = bump.get();
    if (next.as<MaterialLook>().bump_height == 0.0 && !next.as<MaterialLook>().bump.empty())
      next.as<MaterialLook>().bump_height = 0.01;
    run_edit(s, "set bump", [index, next, folder](Document& d) { return set_material_look(d, index, next, folder); });
  }
  look = m;
  float height = static_cast<float>(m.as<MaterialLook>().bump_height);
  edit("set bump height", ImGui::SliderFloat("Bump height", &height, 0.0f, 1.0f, "%.4f", ImGuiSliderFlags_Logarithmic),
       [&] {
         look.as<MaterialLook>().bump_height = height;
         return look;
       }());
  ImGui::TextDisabled("images are paths relative to the SWP file");
}

void default_look(ViewerState& s) {
  render::Material& m = s.display.material;
  render::Lighting& l = s.display.lighting;
  ImGui::TextDisabled("surfaces without a material, and the lights (not saved):");
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

}  // namespace

void material_panel(ViewerState& s) {
  if (!ImGui::CollapsingHeader("Material and light")) return;
  ImGui::PushID("material");
  const int selected = s.selected();
  if (selected >= 0 && is_surface(s.doc().objects[std::size_t(selected)].kind())) surface_choice(s, selected);
  const int material = material_in_view(s);
  if (material >= 0) {
    ImGui::Separator();
    ImGui::Text("material %s", display_name(s.doc(), material).c_str());
    look_fields(s, material);
  } else if (selected < 0) {
    ImGui::TextDisabled("select a surface to give it a material");
  }
  ImGui::Separator();
  default_look(s);
  ImGui::PopID();
}

}  // namespace sweep::viewer::panels
