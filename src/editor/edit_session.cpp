#include "editor/edit_session.hpp"

#include "io/swp/write.hpp"
#include "model/caps.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <numeric>
#include <unordered_map>
#include <utility>

namespace sweep::editor {

void EditSession::load(Document doc, std::string path) {
  std::vector<int> all(doc.objects.size());
  std::iota(all.begin(), all.end(), 0);
  const bool background = background_work_ > 0 && evaluation_work(doc, all) > background_work_;
  Scene scene;
  if (background) {
    scene.objects.resize(doc.objects.size());  // nothing shown until the evaluation is complete
    for (EvaluatedObject& entry : scene.objects) entry.revision = new_scene_revision();
  } else {
    scene = evaluate_document(doc, evaluation_);
  }
  retire_job();
  doc_ = std::move(doc);
  for (Object& object : doc_.objects) object.id = kNoObject;  // a new file: new ids
  assign_ids();
  scene_ = std::move(scene);
  scene_ids_.clear();
  for (const Object& object : doc_.objects) scene_ids_.push_back(object.id);
  file_ = std::move(path);
  history_.clear();
  error_.clear();
  ++revision_;
  if (background) start_job(std::move(all), std::nullopt);
}

bool EditSession::edit(const std::string& label, const Operation& operation) {
  // Inside an open step (a field still active) the edit joins that step.
  if (history_.in_step()) return apply(operation);
  history_.begin(doc_, label);
  const std::size_t undo_count = history_.undo_count();
  try {
    const Change change = operation(doc_);
    assign_ids();  // before the history records the step, so redo brings back the same ids
    history_.end(doc_);
    refresh(change, undo_count);
    error_.clear();
    return true;
  } catch (const std::exception& e) {
    // The operations leave the document as it was when they throw; cancel() restores the
    // snapshot anyway so that an unexpected failure cannot leave half an edit behind.
    const Change restored = history_.cancel(doc_);
    if (restored.structure || !restored.objects.empty())
      refresh(restored, undo_count);  // keeps the last edit's timing otherwise
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
    refresh(change, history_.undo_count());
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
  if (restored.structure || !restored.objects.empty()) refresh(restored, history_.undo_count());
  error_.clear();
}

bool EditSession::undo() {
  if (!can_undo()) return false;
  const std::size_t undo_count = history_.undo_count();
  refresh(history_.undo(doc_), undo_count);
  error_.clear();
  return true;
}

bool EditSession::redo() {
  if (!can_redo()) return false;
  const std::size_t undo_count = history_.undo_count();
  refresh(history_.redo(doc_), undo_count);
  error_.clear();
  return true;
}

bool EditSession::save(const std::string& path) {
  if (path.empty()) {
    error_ = "save: no file name given";
    return false;
  }
  try {
    io::save_swp_file(path, doc_, io::NewDocumentNumbers::Rounded);  // a new document's points: short numbers
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

bool EditSession::take_history_notice() {
  if (history_noticed_ || history_.forgotten() == 0) return false;
  history_noticed_ = true;
  return true;
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

void EditSession::refresh(const Change& change, std::optional<std::size_t> undo_count) {
  ++revision_;
  const auto start = std::chrono::steady_clock::now();
  const bool whole = change.structure || scene_.objects.size() != doc_.objects.size();
  if (whole) align_scene();
  std::vector<int> objects = stale_objects(change, whole);
  // The evaluation in flight goes on beside a small edit of other objects (which, disjoint from
  // it, neither use nor are used by its objects); any other edit supersedes it.
  const auto large = [this](const std::vector<int>& some) {
    return background_work_ > 0 && evaluation_work(doc_, some) > background_work_;
  };
  bool beside = job_ != nullptr && !whole;
  if (job_) {
    const std::vector<int>& running = job_->indices();
    for (const int i : objects) beside = beside && !std::binary_search(running.begin(), running.end(), i);
    if (beside && large(objects)) beside = false;
    if (!beside) {
      std::vector<int> both;
      std::set_union(objects.begin(), objects.end(), running.begin(), running.end(), std::back_inserter(both));
      objects = std::move(both);
    }
  }
  if (!beside && large(objects)) {
    start_job(std::move(objects), undo_count);
    return;
  }
  if (!beside) retire_job();
  evaluate_objects(scene_, doc_, objects, evaluation_);
  last_remesh_objects_ = objects.size();
  last_remesh_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

std::vector<int> EditSession::stale_objects(const Change& change, bool whole) const {
  std::vector<int> objects;
  if (whole) {
    objects.resize(doc_.objects.size());
    std::iota(objects.begin(), objects.end(), 0);
    return objects;
  }
  for (const int index : change.objects) {
    const std::vector<int> dependents = dependents_of(doc_, index);
    objects.insert(objects.end(), dependents.begin(), dependents.end());
  }
  std::sort(objects.begin(), objects.end());
  objects.erase(std::unique(objects.begin(), objects.end()), objects.end());
  return objects;
}

void EditSession::align_scene() {
  std::unordered_map<ObjectId, std::size_t> entry_of;
  for (std::size_t k = 0; k < scene_ids_.size() && k < scene_.objects.size(); ++k) entry_of[scene_ids_[k]] = k;
  std::vector<EvaluatedObject> aligned(doc_.objects.size());
  scene_ids_.assign(doc_.objects.size(), kNoObject);
  for (std::size_t i = 0; i < doc_.objects.size(); ++i) {
    scene_ids_[i] = doc_.objects[i].id;
    const auto found = entry_of.find(doc_.objects[i].id);
    if (found != entry_of.end()) {
      aligned[i] = std::move(scene_.objects[found->second]);  // its buffers, and its last evaluation meanwhile
    } else {
      aligned[i].revision = new_scene_revision();  // a new object: nothing until evaluated
    }
  }
  scene_.objects = std::move(aligned);
}

void EditSession::start_job(std::vector<int> objects, std::optional<std::size_t> undo_count) {
  if (!job_) {
    chain_start_ = std::chrono::steady_clock::now();
    chain_revertible_ = undo_count.has_value();
    chain_undo_count_ = undo_count.value_or(0);
  }
  retire_job();
  // The job reads the objects it evaluates and the entries of those they refer to, which no
  // running evaluation touches (they would be among `objects` otherwise).
  std::vector<bool> evaluated(doc_.objects.size(), false);
  for (const int i : objects) evaluated[static_cast<std::size_t>(i)] = true;
  Scene base;
  base.objects.resize(doc_.objects.size());
  for (const int i : objects) {
    for (const int r : references(doc_.objects[static_cast<std::size_t>(i)])) {
      if (r >= 0 && !evaluated[static_cast<std::size_t>(r)])
        base.objects[std::size_t(r)] = scene_.objects[std::size_t(r)];
    }
  }
  job_ = std::make_unique<EvaluationJob>(doc_, std::move(base), std::move(objects), evaluation_);
}

void EditSession::retire_job() {
  if (!job_) return;
  job_->cancel();
  retired_.push_back(std::move(job_));
}

bool EditSession::poll() {
  std::erase_if(retired_, [](const std::unique_ptr<EvaluationJob>& job) { return job->finished(); });
  if (!job_ || !job_->finished()) return false;
  const std::unique_ptr<EvaluationJob> job = std::move(job_);
  std::vector<EvaluatedObject> results = job->take();
  if (results.size() != job->indices().size()) {
    // As a failed edit: the history goes back to what the scene shows, and the user is told.
    const std::string message = "could not evaluate the document: " + job->error();
    if (chain_revertible_) go_back_to(chain_undo_count_);
    error_ = message;
    return true;
  }
  for (std::size_t k = 0; k < results.size(); ++k) {
    scene_.objects[static_cast<std::size_t>(job->indices()[k])] = std::move(results[k]);
  }
  last_remesh_objects_ = results.size();
  last_remesh_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - chain_start_).count();
  ++revision_;
  return true;
}

double EditSession::evaluation_seconds() const {
  if (!job_) return 0.0;
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - chain_start_).count();
}

void EditSession::finish_evaluation() {
  while (job_) {
    job_->wait();
    poll();
  }
}

bool EditSession::cancel_evaluation() {
  if (!can_cancel_evaluation()) return false;
  // The running job stays until the first refresh below supersedes it, so that every object it
  // was evaluating is evaluated again for the document as it is after going back.
  go_back_to(chain_undo_count_);
  if (job_) {  // nothing to go back through (e.g. the steps were forgotten): drop its results
    retire_job();
  }
  return true;
}

void EditSession::go_back_to(std::size_t undo_count) {
  cancel_step();
  while (history_.undo_count() > undo_count && undo()) {
  }
  while (history_.undo_count() < undo_count && redo()) {
  }
}

}  // namespace sweep::editor
