#pragma once
// A number the user drags or types in. Dragging applies as the value moves (one undo step per
// drag); typing (double-click or Ctrl+click) applies once, on Enter or when the field loses
// focus, so nothing half-typed ("1e1" on the way to "1e13") becomes an edit.
#include "app/viewer/viewer_state.hpp"
#include "editor/edit_session.hpp"

#include <functional>
#include <string>

namespace sweep::viewer::panels {

struct NumberField {
  const char* label = "";  // the ImGui label, which names the field
  std::string role;        // what the number is, in messages ("x of point 3")
  double current = 0.0;    // the value shown
};

/// Draws the drag or slider of a number (with ImGuiSliderFlags_NoInput, so ImGui types nothing
/// itself) into its argument, starting at the current value; returns whether it moved.
using DrawNumber = std::function<bool(double&)>;
/// The edit that gives the number `value`.
using NumberEdit = std::function<editor::EditSession::Operation(double value)>;

/// `field` as `draw` shows it, or as a text field while it is typed in. A dragged value that
/// differs from field.current is applied as part of the step `label`; a typed one as the edit
/// `label` once, unless the text is unchanged (or Esc restored it). Text that is not a number, or
/// a number the edit refuses, changes nothing and sets s.error to say why.
void number_field(ViewerState& s, const NumberField& field, const DrawNumber& draw, const std::string& label,
                  const NumberEdit& edit);

/// The number `text` (spaces around it and one leading '+' allowed), or a message naming `role`.
/// Exposed for tests.
bool parse_typed_number(const std::string& text, const std::string& role, double& value, std::string& message);

}  // namespace sweep::viewer::panels
