#pragma once
// The HTML report's inline style sheet and script (report.cpp writes the page around them).

namespace sweep::snapshot {

/// The page's CSS: dark, one colour per status (--fail, --warning, ...), the heat map's legend.
extern const char* const kReportStyle;
/// The wipe slider, flicker toggle, status filters, j/k keys, and the self-test a headless
/// browser runs at #selftest: it counts the images that loaded, drives the first slider to both
/// ends and the first flicker toggle, and writes what it found into body[data-selftest] and the title.
extern const char* const kReportScript;

}  // namespace sweep::snapshot
