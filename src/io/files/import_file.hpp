#pragma once
// What the importers (mesh/obj_import.hpp, svg/import.hpp) share: their one error type, its message
// form, and the bounded read of the file they import.
#include <filesystem>
#include <stdexcept>
#include <string>
#include <string_view>

namespace sweep::io {

/// An import that cannot be done: one line, "FILE:LINE: DETAIL" or "FILE: DETAIL".
class ImportError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// An input with nothing to import (a drawing without paths or shapes): not a mistake in it, so
/// `sweep import` says so and exits 0 as an export with nothing to write does.
class NothingToImport : public ImportError {
 public:
  using ImportError::ImportError;
};

/// Throws ImportError "FILE:LINE: DETAIL", or "FILE: DETAIL" when `line` is 0.
[[noreturn]] void import_failure(std::string_view file, int line, const std::string& detail);

/// The bytes of the file at `path`. Throws ImportError "PATH: cannot open: REASON" (a directory:
/// "cannot open: it is a directory"), "PATH: cannot read: ..." or, for a file larger than
/// limits::kMaxFileBytes, "PATH: expected WHAT of at most 512 MiB (N bytes), found M bytes" with
/// `what` such as "an SVG file".
std::string read_import_file(const std::filesystem::path& path, std::string_view what);

}  // namespace sweep::io
