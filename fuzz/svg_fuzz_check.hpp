#pragma once
// The properties the SVG fuzzer checks on every input, shared by the libFuzzer harness
// (svg_fuzzer.cpp) and the ctest test that replays the SVG seeds and regressions.
#include <string>
#include <string_view>

namespace sweep::fuzz {

/// Runs every check on `bytes` as an SVG drawing (parse_svg_drawing, io/svg/import.hpp):
///  - it either succeeds or throws ImportError whose message is one line starting "fuzz.svg:"
///    (no other exception);
///  - an imported document has at least one curve, every one a bez2 with 3k + 1 >= 4 finite
///    points and a valid, unique name;
///  - the SWP text of it reads back equal (parse_swp(write_swp(doc)) == doc).
/// Returns an empty string if all hold, otherwise a description of the first violation. Memory
/// errors and undefined behaviour are left to the sanitizers.
std::string check_svg_input(std::string_view bytes);

}  // namespace sweep::fuzz
