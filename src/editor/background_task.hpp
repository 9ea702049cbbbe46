#pragma once
// Work the viewer does off its drawing thread when it would take long: parsing a large file to
// open, evaluating and writing a large export. The work runs on its own thread and returns what
// to do on the drawing thread once it is done (show the document, say what was written), so the
// viewer's state is only ever touched there. Cancel sets a flag the work may look at (an export
// then writes nothing) and drops the result.
#include <atomic>
#include <chrono>
#include <functional>
#include <memory>
#include <string>
#include <thread>

namespace sweep::editor {

class BackgroundTask {
 public:
  /// What to do on the drawing thread when the work is done.
  using Finish = std::function<void()>;
  /// The work: runs on the task's thread; `cancelled` turns true when the user cancels.
  using Work = std::function<Finish(const std::atomic<bool>& cancelled)>;

  /// Starts `work` on a new thread at low priority; `label` says what it does ("Opening x.swp").
  /// Precondition: `work` catches what it throws and returns a Finish that reports it.
  BackgroundTask(std::string label, Work work);
  /// Cancels and waits for the thread.
  ~BackgroundTask();
  BackgroundTask(const BackgroundTask&) = delete;
  BackgroundTask& operator=(const BackgroundTask&) = delete;

  bool finished() const;
  void wait();
  void cancel();
  bool cancelled() const;
  const std::string& label() const { return label_; }
  double seconds() const;
  /// The work's Finish (nothing when cancelled). Precondition: finished(); called once.
  Finish take();

 private:
  struct Shared;
  std::string label_;
  std::chrono::steady_clock::time_point start_;
  std::shared_ptr<Shared> shared_;
  std::thread thread_;
};

}  // namespace sweep::editor
