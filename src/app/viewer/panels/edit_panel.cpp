// Edit: undo and redo, adaptive sampling, then the selected object's name (rename, delete),
// STEPS, a circle's radius and, for control-point curves, the point table; for surfaces their
// clauses (surface_fields.cpp).
#include "app/viewer/panels/number_field.hpp"
#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/panels.hpp"
#include "app/viewer/panels/value_slider.hpp"
#include "editor/adaptive_stats.hpp"
#include "geometry/curves/adaptive.hpp"
#include "model/edit/edit.hpp"
#include "model/evaluation/curve_evaluation.hpp"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string_view>

namespace sweep::viewer::panels {
namespace {

using editor::CommandId;

void undo_buttons(const EditParts& s, editor::CommandTable& commands) {
  command_button(commands, CommandId::Undo, "Undo");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("%s: %s", commands.all_shortcuts_label(CommandId::Undo).c_str(),
                      s.session().can_undo() ? s.session().undo_label().c_str() : "nothing to undo");
  ImGui::SameLine();
  command_button(commands, CommandId::Redo, "Redo");
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("%s: %s", commands.all_shortcuts_label(CommandId::Redo).c_str(),
                      s.session().can_redo() ? s.session().redo_label().c_str() : "nothing to redo");
}

/// Rename (Enter or the button commits) and Delete. Returns false when the object was deleted.
bool name_row(const EditParts& s, int index) {
  const Object& object = s.doc().objects[std::size_t(index)];
  TextField& field = s.fields.rename;
  if (s.fields.rename_for != object.id) {
    field.set(object.name);
    s.fields.rename_for = object.id;
  }
  ImGui::SetNextItemWidth(-130.0f);
  bool rename = ImGui::InputTextWithHint("##name", "(anonymous)", field.text.data(), field.text.size(),
                                         ImGuiInputTextFlags_EnterReturnsTrue | kTextFieldFlags) &&
                field.get() != object.name;
  ImGui::SameLine();
  rename |= ImGui::Button("Rename");
  if (rename) {
    const std::string name = field.get();
    run_edit(s, "rename", [index, name](Document& d) { return rename_object(d, index, name); });
    s.fields.rename_for = editor::kNoObject;
  }
  ImGui::SameLine();
  if (!ImGui::Button("Delete")) return true;
  const std::string label = "delete " + display_name(s.doc(), index);
  if (!run_edit(s, label, [index](Document& d) { return delete_object(d, index); })) return true;
  s.selection().clear();  // its view state stays with its id, for undo
  return false;
}

/// STEPS as an undoable slider (one step per drag or typed value).
void steps_slider(const EditParts& s, int index) {
  const int current = *steps_field(s.doc().objects[std::size_t(index)]);
  // Logarithmic so both 5 and 500 are reachable; a double-click or Ctrl+click types any value.
  const NumberField field{"STEPS", "STEPS", double(current), true, "STEPS"};
  number_field(s, field, int_slider("STEPS", 1, std::max(1000, current), ImGuiSliderFlags_Logarithmic), "set STEPS",
               [index](double steps) {
                 return [index, steps](Document& d) { return set_steps_or_levels(d, index, int(steps)); };
               });
}

/// Drag speed for a parameter: a small share of its size (P and Q step by one).
float drag_speed(CurveParameter parameter, double value) {
  switch (parameter) {
    case CurveParameter::KnotP:
    case CurveParameter::KnotQ:
      return 0.05f;
    case CurveParameter::Alpha:
    case CurveParameter::Tension:
    case CurveParameter::Continuity:
    case CurveParameter::Bias:
      return 0.005f;
    case CurveParameter::Tolerance:
      return float(std::max(1e-5, 0.02 * std::abs(value)));
    case CurveParameter::AtX:
    case CurveParameter::AtY:
    case CurveParameter::AtZ:
      return float(std::max(0.01, 0.005 * std::abs(value)));
    case CurveParameter::Radius:
    case CurveParameter::Pitch:
    case CurveParameter::Turns:
    case CurveParameter::MajorRadius:
      break;
  }
  return float(std::max(1e-3, 0.005 * std::abs(value)));
}

/// The kind's numbers besides points and STEPS (radius; cr/kb clauses; pitch, turns; P, Q, R;
/// the curve's own tolerance, 0 for by STEPS), each an undoable number field (dragged, or typed
/// after a double-click or Ctrl+click); a value out of range is refused with the reader's message.
void parameter_fields(const EditParts& s, int index) {
  const ObjectKind kind = s.doc().objects[std::size_t(index)].kind();
  for (const CurveParameter parameter : parameters_in_file_order(kind)) {
    const Object& object = s.doc().objects[std::size_t(index)];
    const double current = parameter_value(object, parameter);
    const bool whole = parameter == CurveParameter::KnotP || parameter == CurveParameter::KnotQ;
    const bool tube_radius = parameter == CurveParameter::Radius && object.kind() == ObjectKind::TorusKnot;
    const std::string label = tube_radius ? "r" : std::string(parameter_name(parameter));  // as in "knot ... P Q R r"
    const auto draw = [&label, whole, speed = drag_speed(parameter, current)](double& value) {
      const bool moved =
          ImGui::DragScalar(label.c_str(), ImGuiDataType_Double, &value, speed, nullptr, nullptr,
                            whole ? "%.0f" : "%.6g", ImGuiSliderFlags_NoRoundToFormat | ImGuiSliderFlags_NoInput);
      if (whole) value = std::round(value);
      return moved;
    };
    number_field(s, {label.c_str(), label, current, false, {}}, draw, "set " + label, [index, parameter](double value) {
      return [index, parameter, value](Document& d) { return set_curve_parameter(d, index, parameter, value); };
    });
  }
}

/// The tolerance slider on a log scale of our own (editor::tolerance_at): the slider moves a
/// position in [0, 1] and shows the tolerance it stands for, in `value`. The text has no '%', so
/// ImGui shows it as it is.
DrawNumber tolerance_slider(const editor::ToleranceRange& range) {
  return [range](double& value) {
    double position = editor::slider_position(range, value);
    const double start = 0.0;
    const double end = 1.0;
    const std::string shown = editor::tolerance_text(value);
    if (!value_slider("tolerance", ImGuiDataType_Double, &position, &start, &end, shown.c_str(),
                      ImGuiSliderFlags_NoInput | ImGuiSliderFlags_AlwaysClamp)) {
      return false;
    }
    value = editor::tolerance_at(range, position);
    return true;
  };
}

/// A tolerance dragged or typed, if it lies in `range`: "" or why not.
std::string check_tolerance_in(const editor::ToleranceRange& range, double tolerance) {
  if (tolerance >= range.low && tolerance <= range.high) return {};
  return "the tolerance must be from " + editor::tolerance_text(range.low) + " to " +
         editor::tolerance_text(range.high) + " (model units), found " + editor::tolerance_text(tolerance);
}

/// The Adaptive toggle and its tolerance (log scale, model units), beside the STEPS sliders:
/// on, every curve and surface is sampled within the tolerance instead of by STEPS, re-meshed
/// live while the slider moves (set_evaluation, only when the value changes). A viewer
/// setting, not saved into the file.
void sampling_controls(const EditParts& s) {
  EvaluationOptions evaluation = s.session().evaluation();
  const double extent = document_extent(s.doc());
  editor::ToleranceRange range = editor::tolerance_range(extent);
  if (range.high <= 0.0) return;  // nothing to sample
  bool adaptive = evaluation.tolerance > 0.0;
  if (adaptive) {  // e.g. `sweep view --tolerance D` beyond the slider's usual range: keep D
    range.low = std::min(range.low, evaluation.tolerance);
    range.high = std::max(range.high, evaluation.tolerance);
  } else if (!(s.adaptive_tolerance >= range.low && s.adaptive_tolerance <= range.high)) {
    s.adaptive_tolerance = editor::default_tolerance(extent);  // not chosen yet, or another scene
  }
  double tolerance = adaptive ? evaluation.tolerance : s.adaptive_tolerance;
  bool changed = ImGui::Checkbox("Adaptive", &adaptive);
  mark_item(s, "adaptive");  // where scripted tests click
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "Sample every curve and surface so it stays within the tolerance of the exact one\n"
        "(model units), instead of by STEPS: samples gather where curves turn.\n"
        "Stats shows the counts both ways. Not saved into the file (sweep view --tolerance D).");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-90.0f);
  ImGui::BeginDisabled(!adaptive);
  setting_field(s, {"tolerance", "tolerance", tolerance, false, "tolerance"}, tolerance_slider(range),
                [&](double value) {
                  std::string problem = check_tolerance_in(range, value);
                  if (problem.empty() && value != tolerance) {
                    tolerance = value;
                    changed = true;
                  }
                  return problem;
                });
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
    ImGui::SetTooltip("%.3g of the scene's size (%.3g); double-click or Ctrl+click to type a value", tolerance / extent,
                      extent);
  ImGui::EndDisabled();
  if (!changed) return;
  s.adaptive_tolerance = tolerance;
  const double wanted = adaptive ? tolerance : 0.0;
  if (wanted == evaluation.tolerance) return;
  evaluation.tolerance = wanted;
  set_evaluation(s, evaluation);
}

