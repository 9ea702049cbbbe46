#pragma once
// What each command of the editor's command table does in the viewer.
#include "app/viewer/viewer_state.hpp"
#include "editor/commands.hpp"

namespace sweep::viewer {

/// Binds every command to `state` (which must outlive the table).
void bind_commands(editor::CommandTable& table, ViewerState& state);

}  // namespace sweep::viewer
