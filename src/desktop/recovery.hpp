#pragma once
// Crash recovery: while a document has unsaved changes, a copy of it as SWP (written atomically)
// in the state folder, at most about once a second, after each finished edit step. A clean save
// or quit removes it; opening a file whose copy is newer than the file offers it back.
#include "model/document.hpp"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sweep::editor {

/// The recovery copies in one folder.
class RecoveryStore {
 public:
  explicit RecoveryStore(std::filesystem::path folder);

  const std::filesystem::path& folder() const { return folder_; }

  /// Where the copy of `file` goes: "STEM-HASH.swp" with HASH (16 hex digits, FNV-1a) of the
  /// file's absolute, normalized path, so two "vase.swp" in different folders never collide;
  /// "untitled.swp" for a document without a file ("").
  std::filesystem::path copy_path(const std::string& file) const;

  /// Writes `doc` as the copy of `file` (creating the folder). Returns "" or why not; never
  /// throws, and a failure leaves any earlier copy whole.
  std::string write(const Document& doc, const std::string& file) const;
  /// Removes the copy of `file`, if any. Never throws.
  void remove(const std::string& file) const;

  /// The copy of `file` if there is one newer than the file (or the file is gone); for an
  /// untitled document, its copy if there is one.
  std::optional<std::filesystem::path> newer_copy(const std::string& file) const;

 private:
  std::filesystem::path folder_;
};

/// What a recovered document changes against the saved one, by object name (anonymous objects
/// as "kind#index"): "changed vase", "added rim", "removed stem", in document order.
std::vector<std::string> document_differences(const Document& saved, const Document& recovered);

/// When to write the copy: after an edit step finishes, but not more than once per `interval`
/// seconds; an edit inside the interval is written when it ends.
class RecoveryTimer {
 public:
  explicit RecoveryTimer(double interval = 1.0) : interval_(interval) {}
  /// An edit step finished at `now` (seconds).
  void edited(double now);
  /// True when a copy should be written now (then call written()).
  bool due(double now) const;
  void written(double now);
  /// Seconds until due() turns true, or < 0 when nothing waits.
  double wait_time(double now) const;
  /// Nothing waits any more (saved, or the document was replaced).
  void clear() { pending_ = false; }

 private:
  double interval_;
  double last_write_ = -1e300;
  bool pending_ = false;
};

}  // namespace sweep::editor
