#include "io/files/atomic_file.hpp"

#include "io/files/file_faults.hpp"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <random>
#include <stdexcept>
#include <string>

#include <fcntl.h>
#include <unistd.h>

namespace sweep::io {
namespace {

using file_faults_detail::fail_call;

/// The temporary file under a stdio stream (fopencookie), so that each write the stream makes is
/// one counted call that a test can fail.
struct Sink {
  int fd = -1;
  int error = 0;      // the errno of the first failed write
  off_t written = 0;  // bytes written so far
  off_t flushed = 0;  // bytes whose writeback has been started
};

/// Bytes between starts of writeback: a large file goes to the disk while it is being made, so
/// the fsync before the rename waits only for the last few MB (it waited 135-165 ms for the
/// 174 MB of OBJ of weird.swp at ten times its STEPS, on one core whatever --threads said).
constexpr off_t kWritebackBytes = off_t{8} << 20;

/// Starts writeback of what was written since the last start (sync_file_range: asynchronous, a
/// hint; the fsync still makes the file durable). Errors are left to the fsync.
void start_writeback(Sink& sink) {
  if (sink.written - sink.flushed < kWritebackBytes) return;
  ::sync_file_range(sink.fd, sink.flushed, sink.written - sink.flushed, SYNC_FILE_RANGE_WRITE);
  sink.flushed = sink.written;
}

ssize_t sink_write(void* cookie, const char* data, std::size_t size) {
  Sink& sink = *static_cast<Sink*>(cookie);
  if (fail_call(FileCall::Write)) {
    sink.error = errno;
    return 0;  // stdio's error indicator: the stream's writes fail from here on
  }
  for (std::size_t done = 0; done < size;) {
    const ssize_t n = ::write(sink.fd, data + done, size - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) {
      sink.error = n < 0 ? errno : EIO;
      return 0;
    }
    done += static_cast<std::size_t>(n);
  }
  sink.written += static_cast<off_t>(size);
  start_writeback(sink);
  return static_cast<ssize_t>(size);
}

std::runtime_error file_error(const std::filesystem::path& path, const std::string& what, int err) {
  return std::runtime_error("cannot write " + path.string() + ": " + what +
                            (err ? std::string(": ") + std::strerror(err) : ""));
}

}  // namespace

void write_file_atomically(const std::filesystem::path& path, const std::function<bool(std::FILE*)>& write) {
  // The temporary lives in the target's folder so the rename never crosses file systems.
  std::random_device random;
  const std::filesystem::path temp =
      path.string() + ".tmp-" + std::to_string(random() % 1000000) + "-" + std::to_string(::getpid());
  const int fd = fail_call(FileCall::Create) ? -1 : ::open(temp.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) throw file_error(path, "cannot create a temporary file beside it", errno);
  Sink sink{fd, 0, 0, 0};
  std::FILE* file = ::fopencookie(&sink, "wb", cookie_io_functions_t{nullptr, sink_write, nullptr, nullptr});
  if (!file) {
    const int err = errno;
    ::close(fd);
    ::unlink(temp.c_str());
    throw file_error(path, "cannot open the temporary file", err);
  }
  bool ok = false;
  int err = 0;
  try {
    ok = write(file) && std::fflush(file) == 0;
    if (!ok) err = sink.error != 0 ? sink.error : errno;
  } catch (...) {
    std::fclose(file);
    ::close(fd);
    ::unlink(temp.c_str());
    throw;
  }
  std::fclose(file);  // the stream only: it has no close of its own, the descriptor is closed below
  if (ok && (fail_call(FileCall::Sync) || ::fsync(fd) != 0)) {
    ok = false;
    err = errno;
  }
  // A close that fails (NFS reports a failed write here) fails the save; the descriptor is gone.
  const int close_error = fail_call(FileCall::Close) ? errno : 0;
  if (::close(fd) != 0 && ok && close_error == 0) {
    ok = false;
    err = errno;
  }
  if (ok && close_error != 0) {
    ok = false;
    err = close_error;
  }
  if (!ok) {
    ::unlink(temp.c_str());
    throw file_error(path, "writing failed", err);
  }
  if (fail_call(FileCall::Rename) || std::rename(temp.c_str(), path.c_str()) != 0) {
    err = errno;
    ::unlink(temp.c_str());
    throw file_error(path, "cannot rename the temporary file over it", err);
  }
}

void write_file_atomically(const std::filesystem::path& path, std::string_view contents) {
  write_file_atomically(path, [&](std::FILE* f) {
    // In 64 KB writes: the kernel takes them several times faster than one write of a big file
    // (166 MB of STL: 0.63 s in one write, 0.13 s in 64 KB ones).
    constexpr std::size_t kChunk = 64 * 1024;
    for (std::size_t at = 0; at < contents.size(); at += kChunk) {
      const std::size_t n = std::min(kChunk, contents.size() - at);
      if (std::fwrite(contents.data() + at, 1, n, f) != n) return false;
    }
    return true;
  });
}

}  // namespace sweep::io
