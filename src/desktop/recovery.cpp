#include "desktop/recovery.hpp"

#include "base/fnv1a.hpp"
#include "desktop/user_folders.hpp"
#include "io/files/atomic_file.hpp"
#include "io/swp/write.hpp"

#include <cstdint>
#include <system_error>
#include <unordered_map>
#include <utility>

namespace sweep::editor {
namespace {

std::string hex16(std::uint64_t value) {
  static constexpr char kDigits[] = "0123456789abcdef";
  std::string text(16, '0');
  for (int i = 15; i >= 0; --i) {
    text[static_cast<std::size_t>(i)] = kDigits[value & 0xfu];
    value >>= 4;
  }
  return text;
}

bool is_safe_name_char(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '-' || c == '_' || c == '.';
}

std::string normalized_absolute(const std::string& file) {
  std::error_code ec;
  std::filesystem::path path = std::filesystem::absolute(file, ec);
  if (ec) path = file;
  return path.lexically_normal().string();
}

}  // namespace

RecoveryStore::RecoveryStore(std::filesystem::path folder) : folder_(std::move(folder)) {}

std::filesystem::path RecoveryStore::copy_path(const std::string& file) const {
  if (file.empty()) return folder_ / "untitled.swp";
  std::string stem = std::filesystem::path(file).stem().string();
  for (char& c : stem)
    if (!is_safe_name_char(c)) c = '_';
  std::string name = stem;
  name += '-';
  name += hex16(fnv1a(normalized_absolute(file)));
  name += ".swp";
  return folder_ / name;
}

std::string RecoveryStore::write(const Document& doc, const std::string& file) const {
  try {
    UserFolder folder;
    folder.path = folder_;
    if (std::string problem = ensure_folder(folder); !problem.empty()) return problem;
    io::write_file_atomically(copy_path(file), io::write_swp(doc));
    return "";
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    std::string message = "cannot write the recovery copy of ";
    message += file.empty() ? std::string("the untitled document") : file;
    return message;
  }
}

void RecoveryStore::remove(const std::string& file) const {
  try {
    std::error_code ec;
    std::filesystem::remove(copy_path(file), ec);
  } catch (...) {
  }
}

std::optional<std::filesystem::path> RecoveryStore::newer_copy(const std::string& file) const {
  try {
    const std::filesystem::path copy = copy_path(file);
    std::error_code ec;
    if (!std::filesystem::is_regular_file(copy, ec)) return std::nullopt;
    if (file.empty()) return copy;
    if (!std::filesystem::exists(file, ec)) {
      if (ec) return std::nullopt;  // cannot tell: do not offer a copy on a guess
      return copy;
    }
    const auto copy_time = std::filesystem::last_write_time(copy, ec);
    if (ec) return std::nullopt;
    const auto file_time = std::filesystem::last_write_time(file, ec);
    if (ec) return std::nullopt;
    if (copy_time > file_time) return copy;
    return std::nullopt;
  } catch (...) {
    return std::nullopt;
  }
}

std::vector<std::string> document_differences(const Document& saved, const Document& recovered) {
  // Display names are unique within a document (names are, and "kind#index" cannot be one);
  // the first occurrence wins should a document break that.
  const auto index_by_name = [](const Document& doc) {
    std::unordered_map<std::string, std::size_t> indices;
    for (std::size_t i = 0; i < doc.objects.size(); ++i) indices.emplace(display_name(doc, static_cast<int>(i)), i);
    return indices;
  };
  const auto with_prefix = [](const char* prefix, const std::string& name) {
    std::string text = prefix;
    text += name;
    return text;
  };
  const auto saved_names = index_by_name(saved);
  const auto recovered_names = index_by_name(recovered);
  std::vector<std::string> differences;
  for (std::size_t i = 0; i < recovered.objects.size(); ++i) {
    const std::string name = display_name(recovered, static_cast<int>(i));
    const auto found = saved_names.find(name);
    if (found == saved_names.end()) {
      differences.push_back(with_prefix("added ", name));
    } else if (!(saved.objects[found->second] == recovered.objects[i])) {
      differences.push_back(with_prefix("changed ", name));
    }
  }
  for (std::size_t i = 0; i < saved.objects.size(); ++i) {
    const std::string name = display_name(saved, static_cast<int>(i));
    if (!recovered_names.contains(name)) differences.push_back(with_prefix("removed ", name));
  }
  return differences;
}

void RecoveryTimer::edited(double /*now*/) {
  pending_ = true;
}

bool RecoveryTimer::due(double now) const {
  return pending_ && now - last_write_ >= interval_;
}

void RecoveryTimer::written(double now) {
  last_write_ = now;
  pending_ = false;
}

double RecoveryTimer::wait_time(double now) const {
  if (!pending_) return -1.0;
  const double wait = last_write_ + interval_ - now;
  return wait > 0.0 ? wait : 0.0;
}

}  // namespace sweep::editor
