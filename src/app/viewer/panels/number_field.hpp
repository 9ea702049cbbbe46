#pragma once
// A number the user drags or types in. Dragging applies as the value moves (one undo step per
// drag); typing (double-click or Ctrl+click) applies once, on Enter or when the field loses
// focus, so nothing half-typed ("1e1" on the way to "1e13") becomes an edit. Every numeric field
// of the panels goes through here: document edits (number_field) and viewer settings
// (setting_field), drags and sliders, real and whole numbers.
#include "app/viewer/panels/edit_context.hpp"
#include "editor/edit_session.hpp"

#include <functional>
#include <string>

namespace sweep::viewer::panels {

struct NumberField {
  const char* label = "";  // the ImGui label, which names the field
  std::string role;        // what the number is, in messages ("x of point 3")
  double current = 0.0;    // the value shown
  bool whole = false;      // only whole numbers: typed "2.5" is refused with a message
  std::string mark;        // for scripted tests: the name mark_item records the field under ("": none)
};

/// Draws the drag or slider of a number (with ImGuiSliderFlags_NoInput, so ImGui types nothing
/// itself) into its argument, starting at the current value; returns whether it moved.
using DrawNumber = std::function<bool(double&)>;
/// The edit that gives the number `value`.
using NumberEdit = std::function<editor::EditSession::Operation(double value)>;
/// Sets a viewer setting (not saved, not undone) to `value`; returns "" or why it refuses it.
using NumberSetting = std::function<std::string(double value)>;

/// `field` as `draw` shows it, or as a text field while it is typed in. A dragged value that
/// differs from field.current is applied as part of the step `label`; a typed one as the edit
/// `label` once, unless the text is unchanged (or Esc restored it). Text that is not a number, or
/// a number the edit refuses, changes nothing and sets the error to say why.
void number_field(const EditContext& c, const NumberField& field, const DrawNumber& draw, const std::string& label,
                  const NumberEdit& edit);

/// The same for a viewer setting: `set` gets every dragged value that differs from
/// field.current, and a typed one once; its refusal goes to the error.
void setting_field(const EditContext& c, const NumberField& field, const DrawNumber& draw, const NumberSetting& set);

/// DrawNumber for ImGui::SliderFloat(label, low..high, format, flags | NoInput) on a double.
/// `label` must outlive the returned function.
DrawNumber float_slider(const char* label, float low, float high, const char* format, int flags = 0);
/// DrawNumber for ImGui::SliderInt(label, low..high, "%d", flags | NoInput) on a whole number.
/// `label` must outlive the returned function.
DrawNumber int_slider(const char* label, int low, int high, int flags = 0);

/// The number `text` (spaces around it and one leading '+' allowed), or a message naming `role`.
/// With `whole`, only a whole number that fits an int. Exposed for tests.
bool parse_typed_number(const std::string& text, const std::string& role, double& value, std::string& message,
                        bool whole = false);

}  // namespace sweep::viewer::panels
