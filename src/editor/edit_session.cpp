#include "editor/edit_session.hpp"

#include "io/swp_writer.hpp"

#include <chrono>
#include <exception>
#include <utility>

namespace sweep::editor {

void EditSession::load(Document doc, std::string path) {
  Scene scene = evaluate_document(doc, evaluation_);
  doc_ = std::move(doc);
  for (Object& object : doc_.objects) object.id = kNoObject;  // a new file: new ids
  assign_ids();
  scene_ = std::move(scene);
  file_ = std::move(path);
  history_.clear();
  error_.clear();
  ++revision_;
}

bool EditSession::edit(const std::string& label, const Operation& operation) {
  // Inside an open step (a field still active) the edit joins that step.
  if (history_.in_step()) return apply(operation);
  history_.begin(doc_, label);
  try {
    const Change change = operation(doc_);
    assign_ids();  // before the history records the step, so redo brings back the same ids
    history_.end(doc_);
    refresh(change);
    error_.clear();
    return true;
  } catch (const std::exception& e) {
    // The operations leave the document as it was when they throw; cancel() restores the
    // snapshot anyway so that an unexpected failure cannot leave half an edit behind.
    const Change restored = history_.cancel(doc_);
    if (restored.structure || !restored.objects.empty()) refresh(restored);  // keeps the last edit's timing otherwise
    error_ = e.what();
    return false;
  }
}

void EditSession::begin_step(const std::string& label) {
  // One step at a time: a second begin would nest, and nesting is not what the viewer means.
  if (!history_.in_step()) history_.begin(doc_, label);
}

bool EditSession::apply(const Operation& operation) {
  try {
    const Change change = operation(doc_);
    assign_ids();
    refresh(change);
    error_.clear();
    return true;
  } catch (const std::exception& e) {
    error_ = e.what();
    return false;
  }
}

void EditSession::end_step() {
  if (history_.in_step()) history_.end(doc_);
}

void EditSession::cancel_step() {
  if (!history_.in_step()) return;
  const Change restored = history_.cancel(doc_);
  if (restored.structure || !restored.objects.empty()) refresh(restored);
  error_.clear();
}

bool EditSession::undo() {
  if (!can_undo()) return false;
  refresh(history_.undo(doc_));
  error_.clear();
  return true;
}

bool EditSession::redo() {
  if (!can_redo()) return false;
  refresh(history_.redo(doc_));
  error_.clear();
  return true;
}

bool EditSession::save(const std::string& path) {
  if (path.empty()) {
    error_ = "save: no file name given";
    return false;
  }
  try {
    save_swp_file(path, doc_);
  } catch (const std::exception& e) {
    error_ = std::string("could not save: ") + e.what();
    return false;
  }
  file_ = path;
  history_.mark_saved();
  error_.clear();
  return true;
}

void EditSession::set_evaluation(const EvaluationOptions& options) {
  evaluation_ = options;
  refresh(Change{{}, true});
}

int EditSession::index_of(ObjectId id) const {
  if (id == kNoObject) return -1;
  for (std::size_t i = 0; i < doc_.objects.size(); ++i) {
    if (doc_.objects[i].id == id) return static_cast<int>(i);
  }
  return -1;
}

ObjectId EditSession::id_of(int index) const {
  return index >= 0 && std::size_t(index) < doc_.objects.size() ? doc_.objects[std::size_t(index)].id : kNoObject;
}

void EditSession::assign_ids() {
  for (Object& object : doc_.objects) {
    if (object.id == kNoObject) object.id = next_id_++;
  }
}

void EditSession::refresh(const Change& change) {
  ++revision_;
  const auto start = std::chrono::steady_clock::now();
  if (change.structure || scene_.objects.size() != doc_.objects.size()) {
    reevaluate_all(scene_, doc_, evaluation_);  // into the meshes' buffers (a slider drag allocates nothing)
    last_remesh_objects_ = doc_.objects.size();
  } else {
    // Each changed object with its dependents. (A dependent shared by several changed objects
    // is evaluated more than once; edits change one object, undo of a multi-object step is rare.)
    last_remesh_objects_ = 0;
    for (int index : change.objects) last_remesh_objects_ += reevaluate(scene_, doc_, index, evaluation_).size();
  }
  last_remesh_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace sweep::editor
