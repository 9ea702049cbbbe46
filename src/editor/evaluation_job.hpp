#pragma once
// One evaluation of some objects of a document on a worker thread, so that the viewer keeps
// drawing and answering while a large re-mesh runs (a subdivision level, a big file). The job
// owns copies of everything it reads; its results are complete objects or nothing: a job
// cancelled (superseded by a newer edit) gives nothing, so nothing half-built is ever shown.
#include "model/document.hpp"
#include "model/evaluation/scene.hpp"

#include <memory>
#include <string>
#include <thread>
#include <vector>

namespace sweep::editor {

class EvaluationJob {
 public:
  /// Starts evaluating the objects `indices` of `doc` on a new thread at low priority. `base`
  /// holds the evaluated entries of the objects they refer to (the others may be empty).
  /// Precondition: as evaluate_objects (model/evaluation/scene.hpp), with `base` sized as `doc`.
  EvaluationJob(Document doc, Scene base, std::vector<int> indices, const EvaluationOptions& options);
  /// Cancels the job and waits for its thread (at most the object it is evaluating).
  ~EvaluationJob();
  EvaluationJob(const EvaluationJob&) = delete;
  EvaluationJob& operator=(const EvaluationJob&) = delete;

  /// True once the thread has finished (completed, cancelled or failed).
  bool finished() const;
  /// Blocks until finished().
  void wait();
  /// Asks the thread to stop before its next object; its results are then dropped.
  void cancel();
  /// Objects done out of the total, in [0, 1].
  double progress() const;
  const std::vector<int>& indices() const { return indices_; }

  /// The evaluated objects, in the order of indices(); empty when the job was cancelled or
  /// evaluation threw (error() says what). Precondition: finished(); called once.
  std::vector<EvaluatedObject> take();
  /// What evaluation threw ("" if nothing). Precondition: finished().
  const std::string& error() const;

 private:
  struct Work;  // what the thread owns; shared so the thread never outlives what it writes
  std::vector<int> indices_;
  std::shared_ptr<Work> work_;
  std::thread thread_;
};

}  // namespace sweep::editor
