#pragma once
// The system calls an atomic write makes (io/files/atomic_file.cpp), counted and, in tests, made to
// fail: SQLite-style fault injection. Every output Sweep writes (SWP save, recovery copies, OBJ
// with its MTL and images, STL, glb, PNG, the recent-files and window-layout stores) goes
// through write_file_atomically, so failing its k-th write, fsync, close or rename for every k
// an output makes shows that no failure leaves a partial file or a temporary behind
// (tests/io/files/write_failure_test.cpp and its siblings in desktop, editor and render).
#include <cstdint>

namespace sweep::io {

/// The calls an atomic write makes, in the order it makes them.
enum class FileCall : std::uint8_t { Create, Write, Sync, Close, Rename };
inline constexpr int kFileCallCount = 5;

/// How many calls of each kind were made since the last reset_file_calls() (all threads).
std::int64_t file_calls(FileCall call);
void reset_file_calls();

/// Test hook: the `nth` call of `call` (counting from 1 after this) fails with `error` (an errno
/// value such as ENOSPC), once; the other calls run. Destroying it removes the fault.
/// Precondition: nth >= 1, error != 0; one fault at a time.
class ScopedFileFault {
 public:
  ScopedFileFault(FileCall call, std::int64_t nth, int error);
  ~ScopedFileFault();
  ScopedFileFault(const ScopedFileFault&) = delete;
  ScopedFileFault& operator=(const ScopedFileFault&) = delete;
  /// True once the fault has been injected.
  bool injected() const;
};

namespace file_faults_detail {
/// Counts a call and says whether to fail it (then errno is set). For io/files/atomic_file.cpp.
bool fail_call(FileCall call);
}  // namespace file_faults_detail

}  // namespace sweep::io
