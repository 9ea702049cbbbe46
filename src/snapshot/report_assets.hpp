#pragma once
// The HTML report's inline style sheet and script (report.cpp writes the page around them):
// src/snapshot/report.css and report.js, embedded at build time (cmake/embed_files.cmake), so a
// report opens from a CI artifact without a server or network.
#include <optional>
#include <string_view>

namespace sweep::snapshot {

/// The embedded file named `name` ("report.css", "report.js"), if there is one.
std::optional<std::string_view> report_asset(std::string_view name);

/// The page's CSS: dark, one colour per status (--fail, --warning, ...), the heat map's legend.
inline std::string_view report_style() {
  return report_asset("report.css").value_or("");
}
/// The wipe slider, flicker toggle, status filters, j/k keys, and the self-test a headless
/// browser runs at #selftest: it counts the images that loaded, drives the first slider to both
/// ends and the first flicker toggle, and writes what it found into body[data-selftest] and the title.
inline std::string_view report_script() {
  return report_asset("report.js").value_or("");
}

}  // namespace sweep::snapshot
