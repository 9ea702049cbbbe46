#include "editor/background_task.hpp"

#include "base/precondition.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <condition_variable>
#include <exception>
#include <mutex>
#include <utility>

namespace sweep::editor {

struct BackgroundTask::Shared {
  std::atomic<bool> cancelled{false};
  std::mutex mutex;
  std::condition_variable done;
  bool finished = false;  // under mutex
  Finish finish;
};

BackgroundTask::BackgroundTask(std::string label, Work work)
    : label_(std::move(label)), start_(std::chrono::steady_clock::now()), shared_(std::make_shared<Shared>()) {
  thread_ = std::thread([shared = shared_, work = std::move(work)] {
    setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), 10);  // the drawing thread comes first
    Finish finish;
    try {
      finish = work(shared->cancelled);
    } catch (const std::exception&) {
      // A broken precondition: the work reports its own failures. Nothing to do then.
    }
    const std::lock_guard lock(shared->mutex);
    shared->finish = std::move(finish);
    shared->finished = true;
    shared->done.notify_all();
  });
}

BackgroundTask::~BackgroundTask() {
  cancel();
  if (thread_.joinable()) thread_.join();
}

bool BackgroundTask::finished() const {
  const std::lock_guard lock(shared_->mutex);
  return shared_->finished;
}

void BackgroundTask::wait() {
  std::unique_lock lock(shared_->mutex);
  shared_->done.wait(lock, [this] { return shared_->finished; });
}

void BackgroundTask::cancel() {
  shared_->cancelled.store(true);
}

bool BackgroundTask::cancelled() const {
  return shared_->cancelled.load();
}

double BackgroundTask::seconds() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
}

BackgroundTask::Finish BackgroundTask::take() {
  SWEEP_EXPECTS(finished(), "the task has finished");
  if (cancelled()) return {};
  const std::lock_guard lock(shared_->mutex);
  return std::move(shared_->finish);
}

}  // namespace sweep::editor
