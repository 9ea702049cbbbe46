// Undo history. A step is either a list of (index, before, after) objects, when the document
// kept its object count, or two whole documents, when objects were added or removed. Every step
// gets a new id; the state after a step is named by its id (0: the state before any step), so
// "saved" is one id and a state is clean exactly when its id is the saved one. A step discarded
// from the redo list takes its id with it, so a state it led to can never become clean again
// unless saved anew.
#include "model/edit/history.hpp"

#include "base/precondition.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace sweep {
namespace {

/// What differs between two documents with the same object count: the indices of the objects
/// that are not == (Object::operator== ignores source locations).
std::vector<int> changed_objects(const Document& a, const Document& b) {
  std::vector<int> changed;
  for (std::size_t i = 0; i < a.objects.size(); ++i) {
    if (!(a.objects[i] == b.objects[i])) changed.push_back(static_cast<int>(i));
  }
  return changed;
}

std::int64_t cost_of(const Object& object) {
  return 1 + static_cast<std::int64_t>(points_of(object).size());
}

std::int64_t cost_of(const Document& doc) {
  std::int64_t cost = 0;
  for (const Object& o : doc.objects) cost += cost_of(o);
  return cost;
}

}  // namespace

std::uint64_t History::current_id() const {
  return undo_.empty() ? base_id_ : undo_.back().id;
}

void History::trim() {
  // Called after recording, when redo_ is empty. Forget the oldest undo steps; the state
  // before the new oldest one is then the base. The newest step is always kept.
  std::size_t forget = 0;
  while (undo_.size() - forget > 1 && (undo_.size() - forget > max_steps_ || stored_points_ > max_stored_points_)) {
    stored_points_ -= undo_[forget].cost;
    base_id_ = undo_[forget].id;
    ++forget;
  }
  undo_.erase(undo_.begin(), undo_.begin() + static_cast<std::ptrdiff_t>(forget));
  forgotten_ += forget;
}

void History::begin(const Document& doc, std::string label) {
  if (depth_++ > 0) return;  // nested: the outer step keeps its snapshot and label
  snapshot_ = doc;
  snapshot_label_ = std::move(label);
}

void History::end(const Document& doc) {
  if (depth_ == 0) return;  // no step open
  if (--depth_ > 0) return;
  Document before = std::move(*snapshot_);
  snapshot_.reset();
  Step step;
  step.label = std::move(snapshot_label_);
  snapshot_label_.clear();
  if (before.objects.size() == doc.objects.size()) {
    const std::vector<int> changed = changed_objects(before, doc);
    if (changed.empty()) return;
    step.objects.reserve(changed.size());
    for (int i : changed) {
      const auto k = static_cast<std::size_t>(i);
      step.cost += cost_of(before.objects[k]) + cost_of(doc.objects[k]);
      step.objects.push_back({i, std::move(before.objects[k]), doc.objects[k]});
    }
  } else {
    step.cost = cost_of(before) + cost_of(doc);
    step.before = std::move(before);
    step.after = doc;
  }
  step.id = next_id_++;
  for (const Step& discarded : redo_) stored_points_ -= discarded.cost;
  redo_.clear();
  stored_points_ += step.cost;
  undo_.push_back(std::move(step));
  trim();
}

Change History::cancel(Document& doc) {
  Change change;
  if (depth_ == 0) return change;
  depth_ = 0;
  Document before = std::move(*snapshot_);
  snapshot_.reset();
  snapshot_label_.clear();
  if (before.objects.size() == doc.objects.size()) {
    change.objects = changed_objects(before, doc);
  } else {
    change.structure = true;
  }
  doc = std::move(before);
  return change;
}

bool History::in_step() const {
  return depth_ > 0;
}

bool History::can_undo() const {
  return !undo_.empty();
}
bool History::can_redo() const {
  return !redo_.empty();
}
std::string History::undo_label() const {
  return undo_.empty() ? std::string() : undo_.back().label;
}
std::string History::redo_label() const {
  return redo_.empty() ? std::string() : redo_.back().label;
}

Change History::undo(Document& doc) {
  SWEEP_EXPECTS(undo_.empty() || std::all_of(undo_.back().objects.begin(), undo_.back().objects.end(),
                                             [&](const ObjectChange& c) {
                                               return static_cast<std::size_t>(c.index) < doc.objects.size();
                                             }),
                "`doc` is the document the steps were recorded on");
  Change change;
  if (undo_.empty() || in_step()) return change;
  Step step = std::move(undo_.back());
  undo_.pop_back();
  if (step.before) {
    doc = *step.before;
    change.structure = true;
  } else {
    for (const ObjectChange& c : step.objects) {
      doc.objects[static_cast<std::size_t>(c.index)] = c.before;
      change.objects.push_back(c.index);
    }
  }
  redo_.push_back(std::move(step));
  return change;
}

Change History::redo(Document& doc) {
  SWEEP_EXPECTS(redo_.empty() || std::all_of(redo_.back().objects.begin(), redo_.back().objects.end(),
                                             [&](const ObjectChange& c) {
                                               return static_cast<std::size_t>(c.index) < doc.objects.size();
                                             }),
                "`doc` is the document the steps were recorded on");
  Change change;
  if (redo_.empty() || in_step()) return change;
  Step step = std::move(redo_.back());
  redo_.pop_back();
  if (step.after) {
    doc = *step.after;
    change.structure = true;
  } else {
    for (const ObjectChange& c : step.objects) {
      doc.objects[static_cast<std::size_t>(c.index)] = c.after;
      change.objects.push_back(c.index);
    }
  }
  undo_.push_back(std::move(step));
  return change;
}

bool History::dirty() const {
  return current_id() != saved_id_;
}

void History::mark_saved() {
  // Saved in the middle of a step, the file holds a state that no id names yet (and that end()
  // may or may not keep): take an id no step will get, so the document counts as unsaved until
  // the next save. Conservative, never falsely clean.
  saved_id_ = in_step() ? next_id_++ : current_id();
}

void History::clear() {
  undo_.clear();
  redo_.clear();
  snapshot_.reset();
  snapshot_label_.clear();
  depth_ = 0;
  saved_id_ = 0;
  base_id_ = 0;
  stored_points_ = 0;
}

}  // namespace sweep
