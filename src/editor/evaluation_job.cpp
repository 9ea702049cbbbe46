#include "editor/evaluation_job.hpp"

#include "base/precondition.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <condition_variable>
#include <exception>
#include <mutex>
#include <string>
#include <utility>

namespace sweep::editor {

struct EvaluationJob::Work {
  Document doc;
  Scene scene;
  EvaluationOptions options;
  EvaluationProgress progress;
  std::mutex mutex;
  std::condition_variable finished_signal;
  bool finished = false;  // under mutex
  bool complete = false;  // evaluated every object (not cancelled, nothing thrown)
  std::string error;
};

namespace {

/// The drawing thread comes first: the worker yields the CPU to it (Linux: a thread's nice value).
void lower_priority() {
  setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), 10);
}

}  // namespace

EvaluationJob::EvaluationJob(Document doc, Scene base, std::vector<int> indices, const EvaluationOptions& options)
    : indices_(std::move(indices)), work_(std::make_shared<Work>()) {
  SWEEP_EXPECTS(base.objects.size() == doc.objects.size(), "base is sized as doc");
  work_->doc = std::move(doc);
  work_->scene = std::move(base);
  work_->options = options;
  thread_ = std::thread([work = work_, indices = indices_] {
    lower_priority();
    bool complete = false;
    std::string error;
    try {
      complete = evaluate_objects(work->scene, work->doc, indices, work->options, &work->progress);
    } catch (const std::exception& e) {
      error = e.what();  // e.g. std::bad_alloc: the scene keeps what it had
    }
    const std::lock_guard lock(work->mutex);
    work->complete = complete;
    work->error = std::move(error);
    work->finished = true;
    work->finished_signal.notify_all();
  });
}

EvaluationJob::~EvaluationJob() {
  cancel();
  if (thread_.joinable()) thread_.join();
}

bool EvaluationJob::finished() const {
  const std::lock_guard lock(work_->mutex);
  return work_->finished;
}

void EvaluationJob::wait() {
  std::unique_lock lock(work_->mutex);
  work_->finished_signal.wait(lock, [this] { return work_->finished; });
}

void EvaluationJob::cancel() {
  work_->progress.cancel.store(true, std::memory_order_relaxed);
}

double EvaluationJob::progress() const {
  if (indices_.empty()) return 1.0;
  return static_cast<double>(work_->progress.done.load(std::memory_order_relaxed)) /
         static_cast<double>(indices_.size());
}

std::vector<EvaluatedObject> EvaluationJob::take() {
  SWEEP_EXPECTS(finished(), "the job has finished");
  std::vector<EvaluatedObject> out;
  if (!work_->complete) return out;
  out.reserve(indices_.size());
  for (const int i : indices_) out.push_back(std::move(work_->scene.objects[static_cast<std::size_t>(i)]));
  return out;
}

const std::string& EvaluationJob::error() const {
  SWEEP_EXPECTS(finished(), "the job has finished");
  return work_->error;
}

}  // namespace sweep::editor
