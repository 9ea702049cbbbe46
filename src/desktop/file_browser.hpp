#pragma once
// The Open and Save As browser's model, without a window: a folder's sub-folders and .swp files,
// filtered by what was typed, a highlighted row moved by keys, entering folders and going up.
// The viewer draws it (panels/file_browser_panel.cpp).
#include <filesystem>
#include <string>
#include <vector>

namespace sweep::editor {

struct BrowserEntry {
  std::string name;  // file or folder name
  bool folder = false;
};

/// Sub-folders (sorted, case-insensitively) then .swp files (the same), hidden entries (".x")
/// left out, each kept only when `filter` occurs in its name (case-insensitively). Returns ""
/// or why the folder cannot be read ("cannot read /root: Permission denied"); never throws.
std::string list_folder(const std::filesystem::path& folder, const std::string& filter, std::vector<BrowserEntry>& out);

class FileBrowser {
 public:
  /// Shows `folder` (a file's folder when given a file), with nothing typed.
  void open_at(const std::filesystem::path& where);
  /// Re-reads the folder (after the filter or the folder changed).
  void refresh();

  const std::filesystem::path& folder() const { return folder_; }
  const std::vector<BrowserEntry>& entries() const { return entries_; }
  const std::string& error() const { return error_; }
  /// The highlighted row (-1: none).
  int highlighted() const { return highlighted_; }
  const std::string& filter() const { return filter_; }

  void set_filter(const std::string& filter);
  /// Up/down arrows: moves the highlight, clamped to the list.
  void move(int rows);
  void highlight(int row);
  /// Goes to the parent folder (Backspace with nothing typed, or the ".." row).
  void go_up();
  /// Enter on row `row` (or the highlighted one for -1): a folder is entered (returns ""), a
  /// file's full path is returned (the caller opens it).
  std::string activate(int row = -1);
  /// A path typed into the path field: a folder is shown; anything else is returned as the
  /// file to open or save to (relative paths against the shown folder).
  std::string go_to(const std::string& typed);

 private:
  std::filesystem::path folder_;
  std::vector<BrowserEntry> entries_;
  std::string error_;
  std::string filter_;
  int highlighted_ = -1;
};

}  // namespace sweep::editor
