#pragma once
// The sweep command line is put together from these; each adds its subcommand(s) to the app.
#include <CLI/CLI.hpp>

#include <functional>

namespace sweep::app {

/// Work to run after parsing; returns the process exit code.
using Action = std::function<int()>;

/// `sweep export FILE.swp PREFIX` and `sweep info FILE.swp` (core only). cli_commands.cpp
void add_core_commands(CLI::App& app, Action& action);

/// `sweep view FILE.swp` and `sweep render FILE.swp -o OUT.png` (GL). view_commands.cpp
void add_view_commands(CLI::App& app, Action& action);

/// Opens the viewer on `file` (used by the plain `sweep FILE.swp [PREFIX]` form).
/// Without a display, prints one line saying so and pointing to `sweep render`, returns 1.
int open_viewer(const std::string& file);

/// The plain form: exports OBJ (when prefix is not empty) then opens the viewer if a display is
/// available. cli_commands.cpp
int run_plain(const std::string& file, const std::string& prefix);

}  // namespace sweep::app
