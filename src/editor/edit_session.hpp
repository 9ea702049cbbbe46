#pragma once
// The document the viewer edits: the Document, its evaluated Scene and undo History kept in
// step, the file it came from and whether it has unsaved changes. Every object carries a stable
// id (Object::id) from the moment it is loaded or created; the id travels with the object through
// the history, so undo and redo bring back the same ids. No GL and no ImGui.
#include "model/document.hpp"
#include "model/edit.hpp"
#include "model/history.hpp"
#include "model/scene.hpp"

#include <cstdint>
#include <functional>
#include <string>

namespace sweep::editor {

/// A stable object identity (Object::id); kNoObject is none.
using ObjectId = std::uint64_t;
inline constexpr ObjectId kNoObject = 0;

class EditSession {
 public:
  /// Replaces the document (a file was opened) and forgets the history. Throws what evaluation
  /// throws (e.g. std::bad_alloc) and then keeps the old document.
  void load(Document doc, std::string path);

  const Document& document() const { return doc_; }
  const Scene& scene() const { return scene_; }
  const std::string& file() const { return file_; }

  /// The index of the object with id `id`, or -1 (deleted, or never was).
  int index_of(ObjectId id) const;
  /// The id of object `index`, or kNoObject for an index out of range.
  ObjectId id_of(int index) const;
  bool dirty() const { return history_.dirty(); }
  /// Grows whenever the document or its scene changes (load, edits, undo, redo, evaluation).
  std::uint64_t revision() const { return revision_; }

  /// An edit: changes the document and says what changed; throws EditError (or anything else)
  /// leaving the document as it was.
  using Operation = std::function<Change(Document&)>;

  /// Runs `operation` as one undo step named `label` (or as part of the open step, if any) and
  /// re-evaluates what it changed. Returns false and sets error() when it throws (the document
  /// stays as it was).
  bool edit(const std::string& label, const Operation& operation);

  /// Continuous edits (a drag, a value being typed) that undo as one step: begin_step, then
  /// apply() any number of times, then end_step. begin_step() while a step is open does nothing.
  /// A failed apply() sets error() and changes nothing; the step stays open.
  void begin_step(const std::string& label);
  bool apply(const Operation& operation);
  void end_step();
  /// Abandons the open step: the document goes back to what it was at begin_step (a transform
  /// cancelled with Esc), and no undo step is recorded. Does nothing without an open step.
  void cancel_step();
  bool in_step() const { return history_.in_step(); }

  bool can_undo() const { return !in_step() && history_.can_undo(); }
  bool can_redo() const { return !in_step() && history_.can_redo(); }
  std::string undo_label() const { return history_.undo_label(); }
  std::string redo_label() const { return history_.redo_label(); }
  /// Undo and redo one step. Return false when there is nothing to do (or a step is open).
  bool undo();
  bool redo();

  /// Saves to `path` atomically (the old file survives any failure) and makes it the current
  /// file. Returns false and sets error() when it cannot; the edits stay in memory.
  bool save(const std::string& path);

  /// Frame options and seam handling; re-evaluates everything when they change.
  const EvaluationOptions& evaluation() const { return evaluation_; }
  void set_evaluation(const EvaluationOptions& options);

  /// Milliseconds spent re-evaluating (re-meshing) after the last edit, undo or redo.
  double last_remesh_ms() const { return last_remesh_ms_; }
  /// Objects re-evaluated by the last edit.
  std::size_t last_remesh_objects() const { return last_remesh_objects_; }

  /// The message of the last failure ("" after a success); the caller shows and clears it.
  const std::string& error() const { return error_; }
  void clear_error() { error_.clear(); }

 private:
  /// Brings the scene in line with `change` and times it.
  void refresh(const Change& change);
  /// Gives every object without an id (just loaded or created) a new one.
  void assign_ids();

  Document doc_;
  Scene scene_;
  History history_;
  std::string file_;
  EvaluationOptions evaluation_;
  double last_remesh_ms_ = 0.0;
  std::size_t last_remesh_objects_ = 0;
  std::string error_;
  ObjectId next_id_ = 1;  // ids are never reused within a session
  std::uint64_t revision_ = 0;
};

}  // namespace sweep::editor
