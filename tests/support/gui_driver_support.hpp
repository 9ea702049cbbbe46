#pragma once
// Running a tests/app/*_gui_driver.sh script against the real viewer under Xvfb: whether the
// machine can, a fresh folder per test, and the one command line every GUI test uses (recovery
// copies, recent files and the window layout kept in that folder, a timeout so a run can never
// hang the suite, stdout and stderr in driver.out and driver.err).
#include "support/file_support.hpp"
#include "support/text_support.hpp"

#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

namespace sweep::test {

/// True when xvfb-run and xdotool are installed (else the GUI tests skip).
inline bool can_drive_window() {
  return std::system("command -v xvfb-run >/dev/null 2>&1 && command -v xdotool >/dev/null 2>&1") == 0;
}

/// `base`/NAME for the running test, emptied and made.
inline std::filesystem::path fresh_test_folder(const std::filesystem::path& base, const std::string& name) {
  const std::filesystem::path dir = base / name;
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// Runs `driver` SWEEP FILE OBJECT DIR under xvfb-run (a 1280x800 screen) with `env` ("NAME=value "
/// words, may be empty) and the viewer's state and config folders in `dir`, for at most
/// `seconds`. Expects exit status 0 (reporting what the driver printed otherwise) and returns its
/// stdout.
inline std::string run_gui_driver(const std::string& env, const std::filesystem::path& driver,
                                  const std::filesystem::path& file, const std::string& object,
                                  const std::filesystem::path& dir, int seconds = 90) {
  const std::string command = env + " XDG_STATE_HOME=" + quoted(dir / "state") +
                              " XDG_CONFIG_HOME=" + quoted(dir / "config") + " timeout " + std::to_string(seconds) +
                              " xvfb-run -a -s '-screen 0 1280x800x24' bash " + quoted(driver) + " " +
                              quoted(SWEEP_EXECUTABLE) + " " + quoted(file) + " '" + object + "' " + quoted(dir) +
                              " >" + quoted(dir / "driver.out") + " 2>" + quoted(dir / "driver.err");
  const int status = std::system(command.c_str());
  const std::string out = read_file(dir / "driver.out");
  EXPECT_EQ(status, 0) << out << read_file(dir / "driver.err");
  return out;
}

}  // namespace sweep::test
