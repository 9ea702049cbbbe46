#pragma once
// Where Sweep keeps what outlives a run, per the XDG Base Directory specification: recovery
// copies in the state folder ($XDG_STATE_HOME/sweep, default ~/.local/state/sweep), recent files
// and the window layout in the config folder ($XDG_CONFIG_HOME/sweep, default ~/.config/sweep).
// No GL; reads only the environment given.
#include <filesystem>
#include <functional>
#include <string>

namespace sweep::editor {

/// Reads an environment variable: nullptr when unset. Tests pass their own.
using Environment = std::function<const char*(const char*)>;
/// The process environment (std::getenv).
Environment process_environment();

/// A folder, or why there is none ("" when there is one).
struct UserFolder {
  std::filesystem::path path;
  std::string problem;
  bool ok() const { return problem.empty(); }
};

/// $XDG_STATE_HOME/sweep, or $HOME/.local/state/sweep. A relative or empty XDG variable is
/// ignored, as the specification says. Without HOME either: a problem naming both variables.
/// Nothing is created.
UserFolder state_folder(const Environment& env);
/// $XDG_CONFIG_HOME/sweep, or $HOME/.config/sweep; the same rules.
UserFolder config_folder(const Environment& env);

/// Creates `folder.path` (and its parents) if missing. Returns "" or why it cannot, naming the
/// folder ("cannot create /x/sweep: Permission denied"); never throws.
std::string ensure_folder(const UserFolder& folder);

}  // namespace sweep::editor
