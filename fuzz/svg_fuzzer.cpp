// libFuzzer entry point: every input is SVG text run through sweep::fuzz::check_svg_input.
// A violated property aborts with its description, so libFuzzer saves the input as a crash.
#include "svg_fuzz_check.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string problem = sweep::fuzz::check_svg_input({reinterpret_cast<const char*>(data), size});
  if (!problem.empty()) {
    std::fprintf(stderr, "SVG property violated: %s\n", problem.c_str());
    std::abort();
  }
  return 0;
}
