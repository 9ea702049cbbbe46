#include "io/files/file_faults.hpp"

#include "base/precondition.hpp"

#include <array>
#include <atomic>
#include <cerrno>

namespace sweep::io {
namespace {

std::array<std::atomic<std::int64_t>, kFileCallCount> calls{};

// The fault: which call, at which count of it, with which errno (0: none armed).
std::atomic<int> fault_call{0};
std::atomic<std::int64_t> fault_at{0};
std::atomic<int> fault_error{0};
std::atomic<bool> fault_injected{false};

std::size_t slot(FileCall call) {
  return static_cast<std::size_t>(call);
}

}  // namespace

std::int64_t file_calls(FileCall call) {
  return calls[slot(call)].load();
}

void reset_file_calls() {
  for (auto& count : calls) count.store(0);
}

ScopedFileFault::ScopedFileFault(FileCall call, std::int64_t nth, int error) {
  SWEEP_EXPECTS(nth >= 1 && error != 0, "nth >= 1, error != 0");
  SWEEP_EXPECTS(fault_error.load() == 0, "one fault at a time");
  fault_injected.store(false);
  fault_call.store(static_cast<int>(call));
  fault_at.store(file_calls(call) + nth);
  fault_error.store(error);
}

ScopedFileFault::~ScopedFileFault() {
  fault_error.store(0);
}

bool ScopedFileFault::injected() const {
  return fault_injected.load();
}

namespace file_faults_detail {

bool fail_call(FileCall call) {
  const std::int64_t count = ++calls[slot(call)];
  const int error = fault_error.load();
  if (error == 0 || fault_call.load() != static_cast<int>(call) || count != fault_at.load()) return false;
  fault_injected.store(true);
  errno = error;
  return true;
}

}  // namespace file_faults_detail
}  // namespace sweep::io
