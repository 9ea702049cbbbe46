#pragma once
// The viewer's settings kept across runs, in the config folder (settings.txt: one "KEY VALUE"
// a line). Today one: which file dialog Open and Save As use.
#include "desktop/file_chooser.hpp"

#include <filesystem>
#include <string>

namespace sweep::editor {

struct Settings {
  ChooserPreference file_chooser = ChooserPreference::Auto;  // key "file-chooser": auto or in-app
  bool operator==(const Settings&) const = default;
};

/// Reads `file`; a missing file gives the defaults, and a line with an unknown key or value is
/// skipped (a newer Sweep may have written it). Never throws.
Settings load_settings(const std::filesystem::path& file);
/// Writes every setting atomically. Returns "" or why not; never throws.
std::string save_settings(const std::filesystem::path& file, const Settings& settings);

/// The preference SWEEP_FILE_CHOOSER ("auto" or "in-app") sets for this run, over the setting;
/// nullopt when it is unset or says anything else.
std::optional<ChooserPreference> chooser_preference_override(const Environment& env);

}  // namespace sweep::editor
