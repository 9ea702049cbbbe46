#include "app/viewer/panels/number_field.hpp"

#include "app/viewer/actions.hpp"
#include "app/viewer/panels/panel_support.hpp"

#include "geometry/number_text.hpp"

#include <imgui.h>

#include <charconv>
#include <string_view>
#include <system_error>

namespace sweep::viewer::panels {
namespace {

/// True when the user asked to type into the last item (it was just pressed with Ctrl held, or
/// double-clicked), as ImGui's own drags and sliders do.
bool typing_requested() {
  return ImGui::IsItemActivated() && (ImGui::GetIO().KeyCtrl || ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left));
}

void start_typing(ViewerState& s, ImGuiID id, double current) {
  TypedNumber& typed = s.fields.typed_number;
  typed = {};
  typed.id = id;
  typed.initial = number_text(current);
  typed.text.set(typed.initial);
  typed.frame = ImGui::GetFrameCount();
}

/// The typed text as an edit: nothing when unchanged, else the number or why it is none.
void apply_typed(ViewerState& s, const std::string& text, const std::string& initial, const NumberField& field,
                 const std::string& label, const NumberEdit& edit) {
  if (text == initial) return;
  double value = 0.0;
  std::string message;
  if (!parse_typed_number(text, field.role, value, message)) {
    s.error = message;
    return;
  }
  run_edit(s, label, edit(value));
}

/// The field as text being typed in; applies it when Enter is pressed or the field loses focus.
void typed_field(ViewerState& s, const NumberField& field, const std::string& label, const NumberEdit& edit) {
  TypedNumber& typed = s.fields.typed_number;
  typed.frame = ImGui::GetFrameCount();
  // A field of its own id, so ImGui starts it fresh rather than as the drag it replaces; it
  // takes the keyboard a frame after asking (SetKeyboardFocusHere).
  if (!typed.focused) ImGui::SetKeyboardFocusHere();
  ImGui::PushID("typed");
  const bool entered = ImGui::InputText(field.label, typed.text.text.data(), typed.text.text.size(),
                                        ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_AutoSelectAll);
  const bool active = ImGui::IsItemActive();
  ImGui::PopID();
  if (active && !entered) {
    typed.focused = true;
    return;
  }
  if (!entered && !typed.focused) return;  // the keyboard comes next frame
  const std::string text = typed.text.get();
  const std::string initial = typed.initial;
  typed = {};  // the drag again from the next frame
  apply_typed(s, text, initial, field, label, edit);
}

}  // namespace

bool parse_typed_number(const std::string& text, const std::string& role, double& value, std::string& message) {
  std::string_view number = text;
  while (!number.empty() && number.front() == ' ') number.remove_prefix(1);
  while (!number.empty() && number.back() == ' ') number.remove_suffix(1);
  if (number.size() > 1 && number.front() == '+' && number[1] != '-') number.remove_prefix(1);
  const auto [end, error] = std::from_chars(number.data(), number.data() + number.size(), value);
  if (!number.empty() && error == std::errc() && end == number.data() + number.size()) return true;
  message = "expected a number (" + role + "), found '" + text + "'";
  if (error == std::errc::result_out_of_range) message += ": out of range";
  return false;
}

void number_field(ViewerState& s, const NumberField& field, const DrawNumber& draw, const std::string& label,
                  const NumberEdit& edit) {
  const ImGuiID id = ImGui::GetID(field.label);
  TypedNumber& typed = s.fields.typed_number;
  if (typed.id == id && typed.frame < ImGui::GetFrameCount() - 1) typed = {};  // not drawn since: gone
  if (typed.id == id) {
    typed_field(s, field, label, edit);
    return;
  }
  double value = field.current;
  const bool changed = draw(value) && value != field.current;
  if (typing_requested()) {
    start_typing(s, id, field.current);
    return;  // the press starts no drag step
  }
  continuous_item(s, changed, label, edit(value));
}

}  // namespace sweep::viewer::panels
