// libFuzzer entry point: every input is SWP text run through sweep::fuzz::check_swp_input.
// A violated property aborts with its description, so libFuzzer saves the input as a crash.
#include "swp_fuzz_check.hpp"

#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem = sweep::fuzz::check_swp_input({reinterpret_cast<const char*>(data), size});
  if (!problem.empty()) {
    std::fprintf(stderr, "SWP property violated: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
