// Create: curves from templates, and surfaces of revolution, generalized cylinders or birail
// surfaces from existing curves; riders (a surface carried along a curve) under a node of their
// own, closed until opened. Open from the start, near the top of the main panel. Each addition is
// said in the status bar, where the eye is ("added bsp2 'curve'"). A new curve is sized to the
// scene and put beside it (place_new_curve), a new tube's profile made small enough for its
// sweep's bends, and the view framed on what was added.
#include "app/viewer/panels/number_field.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"
#include "base/number_text.hpp"
#include "editor/overlay_builder.hpp"
#include "model/edit/edit.hpp"
#include "model/file_limits.hpp"
#include "render/camera.hpp"

#include <imgui.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <string>
#include <string_view>
#include <vector>

namespace sweep::viewer::panels {
namespace {

/// Runs an edit that appends an object and selects it; says so in the status bar ("added KEYWORD
/// 'NAME'" and `how`). Returns the new object's index, or -1 when the edit was refused (the
/// error says why).
int add_and_select(const CreateParts& s, const std::string& label, const std::function<int(Document&)>& add,
                   TextField& name_field, const std::string& how = {}) {
  int added = -1;
  if (!run_edit(s, label, [&add, &added](Document& d) {
        added = add(d);
        return Change{{added}, true};
      })) {
    return -1;
  }
  s.selection().select(s.session().id_of(added));
  name_field.set("");
  const Object& object = s.doc().objects[std::size_t(added)];
  s.status() = "added " + std::string(keyword(object.kind())) + " '" + display_name(s.doc(), added) + "'" + how;
  return added;
}

/// What a new curve is placed beside: the box of what the view shows, on its ground grid.
SceneBox visible_scene(const CreateParts& s) {
  const render::Bounds bounds = render::scene_bounds(s.session().scene(), s.views().visibility(s.doc()));
  const editor::GroundGrid ground{bounds.min, bounds.max};
  return {bounds.min, bounds.max, editor::ground_height(ground), editor::ground_step(ground)};
}

/// "'NAME'" of the object at `index`.
std::string quoted_name(const Document& doc, int index) {
  std::string text = display_name(doc, index);
  text.insert(text.begin(), '\'');  // not "'" + name: GCC 12 warns (-Wrestrict) about its inlined copy
  text.push_back('\'');
  return text;
}

void curve_controls(const CreateParts& s) {
  CreateFields& f = s.fields;
  const int count = int(curve_templates().size());
  std::vector<std::string_view> labels;
  for (const CurveTemplateInfo& row : curve_templates()) labels.push_back(row.label);
  marked_combo(s.item_positions(), "curve", labels, f.template_choice, "template");
  ImGui::SetNextItemWidth(-120.0f);
  ImGui::InputTextWithHint("##curve_name", "name (empty: automatic)", f.curve_name.text.data(),
                           f.curve_name.text.size(), kTextFieldFlags);
  ImGui::SameLine();
  const bool add = ImGui::Button("Add curve");
  mark_item(s, "add-curve");  // the panel's first button: scripted tests check it shows, and click it
  if (!add) return;
  const CurveTemplateInfo& chosen = curve_templates()[std::size_t(std::clamp(f.template_choice, 0, count - 1))];
  const std::string_view shape = chosen.label;
  std::string name = f.curve_name.get();
  if (name.empty()) name = unique_name(s.doc(), chosen.base_name);
  const SceneBox scene = visible_scene(s);
  std::string placed;
  const int added = add_and_select(
      s, "add curve " + name,
      [shape, name, scene, &placed](Document& d) { return add_curve(d, shape, name, scene, placed); }, f.curve_name);
  if (added >= 0) {
    s.status() += placed + (has_editable_points(s.doc().objects[std::size_t(added)].kind())
                                ? ": drag its points in the view"
                                : ": its numbers are in the Edit panel");
    f.frame_added = true;
  }
  // The next surface is most likely made from it: a 2D curve as its profile, a 3D one as its sweep.
  if (added >= 0)
    (is_planar_curve(s.doc().objects[std::size_t(added)].kind()) ? f.profile_choice : f.sweep_choice) = added;
}

/// The kinds the surface combo offers, in its order.
constexpr ObjectKind kSurfaceKinds[] = {ObjectKind::SurfaceOfRevolution, ObjectKind::GeneralizedCylinder,
                                        ObjectKind::Birail};

/// How many copies of the profile a new surface of revolution has (its STEPS): dragged, or typed
/// after a double-click or Ctrl+click.
void copies_field(const CreateParts& s) {
  const auto draw = [](double& value) {
    int copies = int(value);
    const int low = 1;
    const int high = static_cast<int>(limits::kMaxSteps);
    if (!ImGui::DragScalar("copies (STEPS)", ImGuiDataType_S32, &copies, 0.2f, &low, &high, "%d",
                           ImGuiSliderFlags_AlwaysClamp | ImGuiSliderFlags_NoInput)) {
      return false;
    }
    value = double(copies);
    return true;
  };
  setting_field(s, {"copies (STEPS)", "copies", double(s.fields.surface_steps), true, "copies"}, draw,
                [&s](double copies) {
                  if (copies < 1.0 || copies > double(limits::kMaxSteps)) {
                    return "STEPS must be from 1 to " + std::to_string(limits::kMaxSteps) + ", not " +
                           std::to_string(int(copies));
                  }
                  s.fields.surface_steps = int(copies);
                  return std::string();
                });
}

void surface_controls(const CreateParts& s) {
  CreateFields& f = s.fields;
  marked_combo(s.item_positions(), "surface", {"surface of revolution", "generalized cylinder", "birail surface"},
               f.surface_choice, "surface-kind");
  const ObjectKind kind = kSurfaceKinds[f.surface_choice];
  // Curves to choose from: planar ones for the profile, any for the sweep and the rails.
  std::vector<int> planar_curves;
  std::vector<int> curves;
  for (std::size_t i = 0; i < s.doc().objects.size(); ++i) {
    if (is_planar_curve(s.doc().objects[i].kind())) planar_curves.push_back(int(i));
    if (is_curve(s.doc().objects[i].kind())) curves.push_back(int(i));
  }
  curve_combo(s.doc(), "profile", planar_curves, f.profile_choice);
  if (kind == ObjectKind::GeneralizedCylinder) curve_combo(s.doc(), "sweep", curves, f.sweep_choice);
  if (kind == ObjectKind::Birail) {
    curve_combo(s.doc(), "first rail", curves, f.sweep_choice);
    curve_combo(s.doc(), "second rail", curves, f.rail2_choice);
  }
  if (kind == ObjectKind::SurfaceOfRevolution) copies_field(s);
  ImGui::SetNextItemWidth(-120.0f);
  ImGui::InputTextWithHint("##surface_name", "name (empty: automatic)", f.surface_name.text.data(),
                           f.surface_name.text.size(), kTextFieldFlags);
  ImGui::SameLine();
  const bool add = ImGui::Button("Add surface");
  mark_item(s, "add-surface");
  if (!add) return;
  std::string name = f.surface_name.get();
  if (name.empty()) {
    name = unique_name(s.doc(), kind == ObjectKind::Birail                ? "birail"
                                : kind == ObjectKind::GeneralizedCylinder ? "cylinder"
                                                                          : "revolution");
  }
  const int profile = f.profile_choice;
  const int sweep = kind == ObjectKind::SurfaceOfRevolution ? -1 : f.sweep_choice;
  const int rail2 = kind == ObjectKind::Birail ? f.rail2_choice : -1;
  const int steps = f.surface_steps;
  if (profile < 0 || (kind != ObjectKind::SurfaceOfRevolution && sweep < 0) ||
      (kind == ObjectKind::Birail && rail2 < 0)) {
    s.error() = kind == ObjectKind::Birail                ? "choose a 2D profile curve and two rail curves first"
                : kind == ObjectKind::GeneralizedCylinder ? "choose a 2D profile curve and a sweep curve first"
                                                          : "choose a 2D profile curve first";
    return;
  }
  const Document& doc = s.doc();
  const std::string how = kind == ObjectKind::Birail ? " from " + quoted_name(doc, profile) + " along " +
                                                           quoted_name(doc, sweep) + " and " + quoted_name(doc, rail2)
                          : kind == ObjectKind::GeneralizedCylinder
                              ? " from " + quoted_name(doc, profile) + " along " + quoted_name(doc, sweep)
                              : " turning " + quoted_name(doc, profile) + " in " + std::to_string(steps) + " steps";
  // A tube that would fold over itself where its sweep bends most gets a smaller profile, when
  // nothing else uses the profile; a shared one is left as it is, and the status says so.
  const double fit = kind == ObjectKind::GeneralizedCylinder ? profile_fit_factor(doc, profile, sweep) : 1.0;
  const bool shrink = fit < 1.0 && !is_referenced(doc, profile);
  const std::string fitted =
      fit == 1.0 ? std::string()
      : shrink   ? " (" + quoted_name(doc, profile) + " scaled by " + number_text(fit) + " to fit the sweep's bends)"
                 : ": the profile is too wide for the sweep's tightest bend, the tube folds there (shrink " +
                     quoted_name(doc, profile) + " by " + number_text(fit) + ")";
  if (add_and_select(
          s, "add surface " + name,
          [kind, name, profile, sweep, steps, rail2, shrink, fit](Document& d) {
            if (shrink) scale_curve(d.objects[std::size_t(profile)], fit);
            return add_surface(d, kind, name, profile, sweep, steps, rail2);
          },
          f.surface_name, how + fitted) >= 0) {
    f.frame_added = true;
  }
}

/// A rider: a surface carried along a curve (its clauses are set in the Edit panel).
void rider_controls(const CreateParts& s) {
  CreateFields& f = s.fields;
  std::vector<int> curves;
  std::vector<int> surfaces;
  for (std::size_t i = 0; i < s.doc().objects.size(); ++i) {
    if (is_curve(s.doc().objects[i].kind())) curves.push_back(int(i));
    if (is_surface(s.doc().objects[i].kind())) surfaces.push_back(int(i));
  }
  curve_combo(s.doc(), "path", curves, f.rider_path_choice);
  curve_combo(s.doc(), "model", surfaces, f.rider_model_choice);
  ImGui::SetNextItemWidth(-120.0f);
  ImGui::InputTextWithHint("##rider_name", "name (empty: automatic)", f.rider_name.text.data(),
                           f.rider_name.text.size(), kTextFieldFlags);
  ImGui::SameLine();
  const bool add = ImGui::Button("Add rider");
  mark_item(s, "add-rider");
  if (!add) return;
  if (f.rider_path_choice < 0 || f.rider_model_choice < 0) {
    s.error() = "choose a path curve and a model surface first";
    return;
  }
  std::string name = f.rider_name.get();
  if (name.empty()) name = unique_name(s.doc(), "rider");
  const int path = f.rider_path_choice;
  const int model = f.rider_model_choice;
  const std::string how = ": " + quoted_name(s.doc(), model) + " along " + quoted_name(s.doc(), path);
  if (add_and_select(
          s, "add rider " + name, [name, path, model](Document& d) { return add_rider(d, name, path, model); },
          f.rider_name, how) >= 0) {
    f.frame_added = true;
  }
}

}  // namespace

void create_panel(const CreateParts& s) {
  if (!ImGui::CollapsingHeader("Create", ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::PushID("create");
  curve_controls(s);
  ImGui::Separator();
  surface_controls(s);
  if (ImGui::TreeNode("Rider (a surface carried along a curve)")) {
    rider_controls(s);
    ImGui::TreePop();
  }
  ImGui::PopID();
}

}  // namespace sweep::viewer::panels
