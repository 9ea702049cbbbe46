// Objects: the outliner, curves, surfaces then materials, with visibility per object (kept by
// object id) and selection.
#include "app/viewer/panels/panels.hpp"
#include "model/diagnostics_text.hpp"

#include <imgui.h>

namespace sweep::viewer::panels {
namespace {

void object_row(const ObjectsParts& s, std::size_t i) {
  const Document& doc = s.doc();
  const Object& object = doc.objects[i];
  ImGui::PushID(static_cast<int>(object.id));
  bool visible = s.views.visible(object.id);
  if (ImGui::Checkbox("##visible", &visible)) s.views.set_visible(object.id, visible);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("Show or hide");
  ImGui::SameLine();
  const std::string label = display_name(doc, static_cast<int>(i)) + "  (" + std::string(keyword(object.kind())) + ")";
  if (ImGui::Selectable(label.c_str(), s.selection.object == object.id)) s.selection.select(object.id);
  if (object.kind() == ObjectKind::GeneralizedCylinder || object.kind() == ObjectKind::Birail ||
      (object.kind() == ObjectKind::SurfaceOfRevolution && object.as<CapsPart>().caps)) {
    ImGui::Indent();
    // Wrapped, not cut off at the panel's edge: "profile star, sweep ring, twist 360 deg, material gold".
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    ImGui::TextWrapped("%s", editor::surface_sources_text(doc, static_cast<int>(i)).c_str());
    ImGui::PopStyleColor();
    ImGui::Unindent();
  }
  ImGui::PopID();
}

}  // namespace

void objects_panel(const ObjectsParts& s) {
  if (!ImGui::CollapsingHeader("Objects", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const Document& doc = s.doc();
  if (doc.objects.empty()) ImGui::TextDisabled("(empty scene)");
  // By family, in the order of KindFamily: curves, surfaces, materials, riders.
  const auto group = [](ObjectKind kind) { return static_cast<int>(kind_info(kind).family); };
  static constexpr const char* kTitles[] = {"Curves", "Surfaces", "Materials", "Riders"};
  for (int g : {0, 1, 2, 3}) {
    bool any = false;
    for (const Object& o : doc.objects) any |= group(o.kind()) == g;
    const char* title = kTitles[g];
    if (!any || !ImGui::TreeNodeEx(title, ImGuiTreeNodeFlags_DefaultOpen)) continue;
    // Rows only select and hide: no edit inside the loop shifts them.
    for (std::size_t i = 0; i < doc.objects.size(); ++i) {
      if (group(doc.objects[i].kind()) == g) object_row(s, i);
    }
    ImGui::TreePop();
  }
}

}  // namespace sweep::viewer::panels
