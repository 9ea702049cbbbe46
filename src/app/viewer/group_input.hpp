#pragma once
// The pointer and keys on several points at once: Shift+click adds or removes a handle, a
// Shift+drag draws a rubber band that selects the handles inside it, a drag on a selected handle
// moves the whole selection, and G, R and E run a modal transform (point_transform.hpp) that has
// the keys and the mouse until Enter, a click, Esc or a right click ends it: one undo step.
// Called by input.cpp.
#include "app/viewer/platform.hpp"
#include "app/viewer/viewer_state.hpp"
#include "editor/picking.hpp"

#include <glm/vec2.hpp>

#include <vector>

namespace sweep::viewer {

/// Runs a transform asked for or in progress with this frame's keys and pointer. Returns true
/// while one runs: the keys and the mouse were its own.
bool handle_transform(ViewerState& s, const std::vector<KeyPress>& keys, const editor::ScreenMapping& mapping,
                      const glm::dvec2& mouse);
/// A left press at `mouse` in the view, handle `handle` under it (-1: none). Takes it and returns
/// true when it is about several points: Shift on a handle (toggles it), Shift elsewhere with a
/// curve's points shown (starts a rubber band), or a handle of a selection of several (moves
/// them all).
bool press_on_points(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse, int handle);
/// A rubber band in progress: follows the pointer, selects on release. Returns true while it runs.
bool continue_rubber_band(ViewerState& s, const editor::ScreenMapping& mapping, const glm::dvec2& mouse);

}  // namespace sweep::viewer
