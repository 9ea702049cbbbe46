#pragma once
// The document the viewer edits: the Document, its evaluated Scene and undo History kept in
// step, the file it came from and whether it has unsaved changes. Every object carries a stable
// id (Object::id) from the moment it is loaded or created; the id travels with the object through
// the history, so undo and redo bring back the same ids. No GL and no ImGui.
#include "editor/evaluation_job.hpp"
#include "model/document.hpp"
#include "model/edit/edit.hpp"
#include "model/edit/history.hpp"
#include "model/evaluation/scene.hpp"

#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace sweep::editor {

/// The viewer's set_background threshold: work (samples + vertices + points) above which an
/// evaluation goes to the background. A subdivision runs at about 0.65 microseconds per vertex on
/// a quiet core (benchmarks/BM_SubdivideTenThousandFaces), up to three times that while the
/// window draws in software beside it: 40 000 keeps every evaluation on the drawing thread under
/// about 80 ms (scripts/measure-freeze.sh).
inline constexpr std::int64_t kViewerBackgroundWork = 40'000;

/// A stable object identity (Object::id); kNoObject is none.
using ObjectId = std::uint64_t;
inline constexpr ObjectId kNoObject = 0;

class EditSession {
 public:
  /// Replaces the document (a file was opened) and forgets the history. Throws what evaluation
  /// throws (e.g. std::bad_alloc) and then keeps the old document; evaluated in the background
  /// (see set_background), it shows nothing until its evaluation is complete.
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

  /// True once per session: the first time the history forgets its oldest steps to stay within
  /// its caps (model/edit/history.hpp), so that the viewer tells the user once.
  bool take_history_notice();
  /// Undo steps forgotten so far, and kept now.
  std::size_t forgotten_steps() const { return history_.forgotten(); }
  std::size_t undo_count() const { return history_.undo_count(); }

  bool can_undo() const { return !in_step() && history_.can_undo(); }
  bool can_redo() const { return !in_step() && history_.can_redo(); }
  std::string undo_label() const { return history_.undo_label(); }
  std::string redo_label() const { return history_.redo_label(); }
  /// Undo and redo one step. Return false when there is nothing to do (or a step is open).
  bool undo();
  bool redo();

  /// Saves to `path` atomically (the old file survives any failure) and makes it the current
  /// file: format-preserving for a document read from a file, and a new one's points in short
  /// numbers (NewDocumentNumbers::Rounded, swp/write.hpp). Returns false and sets error() when
  /// it cannot; the edits stay in memory.
  bool save(const std::string& path);

  /// Frame options and seam handling; re-evaluates everything when they change.
  const EvaluationOptions& evaluation() const { return evaluation_; }
  void set_evaluation(const EvaluationOptions& options);

  /// Background evaluation, for the viewer: an edit, undo, redo, load or option change whose
  /// re-evaluation would cost more than `work` (samples + vertices + control points, as
  /// model/caps.hpp's evaluation_work counts them) is evaluated on a worker thread. Meanwhile
  /// scene() keeps, for each object being re-evaluated, its last complete evaluation (or nothing,
  /// for a new object), and poll() installs the new ones all at once when they are done. A newer
  /// edit of the same objects supersedes the evaluation in flight (its results are dropped); an
  /// edit of other objects is evaluated at once beside it. 0 (the default) evaluates everything
  /// at once, as tests and the command line want.
  void set_background(std::int64_t work) { background_work_ = work; }
  /// Installs a finished background evaluation. Returns true when the scene changed (or the
  /// evaluation failed: error() says why, and the edits that asked for it are undone).
  bool poll();
  /// True while a background evaluation runs.
  bool evaluating() const { return job_ != nullptr; }
  /// The running evaluation's objects done out of its total, in [0, 1].
  double evaluation_progress() const { return job_ ? job_->progress() : 1.0; }
  /// The objects the running evaluation evaluates (0 when none runs).
  std::size_t evaluation_objects() const { return job_ ? job_->indices().size() : 0; }
  /// Seconds since the running evaluation (or the chain of evaluations that superseded each
  /// other) began; 0 when none runs.
  double evaluation_seconds() const;
  /// Blocks until no evaluation runs, installing it (screenshots, scripted runs, quitting).
  void finish_evaluation();
  /// True when Cancel can take the document back to what the scene shows (the evaluation came
  /// from edits, undo or redo; not from opening a file).
  bool can_cancel_evaluation() const { return job_ != nullptr && chain_revertible_; }
  /// Cancel: drops the running evaluation and takes the history back to where it was when the
  /// evaluation began (the open step cancelled, steps since undone or redone). Returns false when
  /// nothing runs or !can_cancel_evaluation().
  bool cancel_evaluation();

  /// Milliseconds spent re-evaluating (re-meshing) after the last edit, undo or redo.
  double last_remesh_ms() const { return last_remesh_ms_; }
  /// Objects re-evaluated by the last edit.
  std::size_t last_remesh_objects() const { return last_remesh_objects_; }

  /// The message of the last failure ("" after a success); the caller shows and clears it.
  const std::string& error() const { return error_; }
  void clear_error() { error_.clear(); }

 private:
  /// Brings the scene in line with `change` (at once, or in the background) and times it.
  /// `undo_count`: the history's undo steps before the change, to go back to on Cancel (none
  /// for a load or an option change, which Cancel cannot take back).
  void refresh(const Change& change, std::optional<std::size_t> undo_count = std::nullopt);
  /// The objects `change` makes stale: every object when `whole` (a structure change), else the
  /// changed objects and what depends on them, in document order.
  std::vector<int> stale_objects(const Change& change, bool whole) const;
  /// After a structure change: moves each scene entry to its object's new index (by id) and
  /// gives new objects an empty entry, so that scene() matches the document's indices.
  void align_scene();
  /// Starts evaluating `objects` in the background, superseding the running evaluation.
  void start_job(std::vector<int> objects, std::optional<std::size_t> undo_count);
  /// Cancels the open step, then undoes or redoes until the history has `undo_count` steps.
  void go_back_to(std::size_t undo_count);
  /// Cancels the running evaluation; its thread finishes aside and is joined later.
  void retire_job();
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
  ObjectId next_id_ = 1;             // ids are never reused within a session
  std::vector<ObjectId> scene_ids_;  // the object each scene entry belongs to
  std::int64_t background_work_ = 0;
  std::unique_ptr<EvaluationJob> job_;
  std::vector<std::unique_ptr<EvaluationJob>> retired_;  // cancelled, their threads finishing
  std::chrono::steady_clock::time_point chain_start_;
  std::size_t chain_undo_count_ = 0;  // the history's undo steps when the chain began
  bool chain_revertible_ = false;
  bool history_noticed_ = false;
  std::uint64_t revision_ = 0;
};

}  // namespace sweep::editor
