#include "snapshot/capped_read.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace sweep::snapshot {

std::string read_capped(const std::filesystem::path& file, std::uintmax_t max_bytes, const std::string& what) {
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec) throw std::runtime_error(file.string() + ": cannot read: " + ec.message());
  if (size > max_bytes) {
    throw std::runtime_error(file.string() + ": larger than " + std::to_string(max_bytes >> 20) + " MiB, not " + what);
  }
  std::ifstream in(file, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  if (!in && !in.eof()) throw std::runtime_error(file.string() + ": cannot read");
  return text.str();
}

}  // namespace sweep::snapshot
