// libFuzzer entry point: every input is a snapshot suite (docs/snapshot-suite.md) run through
// sweep::fuzz::check_suite_input against a small models folder made once per process (with
// hidden files, __snapshots__ and a symlink loop). A violated property aborts with its
// description, so libFuzzer saves the input as a crash.
#include "suite_fuzz_check.hpp"

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <system_error>

namespace {

/// The models folder, removed when the process exits normally.
class FuzzModels {
 public:
  FuzzModels() : path_(std::filesystem::temp_directory_path() / ("sweep-suite-fuzz-" + std::to_string(::getpid()))) {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
    sweep::fuzz::make_suite_fuzz_models(path_);
  }
  ~FuzzModels() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  FuzzModels(const FuzzModels&) = delete;
  FuzzModels& operator=(const FuzzModels&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const FuzzModels models;
  const std::string problem =
      sweep::fuzz::check_suite_input({reinterpret_cast<const char*>(data), size}, models.path());
  if (!problem.empty()) {
    std::fprintf(stderr, "suite property violated: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