/// The width of the selection's fields: the panel's less the room for the widest label beside
/// them (a curve parameter's, STEPS, a surface's or a rider's), so that the fields line up and
/// no label is cut off at the panel's edge, at any UI scale.
float field_width() {
  float widest = 0.0f;
  for (int k = 0; k <= static_cast<int>(CurveParameter::Tolerance); ++k) {
    const std::string_view name = parameter_name(static_cast<CurveParameter>(k));
    widest = std::max(widest, ImGui::CalcTextSize(name.data(), name.data() + name.size()).x);
  }
  for (const char* label : {"STEPS", "scale", "twist", "degrees", "level", "path", "model", "seconds", "start", "up"}) {
    widest = std::max(widest, ImGui::CalcTextSize(label).x);
  }
  return -(widest + ImGui::GetStyle().ItemInnerSpacing.x);
}

}  // namespace

void edit_panel(const EditParts& s, editor::CommandTable& commands) {
  undo_buttons(s, commands);
  sampling_controls(s);
  const int index = s.selected();
  if (index < 0) {
    ImGui::TextDisabled("click a curve in the view, or a name in Objects");
    return;
  }
  ImGui::PushID("selection");
  ImGui::PushItemWidth(field_width());
  const ObjectKind kind = s.doc().objects[std::size_t(index)].kind();
  ImGui::Text("%s  (%s)", display_name(s.doc(), index).c_str(), std::string(keyword(kind)).c_str());
  if (name_row(s, index)) {
    if (kind_info(kind).steps) steps_slider(s, index);
    if (is_curve(kind)) parameter_fields(s, index);
    if (has_editable_points(kind)) point_table(s, commands, index);
    if (is_curve(kind)) curve_tools(s, commands, index);
    if (is_surface(kind)) surface_fields(s, index);
    if (is_rider(kind)) rider_fields(s, index);
  }
  ImGui::PopItemWidth();
  ImGui::PopID();
}

}  // namespace sweep::viewer::panels
