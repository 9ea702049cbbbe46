#include "io/files/import_file.hpp"

#include "model/file_limits.hpp"

#include <cerrno>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <system_error>

namespace sweep::io {

void import_failure(std::string_view file, int line, const std::string& detail) {
  std::string message(file);
  if (line > 0) message += ':' + std::to_string(line);
  throw ImportError(message + ": " + detail);
}

std::string read_import_file(const std::filesystem::path& path, std::string_view what) {
  const std::string file = path.string();
  std::ifstream in(path, std::ios::binary);
  if (!in) import_failure(file, 0, std::string("cannot open: ") + std::strerror(errno));
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) import_failure(file, 0, "cannot open: it is a directory");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if (size < 0) import_failure(file, 0, "cannot read: not a regular file");
  if (static_cast<std::uint64_t>(size) > limits::kMaxFileBytes) {
    import_failure(file, 0,
                   "expected " + std::string(what) + " of at most " + std::to_string(limits::kMaxFileBytes >> 20) +
                       " MiB (" + std::to_string(limits::kMaxFileBytes) + " bytes), found " + std::to_string(size) +
                       " bytes");
  }
  in.seekg(0, std::ios::beg);
  std::string text(static_cast<std::size_t>(size), '\0');
  if (!in.read(text.data(), size)) import_failure(file, 0, std::string("cannot read: ") + std::strerror(errno));
  return text;
}

}  // namespace sweep::io
