#pragma once
// Writing a Document back to SWP text that the original format reads.
#include "model/document.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace sweep {

/// SWP text for a document; numbers are written in shortest round-trip form, so
/// parse_swp(write_swp(doc)) == doc. If `first_lines` is given it receives the 1-based line on
/// which each object starts.
std::string write_swp(const Document& doc, std::vector<int>* first_lines = nullptr);

/// Writes write_swp(doc) to `path` through a temporary file and a rename, so the old file
/// survives any failure. Throws std::runtime_error with a clear message.
void save_swp_file(const std::filesystem::path& path, const Document& doc);

}  // namespace sweep
