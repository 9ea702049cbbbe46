#pragma once
// Writing files so that readers never see half of one: write "NAME.tmp-XXXX" beside the
// target, flush, fsync, then rename over the target. On any failure the temporary is removed
// and the target is untouched.
#include <cstdio>
#include <filesystem>
#include <functional>
#include <string_view>

namespace sweep::io {

/// Calls `write(file)` on a temporary file beside `path`, then renames it over `path`.
/// `write` returns false (or throws) to abort. Throws std::runtime_error naming the path
/// and the reason ("No such file or directory", "No space left on device", ...).
void write_file_atomically(const std::filesystem::path& path, const std::function<bool(std::FILE*)>& write);

/// Convenience: writes `contents` atomically.
void write_file_atomically(const std::filesystem::path& path, std::string_view contents);

}  // namespace sweep::io
