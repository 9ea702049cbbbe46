#pragma once
// The properties the SWP fuzzer checks on every input, shared by the libFuzzer harness and the
// ctest test that replays tests/data/fuzz-regressions/ (so a crash input stays a test forever).
#include <cstdint>
#include <string>
#include <string_view>

namespace sweep::fuzz {

/// Work bounds of one fuzz input. Documents within the caps of core/limits.hpp can still ask for
/// millions of samples, which is linear work but too slow for thousands of executions a second;
/// those documents are parsed and round-tripped but not evaluated.
inline constexpr std::int64_t kMaxFuzzCurveSamples = 200'000;
inline constexpr std::int64_t kMaxFuzzMeshVertices = 400'000;
/// Meshes up to this size are also turned into OBJ text and read back.
inline constexpr std::size_t kMaxFuzzObjVertices = 20'000;

/// Runs every check on `bytes` as SWP text:
///  - parse_swp either succeeds or throws ParseError with a line >= 1 (no other exception);
///  - parse_swp(write_swp(doc)) == doc and validate_document(doc) accepts it;
///  - evaluate_document, with projection and with rotation-minimizing frames, gives one entry
///    per object, curve frames finite and right-handed orthonormal, meshes finite with every
///    index in range and exactly the vertex and triangle counts the curves' samples imply;
///  - obj_text of a small mesh has one v/vn line per vertex, one f line per triangle, all finite.
/// Returns an empty string if all hold, otherwise a description of the first violation.
/// Memory errors and undefined behaviour are left to the sanitizers.
std::string check_swp_input(std::string_view bytes);

}  // namespace sweep::fuzz
