#include "desktop/settings.hpp"

#include "io/files/atomic_file.hpp"

#include <fstream>
#include <sstream>
#include <system_error>

namespace sweep::editor {

Settings load_settings(const std::filesystem::path& file) {
  Settings settings;
  try {
    std::ifstream in(file, std::ios::binary);
    std::string line;
    while (in && std::getline(in, line)) {
      std::istringstream words(line);
      std::string key;
      std::string value;
      words >> key >> value;
      if (key != "file-chooser") continue;
      if (const auto preference = chooser_preference_named(value)) settings.file_chooser = *preference;
    }
  } catch (...) {
  }
  return settings;
}

std::string save_settings(const std::filesystem::path& file, const Settings& settings) {
  const std::string cannot = "cannot save the settings to " + file.string() + ": ";
  try {
    std::error_code ec;
    if (file.has_parent_path()) {
      std::filesystem::create_directories(file.parent_path(), ec);
      if (ec) return cannot + ec.message();
    }
    io::write_file_atomically(file,
                              std::string("file-chooser ") + chooser_preference_name(settings.file_chooser) + "\n");
    return "";
  } catch (const std::exception& e) {
    std::string reason = e.what();
    const std::string prefix = "cannot write " + file.string() + ": ";
    if (reason.starts_with(prefix)) reason.erase(0, prefix.size());
    return cannot + reason;
  } catch (...) {
    return cannot + "unknown error";
  }
}

std::optional<ChooserPreference> chooser_preference_override(const Environment& env) {
  const char* value = env("SWEEP_FILE_CHOOSER");
  if (value == nullptr) return std::nullopt;
  return chooser_preference_named(value);
}

}  // namespace sweep::editor
