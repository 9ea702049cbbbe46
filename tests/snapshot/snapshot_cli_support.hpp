#pragma once
// The real `sweep snapshot` run from a test: a folder of starter models, the command with its
// exit status and output, a control point moved, and the HTML report driven in headless chromium.
#include "support/file_support.hpp"
#include "support/text_support.hpp"

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

namespace sweep::test {

namespace fs = std::filesystem;

struct Outcome {
  int status = -1;
  std::string out;
  std::string err;
};

/// `sweep snapshot ARGS` (run from `dir`, with the environment assignments `env` such as
/// "GALLIUM_DRIVER=softpipe"), its exit status, stdout and stderr.
inline Outcome snapshot(const fs::path& dir, const std::string& args, const std::string& env = "") {
  const std::string command = "cd " + quoted(dir) + " && " + env + " " + quoted(SWEEP_EXECUTABLE) + " snapshot " +
                              args + " >" + quoted(dir / "run.out") + " 2>" + quoted(dir / "run.err");
  const int raw = std::system(command.c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, read_file(dir / "run.out"), read_file(dir / "run.err")};
}

/// A fresh folder `models` with three starter files.
inline fs::path fresh_models(const std::string& test) {
  const fs::path dir = fs::path(SWEEP_TEST_OUTPUT_DIR) / test;
  fs::remove_all(dir);
  fs::create_directories(dir / "models" / "more");
  for (const char* stem : {"wineglass", "circles"}) {
    fs::copy_file(fs::path(SWEEP_SWP_DIR) / (std::string(stem) + ".swp"),
                  dir / "models" / (std::string(stem) + ".swp"));
  }
  fs::copy_file(fs::path(SWEEP_SWP_DIR) / "tor.swp", dir / "models" / "more" / "tor.swp");
  return dir;
}

/// The lines of `text` that start with `prefix`.
inline std::vector<std::string> lines_starting(const std::string& text, const std::string& prefix) {
  std::vector<std::string> out;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind(prefix, 0) == 0) out.push_back(line);
  }
  return out;
}

/// Moves one control point of the wineglass's outer wall by 0.05 in x (1% of the glass's size).
inline void move_outer_wall_point(const fs::path& file) {
  std::string text = read_file(file);
  const std::string point = "[-1.164785 1.105511]";
  ASSERT_NE(text.find(point), std::string::npos);
  text.replace(text.find(point), point.size(), "[-1.214785 1.105511]");
  write_text(file, text);
}

/// The report of a real run in headless chromium: its self-test (#selftest) loads every image and
/// moves a slider.
inline void expect_report_works_in_a_browser(const fs::path& report) {
  if (!fs::exists("/usr/bin/chromium")) return;  // scripts/install-deps.sh installs it; tested in report_test too
  const std::string command =
      "timeout 60 /usr/bin/chromium --headless --no-sandbox --disable-gpu --no-first-run "
      "--user-data-dir=" +
      quoted(report / "profile") + " --virtual-time-budget=5000 --dump-dom " +
      test::quoted(fs::path("file://" + (report / "index.html").string() + "#selftest")) + " >" +
      quoted(report / "dom.html") + " 2>" + quoted(report / "chromium.log");
  ASSERT_EQ(std::system(command.c_str()), 0) << read_file(report / "chromium.log");
  const std::string dom = read_file(report / "dom.html");
  const std::size_t at = dom.find("data-selftest=\"images ");
  ASSERT_NE(at, std::string::npos) << dom.substr(0, 2000);
  const std::string result = dom.substr(at + 15, dom.find('"', at + 15) - at - 15);
  const std::size_t slash = result.find('/');
  const std::string loaded = result.substr(7, slash - 7);
  EXPECT_EQ(result.rfind("images " + loaded + "/" + loaded + " loaded; slider ok", 0), 0u) << result;
}

}  // namespace sweep::test
