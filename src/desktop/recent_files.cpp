#include "desktop/recent_files.hpp"

#include "io/files/atomic_file.hpp"

#include <algorithm>
#include <fstream>
#include <system_error>

namespace sweep::editor {

void remember_recent(std::deque<std::string>& recent, const std::string& path) {
  if (path.empty()) return;
  std::string absolute = path;
  try {
    std::error_code ec;
    const std::filesystem::path full = std::filesystem::absolute(path, ec);
    if (!ec) absolute = full.lexically_normal().string();
  } catch (...) {
    absolute = path;
  }
  recent.erase(std::remove(recent.begin(), recent.end(), absolute), recent.end());
  recent.push_front(absolute);
  while (recent.size() > kMaxRecentFiles) recent.pop_back();
}

std::deque<std::string> load_recent(const std::filesystem::path& file) {
  std::deque<std::string> recent;
  try {
    std::ifstream in(file, std::ios::binary);
    if (!in) return recent;
    std::string line;
    while (recent.size() < kMaxRecentFiles && std::getline(in, line)) {
      if (!line.empty() && line.back() == '\r') line.pop_back();
      if (line.empty()) continue;
      recent.push_back(line);
    }
  } catch (...) {
  }
  return recent;
}

std::string save_recent(const std::filesystem::path& file, const std::deque<std::string>& recent) {
  const auto cannot_save = [&](const std::string& reason) {
    std::string message = "cannot save the recent files to ";
    message += file.string();
    message += ": ";
    message += reason;
    return message;
  };
  try {
    std::error_code ec;
    if (file.has_parent_path()) {
      std::filesystem::create_directories(file.parent_path(), ec);
      if (ec) return cannot_save(ec.message());
    }
    std::string text;
    for (const std::string& path : recent) {
      if (path.empty() || path.find_first_of("\r\n") != std::string::npos) continue;  // would not read back
      text += path;
      text += '\n';
    }
    io::write_file_atomically(file, text);
    return "";
  } catch (const std::exception& e) {
    // write_file_atomically names the path itself ("cannot write PATH: REASON"): keep the reason.
    std::string reason = e.what();
    std::string prefix = "cannot write ";
    prefix += file.string();
    prefix += ": ";
    if (reason.starts_with(prefix)) reason.erase(0, prefix.size());
    return cannot_save(reason);
  } catch (...) {
    return cannot_save("unknown error");
  }
}

}  // namespace sweep::editor
