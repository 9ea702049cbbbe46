// A dialog program (zenity, kdialog) run as a child process: its stdout is the chosen path, its
// exit status says whether one was chosen.
#include "desktop/chooser_backends.hpp"

#include <fcntl.h>
#include <poll.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>
#include <array>
#include <cerrno>
#include <csignal>
#include <cstring>

extern char** environ;

namespace sweep::editor {
namespace {

/// Enough for any path a dialog prints; more is not read (and the path is refused as too long).
constexpr std::size_t kMaxOutput = 1 << 16;

struct Pipe {
  int read = -1;
  int write = -1;
  bool open() {
    int ends[2];
    if (::pipe2(ends, O_CLOEXEC) != 0) return false;
    read = ends[0];
    write = ends[1];
    return true;
  }
  ~Pipe() {
    if (read >= 0) ::close(read);
    if (write >= 0) ::close(write);
  }
};

/// Reads both pipes until the child closes them (output capped at kMaxOutput each).
void read_all(int out_fd, int err_fd, std::string& out, std::string& err) {
  std::array<pollfd, 2> fds{{{out_fd, POLLIN, 0}, {err_fd, POLLIN, 0}}};
  std::array<std::string*, 2> texts{&out, &err};
  int open = 2;
  char buffer[4096];
  while (open > 0) {
    if (::poll(fds.data(), fds.size(), -1) < 0) {
      if (errno == EINTR) continue;
      return;
    }
    for (std::size_t i = 0; i < fds.size(); ++i) {
      if (fds[i].fd < 0 || fds[i].revents == 0) continue;
      const ssize_t n = ::read(fds[i].fd, buffer, sizeof buffer);
      if (n > 0) {
        if (texts[i]->size() < kMaxOutput) texts[i]->append(buffer, static_cast<std::size_t>(n));
      } else if (n == 0 || errno != EINTR) {
        fds[i].fd = -1;
        --open;
      }
    }
  }
}

int wait_exit(pid_t child) {
  int status = 0;
  while (::waitpid(child, &status, 0) < 0) {
    if (errno != EINTR) return -1;
  }
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

}  // namespace

ChooserResult run_command_chooser(const std::vector<std::string>& argv, FileChoice::Cancel& cancel) {
  Pipe out;
  Pipe err;
  if (!out.open() || !err.open()) return command_result(argv[0], -1, "", std::strerror(errno));
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_adddup2(&actions, out.write, STDOUT_FILENO);
  posix_spawn_file_actions_adddup2(&actions, err.write, STDERR_FILENO);
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  pid_t child = 0;
  const int spawned = ::posix_spawn(&child, args[0], &actions, nullptr, args.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (spawned != 0) return command_result(argv[0], -1, "", std::strerror(spawned));
  {
    std::lock_guard<std::mutex> lock(cancel.mutex);
    cancel.child = child;
    if (cancel.requested) ::kill(child, SIGTERM);
  }
  ::close(out.write);
  ::close(err.write);
  out.write = err.write = -1;
  std::string output;
  std::string errors;
  read_all(out.read, err.read, output, errors);
  // Waits for the exit without reaping, so `child` never names a reused process id.
  siginfo_t info{};
  while (::waitid(P_PID, static_cast<id_t>(child), &info, WEXITED | WNOWAIT) < 0 && errno == EINTR) {
  }
  {
    std::lock_guard<std::mutex> lock(cancel.mutex);
    cancel.child = 0;
  }
  const int status = wait_exit(child);
  if (cancel.requested) return {};  // closed by us: nothing chosen
  return command_result(argv[0], status, output, errors);
}

}  // namespace sweep::editor
