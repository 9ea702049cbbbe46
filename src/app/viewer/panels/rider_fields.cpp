// The selected rider in the Edit panel: its path and model (named objects above it), seconds a
// loop, start (a phase) and whether it keeps upright about an up vector. Every change is one
// undoable edit through set_rider; the core's message shows when it refuses one.
#include "app/viewer/panels/number_field.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"
#include "model/edit/edit.hpp"

#include <imgui.h>

#include <functional>
#include <string>
#include <vector>

namespace sweep::viewer::panels {
namespace {

/// Named objects before `rider` that `wanted` accepts.
std::vector<int> candidates(const Document& doc, int rider, bool (*wanted)(ObjectKind)) {
  std::vector<int> out;
  for (int i = 0; i < rider; ++i) {
    const Object& o = doc.objects[std::size_t(i)];
    if (wanted(o.kind()) && !o.name.empty()) out.push_back(i);
  }
  return out;
}

/// Applies `change` to a copy of the rider's data as the edit `label`.
void edit_rider(const EditContext& s, int index, const std::string& label,
                const std::function<void(RiderObject&)>& change) {
  RiderObject value = s.doc().objects[std::size_t(index)].as<RiderObject>();
  change(value);
  run_edit(s, label, [index, value](Document& d) { return set_rider(d, index, value); });
}

/// A number of the rider that set_rider checks (seconds, start).
void rider_number(const EditContext& s, int index, const char* label, double RiderObject::*member, float low,
                  float high) {
  const RiderObject& r = s.doc().objects[std::size_t(index)].as<RiderObject>();
  number_field(s, {label, label, r.*member, false, label}, float_slider(label, low, high, "%.3g"),
               std::string("set ") + label, [index, member, r](double v) {
                 RiderObject value = r;
                 value.*member = v;
                 return [index, value](Document& d) { return set_rider(d, index, value); };
               });
}

void upright_controls(const EditContext& s, int index) {
  const RiderObject& r = s.doc().objects[std::size_t(index)].as<RiderObject>();
  bool upright = r.up != glm::dvec3(0.0);
  if (ImGui::Checkbox("keep upright", &upright)) {
    edit_rider(s, index, upright ? "keep upright" : "follow the path's frames",
               [upright](RiderObject& v) { v.up = upright ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(0.0); });
  }
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("B as close to the up vector as the tangent allows (cars, trains)");
  if (!upright) return;
  double up[3] = {r.up.x, r.up.y, r.up.z};
  if (ImGui::InputScalarN("up", ImGuiDataType_Double, up, 3, nullptr, nullptr, "%.3g",
                          ImGuiInputTextFlags_EnterReturnsTrue)) {
    edit_rider(s, index, "set up", [&up](RiderObject& v) { v.up = {up[0], up[1], up[2]}; });
  }
}

}  // namespace

void rider_fields(const EditContext& s, int index) {
  const RiderObject& r = s.doc().objects[std::size_t(index)].as<RiderObject>();
  int path = r.path;
  if (curve_combo(s.doc(), "path", candidates(s.doc(), index, is_curve), path)) {
    edit_rider(s, index, "set path", [path](RiderObject& v) { v.path = path; });
  }
  int model = r.model;
  if (curve_combo(s.doc(), "model", candidates(s.doc(), index, is_surface), model)) {
    edit_rider(s, index, "set model", [model](RiderObject& v) { v.model = model; });
  }
  rider_number(s, index, "seconds", &RiderObject::seconds, 0.5f, 60.0f);
  rider_number(s, index, "start", &RiderObject::start, 0.0f, 0.999f);
  upright_controls(s, index);
}

}  // namespace sweep::viewer::panels
