#pragma once
// Keyboard and mouse for the 3D view: key presses run commands from the table, clicks pick
// handles and curves, drags move control points or the camera. Whatever ImGui is using (a
// field being typed in, a panel under the pointer) is left to ImGui.
#include "app/viewer/platform.hpp"
#include "app/viewer/viewer_state.hpp"
#include "editor/commands.hpp"
#include "editor/picking.hpp"

#include <glm/vec2.hpp>

#include <vector>

namespace sweep::viewer {

/// How world points map to window positions this frame (framebuffer of `framebuffer` pixels).
editor::ScreenMapping screen_mapping(const ViewerState& s, glm::ivec2 framebuffer);

/// Window positions of the selected curve's control points (nullopt: behind the eye).
std::vector<std::optional<glm::dvec2>> handle_positions(const ViewerState& s, const editor::ScreenMapping& mapping);

/// Handles this frame's keys and mouse. `held_axis` is the axis key held down (or -1).
void handle_input(ViewerState& s, editor::CommandTable& commands, const std::vector<KeyPress>& keys, int held_axis,
                  glm::ivec2 framebuffer);

}  // namespace sweep::viewer
