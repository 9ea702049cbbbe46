#pragma once
// Screenshot regression of one document inside a program or a test (what `sweep snapshot` does
// for a folder): render it, compare with the reference picture, and when it differs say which
// named object changed and how far it moved.
#include <sweep/document.hpp>
#include <sweep/version.hpp>

#include <filesystem>
#include <string>
#include <vector>

SWEEP_BEGIN_NAMESPACE

struct SnapshotOptions {
  std::string mode = "smooth";  // "smooth", "wire" or "frames"
  int width = 320;
  int height = 240;
  double threshold = 0.1;  // as CompareOptions
  std::size_t max_diff_pixels = 8;
  bool update = false;  // accept: rewrite a reference that fails, as `sweep snapshot --update`
};

struct SnapshotResult {
  /// "pass", "warning", "FAIL", "new" (a reference was written: the case fails unless
  /// `update`), "updated" or "error".
  std::string status;
  bool passed = false;  // pass, warning, updated, or new with update
  std::string message;  // one line, as `sweep snapshot` prints it
  /// The objects, "wineglass: 423 pixels changed (0 differ); its mesh moved up to 0.0326" (failures and warnings).
  std::vector<std::string> objects;
  /// The names of the objects whose geometry or material changed (added and removed ones too).
  std::vector<std::string> changed_objects;
  std::filesystem::path reference;  // the reference picture compared or written
};

/// Compares `doc`'s picture with the reference `folder/NAME-MODE.png` (and its sidecar, with
/// the camera the reference was taken with and every object's fingerprint), as `sweep snapshot`
/// does for one case: the first call writes the reference. Throws Error when no offscreen
/// context can be made or a reference cannot be written.
SWEEP_API SnapshotResult check_snapshot(const Document& doc, const std::filesystem::path& folder,
                                        const std::string& name, const SnapshotOptions& options = {});

SWEEP_END_NAMESPACE
