#pragma once
// The pen's keys and pointer in the view (pen_actions.hpp does what they ask), and its marks:
// the nodes and handles put down, the line to where the next click lands, the first node ringed
// when a click there closes the curve, and where the pointer snapped. Called by input.cpp while
// the pen is on.
#include "app/viewer/viewer_state.hpp"
#include "editor/commands.hpp"
#include "editor/picking.hpp"

#include <glm/vec2.hpp>

namespace sweep::viewer {

/// A key while the pen is on: Enter ends the stroke; Esc ends it, or with none puts the pen away;
/// Backspace and Del take back the last node. While a stroke is drawn (one undo step) every other
/// key is held back too, so nothing else edits meanwhile. True when the pen took the key.
bool pen_key(ViewerState& s, const editor::Shortcut& pressed);
/// The left button over the view: a press puts down a node (snapped as a dragged point snaps: to
/// the grid, and unless Ctrl is held to points, curves and the axis), moving while held drags its
/// handles, a press on the first node closes the curve. `over_view`: ImGui does not want the mouse.
void pen_pointer(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse, bool over_view);
/// The pen's marks for this frame (ImGui's foreground).
void draw_pen(const ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse);

}  // namespace sweep::viewer
