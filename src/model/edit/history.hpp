#pragma once
// Undo and redo for editing a Document. Each step stores only the objects it changed (or the
// whole document when the edit changed its structure), so a drag of one point of a large file
// does not copy the file per step.
#include "model/document.hpp"
#include "model/edit/edit.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace sweep {

class History {
 public:
  /// Keeps at most `max_steps` undo steps and at most `max_stored_points` control points in them
  /// (objects count 1 each besides their points), the newest step always; the oldest undo steps
  /// are forgotten first (forgotten() counts them). The defaults (1000 steps, 2 million points,
  /// 24 bytes each) bound the history to about 50 MB: 10 000 random edits in one session grow
  /// the viewer's memory by less than 64 MiB (docs/reliability.md, "Long sessions").
  History() = default;
  History(std::size_t max_steps, std::int64_t max_stored_points)
      : max_steps_(max_steps), max_stored_points_(max_stored_points) {}

  /// Starts a step: remembers `doc` as it is before the edit. A drag calls begin() on mouse
  /// press, edits the document any number of times, and end() on release: one step.
  /// Calling begin() while a step is open keeps the first snapshot and label (nesting is
  /// flattened): only the end() matching the outermost begin() records the step.
  void begin(const Document& doc, std::string label);
  /// Ends the step opened by begin(): records the difference between the snapshot and `doc`.
  /// Records nothing if nothing changed. Discards the redo steps when it records.
  void end(const Document& doc);
  /// Abandons the open step and restores the snapshot into `doc` (for a failed edit).
  /// Returns what changed back.
  Change cancel(Document& doc);
  bool in_step() const;

  bool can_undo() const;
  /// Undo steps forgotten so far to stay within the caps, the oldest first.
  std::size_t forgotten() const { return forgotten_; }
  /// The undo steps kept (for going back to a point in the history, as Cancel does).
  std::size_t undo_count() const { return undo_.size(); }
  bool can_redo() const;
  /// Label of the step undo()/redo() would apply ("" if none).
  std::string undo_label() const;
  std::string redo_label() const;
  /// Undoes/redoes one step in `doc` and returns what changed (empty if nothing to do, and
  /// while a step is open). Precondition: `doc` is the document the steps were recorded on.
  Change undo(Document& doc);
  Change redo(Document& doc);

  /// True when `doc` differs from the last saved (or loaded) state through recorded steps.
  bool dirty() const;
  /// Marks the current state as saved. Called while a step is open, the document stays dirty
  /// until the next save (the saved state lies inside the step, which no undo returns to).
  void mark_saved();
  /// Forgets every step (a new file was opened); the current state counts as saved.
  void clear();

 private:
  struct ObjectChange {
    int index = -1;
    Object before;
    Object after;
  };
  struct Step {
    std::string label;
    std::vector<ObjectChange> objects;  // in-place changes, when the structure stayed
    std::optional<Document> before;     // whole documents, when the structure changed
    std::optional<Document> after;
    std::uint64_t id = 0;
    std::int64_t cost = 0;  // stored points and objects, for the memory bound
  };
  std::uint64_t current_id() const;
  void trim();
  std::vector<Step> undo_;
  std::vector<Step> redo_;
  std::optional<Document> snapshot_;
  std::string snapshot_label_;
  int depth_ = 0;  // begin() calls not yet matched by end()
  std::uint64_t next_id_ = 1;
  std::uint64_t saved_id_ = 0;  // id of the state when saved (see current_id)
  std::uint64_t base_id_ = 0;   // id of the state before the oldest undo step (0: as loaded)
  std::size_t max_steps_ = 1000;
  std::int64_t max_stored_points_ = 2'000'000;
  std::int64_t stored_points_ = 0;  // cost of the steps in undo_ and redo_
  std::size_t forgotten_ = 0;
};

}  // namespace sweep
