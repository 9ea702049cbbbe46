#pragma once
// Small pieces the panels share.
#include "app/viewer/panels/edit_context.hpp"
#include "editor/commands.hpp"

#include <imgui.h>

#include <string>
#include <string_view>
#include <vector>

namespace sweep::viewer::panels {

/// Every text field's flags: a click selects its whole text, so what is typed at once replaces it
/// whole even when the keys arrive with the click (ImGui 1.86 ignores keys, Ctrl+A among them,
/// in the frame a field is activated, and inserts the characters where the click put the cursor).
inline constexpr ImGuiInputTextFlags kTextFieldFlags = ImGuiInputTextFlags_AutoSelectAll;

/// The colour of a warning's text: the status bar's and the print findings'.
inline const ImVec4 kWarningText{1.0f, 0.78f, 0.3f, 1.0f};

/// A button for `id` labelled "LABEL [SHORTCUT]" (or `text` with the shortcut), disabled when
/// the command is. Runs the command when pressed.
void command_button(editor::CommandTable& commands, editor::CommandId id, const std::string& text = {});

/// "trefoil-knot" for "trefoil knot", "open-b-spline-2d" for "open B-spline (2D)": a choice's
/// mark for scripted tests (one word).
std::string mark_name(std::string_view label);
/// A combo of `labels`, all shown when open, the open list's entries marked for scripted tests as
/// "PREFIX-NAME" (mark_name) and the combo as "PREFIX".
void marked_combo(ItemPositions* positions, const char* label, const std::vector<std::string_view>& labels, int& choice,
                  const std::string& prefix);

/// A menu item for `id` with its shortcut, greyed out when disabled; runs it when chosen.
/// `checked`: a check mark beside it (a setting that is on).
void command_menu_item(editor::CommandTable& commands, editor::CommandId id, const std::string& text = {},
                       bool checked = false);

/// A combo box of curves by display name; `choice` is an object index, or -1 for `none` when
/// it is given (otherwise -1 becomes the first candidate). Returns true when the user chose.
bool curve_combo(const Document& doc, const char* label, const std::vector<int>& candidates, int& choice,
                 const char* none = nullptr);

/// "TEXT [SHORTCUT]" for a command's control that is not a button (a combo, a checkbox).
std::string with_shortcut(const editor::CommandTable& commands, editor::CommandId id, const std::string& text);

}  // namespace sweep::viewer::panels
