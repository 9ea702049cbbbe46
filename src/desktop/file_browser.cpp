#include "desktop/file_browser.hpp"

#include <algorithm>
#include <cctype>
#include <system_error>

namespace sweep::editor {
namespace {

char lower(char c) {
  return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}

std::string lowered(std::string text) {
  for (char& c : text) c = lower(c);
  return text;
}

bool has_swp_extension(const std::filesystem::path& path) {
  return lowered(path.extension().string()) == ".swp";
}

/// Case-insensitive order, ties broken by the bytes so the order never depends on the listing.
bool name_before(const std::string& a, const std::string& b) {
  const std::string la = lowered(a);
  const std::string lb = lowered(b);
  if (la != lb) return la < lb;
  return a < b;
}

/// Absolute, normalized, and without a trailing separator (so parent_path() goes up).
std::filesystem::path clean_folder(const std::filesystem::path& folder) {
  std::error_code ec;
  std::filesystem::path path = std::filesystem::absolute(folder, ec);
  if (ec) path = folder;
  path = path.lexically_normal();
  if (!path.has_filename() && path != path.root_path()) path = path.parent_path();
  return path;
}

std::filesystem::path current_folder() {
  std::error_code ec;
  std::filesystem::path path = std::filesystem::current_path(ec);
  if (ec) return std::filesystem::path("/");
  return path;
}

}  // namespace

std::string list_folder(const std::filesystem::path& folder, const std::string& filter,
                        std::vector<BrowserEntry>& out) {
  out.clear();
  const auto cannot_read = [&](const std::error_code& ec) {
    std::string message = "cannot read ";
    message += folder.string();
    message += ": ";
    message += ec.message();
    return message;
  };
  try {
    std::error_code ec;
    std::filesystem::directory_iterator it(folder, ec);
    if (ec) return cannot_read(ec);
    const std::string wanted = lowered(filter);
    std::vector<BrowserEntry> folders;
    std::vector<BrowserEntry> files;
    for (; it != std::filesystem::directory_iterator(); it.increment(ec)) {
      if (ec) break;
      const std::string name = it->path().filename().string();
      if (name.empty() || name[0] == '.') continue;
      if (!wanted.empty() && lowered(name).find(wanted) == std::string::npos) continue;
      std::error_code entry_ec;
      const bool is_folder = it->is_directory(entry_ec);  // follows symbolic links
      if (entry_ec) continue;
      if (is_folder) {
        folders.push_back({name, true});
      } else if (has_swp_extension(it->path())) {
        files.push_back({name, false});
      }
    }
    if (ec) {
      out.clear();
      return cannot_read(ec);
    }
    const auto by_name = [](const BrowserEntry& a, const BrowserEntry& b) { return name_before(a.name, b.name); };
    std::sort(folders.begin(), folders.end(), by_name);
    std::sort(files.begin(), files.end(), by_name);
    out = std::move(folders);
    out.insert(out.end(), files.begin(), files.end());
    return "";
  } catch (const std::exception& e) {
    out.clear();
    std::string message = "cannot read ";
    message += folder.string();
    message += ": ";
    message += e.what();
    return message;
  }
}

void FileBrowser::open_at(const std::filesystem::path& where) {
  std::error_code ec;
  std::filesystem::path folder = where;
  // A file (or a .swp path that does not exist yet, as for Save As) shows its folder; a folder
  // that happens to end in ".swp" is still a folder.
  const bool is_folder = std::filesystem::is_directory(where, ec);
  ec.clear();
  if (!is_folder && (std::filesystem::is_regular_file(where, ec) || has_swp_extension(where))) {
    folder = where.parent_path();
    if (folder.empty()) folder = current_folder();
  }
  ec.clear();
  if (!std::filesystem::is_directory(folder, ec)) folder = current_folder();
  folder_ = clean_folder(folder);
  filter_.clear();
  refresh();
  highlighted_ = entries_.empty() ? -1 : 0;
}

void FileBrowser::refresh() {
  error_ = list_folder(folder_, filter_, entries_);
  highlight(highlighted_);
}

void FileBrowser::set_filter(const std::string& filter) {
  filter_ = filter;
  refresh();
  highlighted_ = entries_.empty() ? -1 : 0;
}

void FileBrowser::highlight(int row) {
  if (entries_.empty() || row < 0) {
    highlighted_ = -1;
    return;
  }
  highlighted_ = std::min(row, static_cast<int>(entries_.size()) - 1);
}

void FileBrowser::move(int rows) {
  if (entries_.empty()) {
    highlighted_ = -1;
    return;
  }
  const long long last = static_cast<long long>(entries_.size()) - 1;
  const long long row = std::clamp(static_cast<long long>(highlighted_) + rows, 0LL, last);
  highlighted_ = static_cast<int>(row);
}

void FileBrowser::go_up() {
  const std::filesystem::path parent = folder_.parent_path();
  if (parent.empty() || parent == folder_) return;  // at the root
  const std::string left = folder_.filename().string();
  folder_ = parent;
  filter_.clear();
  refresh();
  // Highlight the folder just left, so going down again is one key.
  highlighted_ = entries_.empty() ? -1 : 0;
  for (std::size_t i = 0; i < entries_.size(); ++i)
    if (entries_[i].folder && entries_[i].name == left) highlighted_ = static_cast<int>(i);
}

std::string FileBrowser::activate(int row) {
  if (row == -1) row = highlighted_;
  if (row < 0 || row >= static_cast<int>(entries_.size())) return "";
  const BrowserEntry entry = entries_[static_cast<std::size_t>(row)];
  if (entry.folder) {
    folder_ = clean_folder(folder_ / entry.name);
    filter_.clear();
    refresh();
    highlighted_ = entries_.empty() ? -1 : 0;
    return "";
  }
  return (folder_ / entry.name).string();
}

std::string FileBrowser::go_to(const std::string& typed) {
  if (typed.empty()) return "";
  std::filesystem::path path = typed;
  if (path.is_relative()) path = folder_ / path;
  path = path.lexically_normal();
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) {
    open_at(path);
    return "";
  }
  return path.string();
}

}  // namespace sweep::editor
