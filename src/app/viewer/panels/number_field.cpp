#include "app/viewer/panels/number_field.hpp"

#include "app/viewer/panels/panel_support.hpp"
#include "app/viewer/panels/value_slider.hpp"

#include "base/number_text.hpp"

#include <imgui.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <string_view>
#include <system_error>
#include <utility>

namespace sweep::viewer::panels {
namespace {

/// True when the user asked to type into the last item (it was just pressed with Ctrl held, or
/// double-clicked), as ImGui's own drags and sliders do.
bool typing_requested() {
  return ImGui::IsItemActivated() && (ImGui::GetIO().KeyCtrl || ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left));
}

void start_typing(const EditContext& c, ImGuiID id, double current) {
  TypedNumber& typed = c.typed_number();
  typed = {};
  typed.id = id;
  typed.initial = number_text(current);
  typed.text.set(typed.initial);
  typed.frame = ImGui::GetFrameCount();
}

/// How a field's value is applied: as it is dragged (each frame, `changed` saying whether it
/// moved) and once typed.
struct Apply {
  std::function<void(bool changed, double value)> dragged;
  std::function<void(double value)> typed;
};

/// The typed text applied: nothing when unchanged, else the number or why it is none.
void apply_typed(const EditContext& c, const std::string& text, const std::string& initial, const NumberField& field,
                 const Apply& apply) {
  if (text == initial) return;
  double value = 0.0;
  std::string message;
  if (!parse_typed_number(text, field.role, value, message, field.whole)) {
    c.error() = message;
    return;
  }
  apply.typed(value);
}

/// The field as text being typed in; applies it when Enter is pressed or the field loses focus.
void typed_field(const EditContext& c, const NumberField& field, const Apply& apply) {
  TypedNumber& typed = c.typed_number();
  typed.frame = ImGui::GetFrameCount();
  // A field of its own id, so ImGui starts it fresh rather than as the drag it replaces; it
  // takes the keyboard a frame after asking (SetKeyboardFocusHere).
  if (!typed.focused) ImGui::SetKeyboardFocusHere();
  ImGui::PushID("typed");
  const bool entered = ImGui::InputText(field.label, typed.text.text.data(), typed.text.text.size(),
                                        ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
  const bool active = ImGui::IsItemActive();
  ImGui::PopID();
  if (!field.mark.empty()) mark_item(c, field.mark);
  if (active && !entered) {
    typed.focused = true;
    return;
  }
  if (!entered && !typed.focused) return;  // the keyboard comes next frame
  const std::string text = typed.text.get();
  const std::string initial = typed.initial;
  typed = {};  // the drag again from the next frame
  apply_typed(c, text, initial, field, apply);
}

/// The field drawn by `draw`, or typed in; what it sets goes through `apply`.
void field_with_typing(const EditContext& c, const NumberField& field, const DrawNumber& draw, const Apply& apply) {
  const ImGuiID id = ImGui::GetID(field.label);
  TypedNumber& typed = c.typed_number();
  if (typed.id == id && typed.frame < ImGui::GetFrameCount() - 1) typed = {};  // not drawn since: gone
  if (typed.id == id) {
    typed_field(c, field, apply);
    return;
  }
  double value = field.current;
  const bool changed = draw(value) && value != field.current;
  if (!field.mark.empty()) mark_item(c, field.mark);
  if (typing_requested()) {
    start_typing(c, id, field.current);
    return;  // the press starts no drag step
  }
  apply.dragged(changed, value);
}

/// The setting `set` to `value`, its refusal into the error.
void set_setting(const EditContext& c, const NumberSetting& set, double value) {
  if (std::string problem = set(value); !problem.empty()) c.error() = std::move(problem);
}

}  // namespace

bool parse_typed_number(const std::string& text, const std::string& role, double& value, std::string& message,
                        bool whole) {
  std::string_view number = text;
  while (!number.empty() && number.front() == ' ') number.remove_prefix(1);
  while (!number.empty() && number.back() == ' ') number.remove_suffix(1);
  if (number.size() > 1 && number.front() == '+' && number[1] != '-') number.remove_prefix(1);
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  const bool read = !number.empty() && error == std::errc() && end == number.data() + number.size();
  const bool fits = std::abs(value) <= double(std::numeric_limits<int>::max());
  if (read && (!whole || (value == std::floor(value) && fits))) return true;
  message = std::string(whole ? "expected a whole number (" : "expected a number (") + role + "), found '" + text + "'";
  if (error == std::errc::result_out_of_range || (read && whole && !fits)) message += ": out of range";
  return false;
}

void number_field(const EditContext& c, const NumberField& field, const DrawNumber& draw, const std::string& label,
                  const NumberEdit& edit) {
  field_with_typing(c, field, draw,
                    {[&](bool changed, double value) { c.continuous_item(changed, label, edit(value)); },
                     [&](double value) { c.run_edit(label, edit(value)); }});
}

void setting_field(const EditContext& c, const NumberField& field, const DrawNumber& draw, const NumberSetting& set) {
  field_with_typing(c, field, draw,
                    {[&](bool changed, double value) {
                       if (changed) set_setting(c, set, value);
                     },
                     [&](double value) { set_setting(c, set, value); }});
}

DrawNumber float_slider(const char* label, float low, float high, const char* format, int flags) {
  return [=](double& value) {
    float shown = static_cast<float>(value);
    if (!value_slider_float(label, &shown, low, high, format, flags | ImGuiSliderFlags_NoInput)) return false;
    value = double(shown);
    return true;
  };
}

DrawNumber int_slider(const char* label, int low, int high, int flags) {
  return [=](double& value) {
    int shown = static_cast<int>(value);
    if (!value_slider(label, ImGuiDataType_S32, &shown, &low, &high, "%d", flags | ImGuiSliderFlags_NoInput)) {
      return false;
    }
    value = double(shown);
    return true;
  };
}

}  // namespace sweep::viewer::panels
