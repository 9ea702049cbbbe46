// A set of files replaced together (file_set.hpp).
#include "io/files/file_set.hpp"

#include <filesystem>
#include <set>
#include <stdexcept>
#include <system_error>

namespace sweep::io {
namespace {

/// Every target's folder exists: a missing one is named before anything is written.
void check_folders(const std::vector<FileSetMember>& outputs) {
  for (const FileSetMember& output : outputs) {
    const std::filesystem::path folder = std::filesystem::path(output.target).parent_path();
    if (folder.empty() || std::filesystem::is_directory(folder)) continue;
    throw std::runtime_error("cannot write " + output.target + ": folder " + folder.string() +
                             ": No such file or directory");
  }
}

/// Every target once: two outputs with one name would overwrite each other.
void check_distinct(const std::vector<FileSetMember>& outputs) {
  std::set<std::string> seen;
  for (const FileSetMember& output : outputs) {
    if (seen.insert(output.target).second) continue;
    std::string message = "cannot write ";
    message += output.target;
    message += ": two exported files have that name";
    throw std::runtime_error(message);
  }
}

void remove_quietly(const std::vector<std::string>& paths) {
  std::error_code ignored;
  for (const std::string& path : paths) std::filesystem::remove(path, ignored);
}

std::string staged_path(const std::string& path) {
  return path + ".export-tmp";
}

std::string set_aside_path(const std::string& path) {
  return path + ".export-old";
}

/// Renames every staged file over its target. The old targets are set aside first and put back
/// if any rename fails, so the set of files changes all at once or not at all.
void install(const std::vector<std::string>& staged, const std::vector<FileSetMember>& outputs) {
  namespace fs = std::filesystem;
  for (const FileSetMember& output : outputs) {  // a folder in the way is the user's: never moved
    if (fs::is_directory(output.target)) throw std::runtime_error("cannot write " + output.target + ": Is a directory");
  }
  std::vector<std::string> set_aside;  // targets that existed, now under set_aside_path
  std::vector<std::string> installed;
  try {
    for (std::size_t k = 0; k < staged.size(); ++k) {
      const std::string& target = outputs[k].target;
      if (fs::exists(fs::symlink_status(target))) {
        fs::rename(target, set_aside_path(target));
        set_aside.push_back(target);
      }
      fs::rename(staged[k], target);
      installed.push_back(target);
    }
  } catch (...) {
    remove_quietly(installed);
    std::error_code ignored;
    for (const std::string& target : set_aside) fs::rename(set_aside_path(target), target, ignored);
    throw;
  }
  for (const std::string& target : set_aside) remove_quietly({set_aside_path(target)});
}

}  // namespace

void write_file_set(const std::vector<FileSetMember>& outputs) {
  check_distinct(outputs);
  check_folders(outputs);
  std::vector<std::string> staged;
  try {
    for (const FileSetMember& output : outputs) {
      staged.push_back(staged_path(output.target));
      output.write(staged.back());
    }
    install(staged, outputs);
  } catch (const std::filesystem::filesystem_error& e) {
    remove_quietly(staged);
    throw std::runtime_error(std::string("cannot write ") + e.path2().string() + ": " + e.code().message());
  } catch (...) {
    remove_quietly(staged);
    throw;
  }
}

}  // namespace sweep::io
