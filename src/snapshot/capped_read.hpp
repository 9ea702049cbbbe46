#pragma once
// Reading a file that the run wrote before (a sidecar, a results file) with a cap on its size,
// so a wrong or hostile file never eats memory.
#include <cstdint>
#include <filesystem>
#include <string>

namespace sweep::snapshot {

/// The bytes of `file`. Throws std::runtime_error "FILE: cannot read: REASON" or "FILE: larger
/// than N MiB, not WHAT" (`what` such as "a sidecar").
std::string read_capped(const std::filesystem::path& file, std::uintmax_t max_bytes, const std::string& what);

}  // namespace sweep::snapshot
