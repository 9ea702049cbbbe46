#include "desktop/user_folders.hpp"

#include <cstdlib>
#include <system_error>

namespace sweep::editor {
namespace {

/// The value of `name` when it is set, non-empty and absolute (the XDG rule); "" otherwise.
std::string absolute_variable(const Environment& env, const char* name) {
  const char* value = env ? env(name) : nullptr;
  if (!value || !*value) return "";
  const std::filesystem::path path(value);
  if (!path.is_absolute()) return "";
  return value;
}

UserFolder user_folder(const Environment& env, const char* xdg_variable, const char* home_relative,
                       const char* what_for) {
  UserFolder folder;
  const std::string xdg = absolute_variable(env, xdg_variable);
  if (!xdg.empty()) {
    folder.path = std::filesystem::path(xdg) / "sweep";
    return folder;
  }
  const char* home = env ? env("HOME") : nullptr;
  if (home && *home) {
    folder.path = std::filesystem::path(home) / home_relative / "sweep";
    return folder;
  }
  folder.problem = "neither ";
  folder.problem += xdg_variable;
  folder.problem += " nor HOME is set: nowhere to keep ";
  folder.problem += what_for;
  return folder;
}

}  // namespace

Environment process_environment() {
  return [](const char* name) -> const char* { return std::getenv(name); };
}

UserFolder state_folder(const Environment& env) {
  return user_folder(env, "XDG_STATE_HOME", ".local/state", "recovery copies");
}

UserFolder config_folder(const Environment& env) {
  return user_folder(env, "XDG_CONFIG_HOME", ".config", "recent files and the window layout");
}

std::string ensure_folder(const UserFolder& folder) {
  if (!folder.ok()) return folder.problem;
  try {
    std::error_code ec;
    const std::string name = folder.path.string();
    if (std::filesystem::exists(folder.path, ec)) {
      if (std::filesystem::is_directory(folder.path, ec)) return "";
      std::string message = "cannot use ";
      message += name;
      message += ": it is not a folder";
      return message;
    }
    ec.clear();
    std::filesystem::create_directories(folder.path, ec);
    if (ec) {
      std::string message = "cannot create ";
      message += name;
      message += ": ";
      message += ec.message();
      return message;
    }
    return "";
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    std::string message = "cannot create ";
    message += folder.path.string();
    return message;
  }
}

}  // namespace sweep::editor
