#pragma once
// A set of files replaced together, all at once or not at all: an export's OBJ, its MTL and the
// material's images, or its files per surface. Each file is written to a staging name beside
// its target ("TARGET.export-tmp"), then every target that exists is set aside
// ("TARGET.export-old") as its new file is renamed over it; if any rename fails the new files are
// removed and the old ones put back. Each file's own write is atomic (atomic_file.hpp).
#include <functional>
#include <string>
#include <vector>

namespace sweep::io {

/// One file of a set: its target, and what writes it (to the staging path it is given).
struct FileSetMember {
  std::string target;
  std::function<void(const std::string& staged)> write;
};

/// Writes `files` as one set. Throws std::runtime_error, before anything is written, for two
/// members with one target ("cannot write T: two exported files have that name") or a target
/// whose folder is missing ("cannot write T: folder F: No such file or directory"); and for a
/// folder where a target goes or a write or rename that fails ("cannot write T: REASON"),
/// leaving every target as it was and no staging file behind.
void write_file_set(const std::vector<FileSetMember>& files);

}  // namespace sweep::io
