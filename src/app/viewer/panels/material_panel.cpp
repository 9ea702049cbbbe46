// Material and light: the selected surface's material (chosen from the document's materials, or
// a new one) and that material's colour, shininess, texture or checker and bump, each an
// undoable edit saved with the file; then the default look of surfaces without a material, the
// lights, the background, and the lengths of frame axes and normals.
#include "app/viewer/panels/number_field.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"
#include "app/viewer/panels/value_slider.hpp"
#include "model/material.hpp"

#include <imgui.h>

#include <cmath>
#include <string>
#include <vector>

namespace sweep::viewer::panels {
namespace {

/// The material of the selection: the selected material, or the selected surface's; -1: none.
int material_in_view(const MaterialParts& s) {
  const int index = s.selected();
  if (index < 0) return -1;
  const Object& o = s.doc().objects[std::size_t(index)];
  if (is_material(o.kind())) return index;
  return is_surface(o.kind()) ? o.as<MaterialPart>().material : -1;
}

/// The selected surface's material: the materials above it, or a new one.
void surface_choice(const MaterialParts& s, int surface) {
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
  ImGui::InputTextWithHint("##new material", "new material name", name.text.data(), name.text.size(), kTextFieldFlags);
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

/// For the last item, a field of material `index`'s look: one undoable step per drag, applying
/// the look `change` makes of the current one. The caller draws the widget in a statement of its
/// own before calling this, so `change` sees the widget's new value (in one call's arguments the
/// order would be unspecified).
template <typename ChangeLook>
void look_item(const MaterialParts& s, int index, const char* label, bool changed, const ChangeLook& change) {
  Object next = s.doc().objects[std::size_t(index)];
  change(next.as<MaterialLook>());
  const std::filesystem::path folder = image_base(s.session().file());
  s.continuous_item(changed, label,
                    [index, next, folder](Document& d) { return set_material_look(d, index, next, folder); });
}

/// A number of material `index`'s look as a number field (dragged, or typed after a double-click
/// or Ctrl+click): the edit `label` sets the look `set(look, value)` makes of the current one.
template <typename SetLook>
void look_number(const MaterialParts& s, int index, const NumberField& field, const DrawNumber& draw, const char* label,
                 const SetLook& set) {
  const std::filesystem::path folder = image_base(s.session().file());
  number_field(s, field, draw, label, [&s, index, folder, &set](double value) {
    Object next = s.doc().objects[std::size_t(index)];
    set(next.as<MaterialLook>(), value);
    return [index, next, folder](Document& d) { return set_material_look(d, index, next, folder); };
  });
}

/// The colour the widget shows, `shown`, as a material colour: a component the user left alone
/// (the same in 8 bits, which the widget edits in and writes back all three of) keeps its exact
/// value, so moving the red writes no rounding into green and blue.
glm::dvec3 edited_color(const glm::dvec3& old, const glm::vec3& shown) {
  const auto byte = [](double c) { return std::lround(c * 255.0); };
  glm::dvec3 color = old;
  for (int i = 0; i < 3; ++i) {
    if (byte(shown[i]) != byte(old[i])) color[i] = shown[i];
  }
  return color;
}

/// The colour of material `index` (`old`): a swatch that opens a picker (a drag in it is one
/// step), and its red, green and blue from 0 to 1, as the file writes them, as number fields
/// (ImGui's own colour fields apply every keystroke typed into them).
void look_colour(const MaterialParts& s, int index, const glm::dvec3& old) {
  glm::vec3 color(old);
  if (ImGui::ColorButton("##colour swatch", ImVec4(color.r, color.g, color.b, 1.0f))) ImGui::OpenPopup("colour picker");
  mark_item(s, "colour");
  if (ImGui::BeginPopup("colour picker")) {
    const bool changed =
        ImGui::ColorPicker3("##picker", &color.x, ImGuiColorEditFlags_NoInputs | ImGuiColorEditFlags_NoSidePreview);
    look_item(s, index, "set colour", changed,
              [&](MaterialLook& look) { look.color = edited_color(look.color, color); });
    ImGui::EndPopup();
  }
  static constexpr const char* kLabels[] = {"##red", "##green", "##blue"};
  static constexpr const char* kNames[] = {"red", "green", "blue"};
  const float width = (ImGui::CalcItemWidth() - ImGui::GetFrameHeight()) / 3.0f - ImGui::GetStyle().ItemInnerSpacing.x;
  for (int i = 0; i < 3; ++i) {
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::SetNextItemWidth(width);
    look_number(s, index, {kLabels[i], std::string(kNames[i]) + " of the colour", old[i], false, kNames[i]},
                float_slider(kLabels[i], 0.0f, 1.0f, "%.3f"), "set colour",
                [i](MaterialLook& look, double value) { look.color[i] = value; });
  }
  ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
  ImGui::TextUnformatted("Colour");
}

/// Colour, shininess and checker cells of material `index`.
void look_sliders(const MaterialParts& s, int index) {
  const MaterialLook old = s.doc().objects[std::size_t(index)].as<MaterialLook>();  // a copy: edits replace it
  look_colour(s, index, old.color);
  look_number(s, index, {"Shininess##material", "shininess", old.shininess, false, "shininess"},
              float_slider("Shininess##material", 1.0f, 1000.0f, "%.0f", ImGuiSliderFlags_Logarithmic), "set shininess",
              [](MaterialLook& look, double value) { look.shininess = value; });
  look_number(s, index, {"Checker cells", "checker cells", double(old.checker), true, "checker"},
              int_slider("Checker cells", 0, 32), "set checker", [](MaterialLook& look, double value) {
                look.checker = int(value);
                if (look.checker > 0) look.texture.clear();
              });
}

/// The look of material `index`, each field one undoable edit (a drag is one step).
void look_fields(const MaterialParts& s, int index) {
  look_sliders(s, index);
  const Object& m = s.doc().objects[std::size_t(index)];
  const std::filesystem::path folder = image_base(s.session().file());
  TextField& texture = s.fields.material_texture;
  TextField& bump = s.fields.material_bump;
  if (s.fields.material_for != m.id) {
    texture.set(m.as<MaterialLook>().texture);
    bump.set(m.as<MaterialLook>().bump);
    s.fields.material_for = m.id;
  }
  if (ImGui::InputTextWithHint("Texture", "image.png (Enter)", texture.text.data(), texture.text.size(),
                               ImGuiInputTextFlags_EnterReturnsTrue | kTextFieldFlags)) {
    Object next = m;
    next.as<MaterialLook>().texture = texture.get();
    if (!next.as<MaterialLook>().texture.empty()) next.as<MaterialLook>().checker = 0;
    run_edit(s, "set texture",
             [index, next, folder](Document& d) { return set_material_look(d, index, next, folder); });
  }
  if (ImGui::InputTextWithHint("Bump", "height.png (Enter)", bump.text.data(), bump.text.size(),
                               ImGuiInputTextFlags_EnterReturnsTrue | kTextFieldFlags)) {
    Object next = m;
    next.as<MaterialLook>().bump = bump.get();
    if (next.as<MaterialLook>().bump_height == 0.0 && !next.as<MaterialLook>().bump.empty())
      next.as<MaterialLook>().bump_height = 0.01;
    run_edit(s, "set bump", [index, next, folder](Document& d) { return set_material_look(d, index, next, folder); });
  }
  const double height = s.doc().objects[std::size_t(index)].as<MaterialLook>().bump_height;  // after the edits above
  look_number(s, index, {"Bump height", "bump height", height, false, "bump height"},
              float_slider("Bump height", 0.0f, 1.0f, "%.4f", ImGuiSliderFlags_Logarithmic), "set bump height",
              [](MaterialLook& look, double value) { look.bump_height = value; });
  ImGui::TextDisabled("images are paths relative to the SWP file");
}

void default_look(const MaterialParts& s) {
  render::Material& m = s.display.material;
  render::Lighting& l = s.display.lighting;
  ImGui::TextDisabled("surfaces without a material, and the lights (not saved):");
  ImGui::ColorEdit3("Colour", &m.color.x);
  ImGui::ColorEdit3("Specular", &m.specular.x);
  value_slider_float("Shininess", &m.shininess, 1.0f, 256.0f, "%.0f", ImGuiSliderFlags_Logarithmic);
  ImGui::Checkbox("Two-sided lighting", &m.two_sided);
  ImGui::ColorEdit3("Key light", &l.key_color.x);
  ImGui::ColorEdit3("Fill light", &l.fill_color.x);
  ImGui::ColorEdit3("Ambient", &l.ambient.x);
  ImGui::ColorEdit3("Background", &s.display.background.x);
  value_slider_float("Frame length", &s.display.frame_length, 0.005f, 0.5f, "%.3f", ImGuiSliderFlags_Logarithmic);
  value_slider_float("Normal length", &s.display.normal_length, 0.005f, 0.5f, "%.3f", ImGuiSliderFlags_Logarithmic);
}

}  // namespace

void material_panel(const MaterialParts& s) {
  const bool open = ImGui::CollapsingHeader("Material and light");
  mark_item(s, "material panel");  // where scripted tests open it
  if (!open) return;
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
